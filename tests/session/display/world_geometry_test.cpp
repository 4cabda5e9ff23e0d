// The world view's geometry (session/display/world_geometry.h) against core's own
// projection and poses, computed independently here: the image plane, the rays, the depths,
// the arrows, and a plane's loop and frame as the desktop's and the page's world views draw
// them.
#include "display/world_geometry.h"

#include <gtest/gtest.h>

#include <cmath>

#include "flow/plane_scene.h"
#include "scene/viewer_script.h"

namespace oflab::test {
namespace {

// Pixel of a point on the image plane, read off the drawn rectangle's corners by linear
// interpolation (independent of the formula that placed them).
Vec2 pixel_on_image_plane(const std::array<Vec3, 4>& corners, const Camera& camera,
                          const Vec3& point) {
  const double u = (point.x - corners[0].x) / (corners[1].x - corners[0].x);
  const double v = (point.y - corners[0].y) / (corners[3].y - corners[0].y);
  return {u * camera.width, v * camera.height};
}

TEST(WorldGeometry, ImagePlaneCornersProjectToThePixelCorners) {
  const Camera camera{600.0, 380.0, 310.0, 800, 600};
  const std::array<Vec3, 4> corners = image_plane_corners(camera, 0.7);
  const Vec2 expected[4] = {{0, 0}, {800, 0}, {800, 600}, {0, 600}};
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(corners[size_t(k)].z, 0.7, 1e-15);
    const Vec2 pixel = centred_to_pixel(camera, project_centred(camera, corners[size_t(k)]));
    EXPECT_NEAR(pixel.x, expected[k].x, 1e-9) << k;
    EXPECT_NEAR(pixel.y, expected[k].y, 1e-9) << k;
  }
}

TEST(WorldGeometry, RaysCrossTheImagePlaneAtThePlaneCornersPixels) {
  const PlaneScene scene = default_demo_scene();
  const double depth = 0.9;
  const std::array<Vec3, 4> image = image_plane_corners(scene.camera, depth);
  for (const Vec3& corner : plane_corners(scene.pose)) {
    const Vec3 crossing = ray_at_depth(corner, depth);
    EXPECT_NEAR(crossing.z, depth, 1e-15);
    // On the ray: parallel to the corner.
    EXPECT_NEAR(glm::length(glm::cross(crossing, corner)), 0.0, 1e-12);
    const Vec2 drawn = pixel_on_image_plane(image, scene.camera, crossing);
    const Vec2 seen = centred_to_pixel(scene.camera, project_centred(scene.camera, corner));
    EXPECT_NEAR(drawn.x, seen.x, 1e-9);
    EXPECT_NEAR(drawn.y, seen.y, 1e-9);
  }
}

TEST(WorldGeometry, ImageDepthsSitBetweenTheEyeAndTheScene) {
  EXPECT_DOUBLE_EQ(plane_image_depth({{0, 0, 3}, {1, 0, 2}, {0, 1, 5}}), 1.0);
  EXPECT_DOUBLE_EQ(plane_image_depth({}), 1.0);
  // A plane flying into the eye (depth 2 down to 0.02): half the nearest would be 0.01, a
  // point; a quarter of the median depth (the 51st of 100, 1.02) holds instead.
  std::vector<Vec3> approach;
  for (int k = 0; k <= 99; ++k) approach.push_back({0, 0, 2.0 - 0.02 * k});
  EXPECT_NEAR(plane_image_depth(approach), 0.25 * 1.02, 1e-12);
  EXPECT_DOUBLE_EQ(scene_image_depth({{0, 0, 0}, {3, 4, 0}}), 0.5);
  EXPECT_DOUBLE_EQ(scene_image_depth({{1, 1, 1}}), 1.0);
}

TEST(WorldGeometry, ArrowLengthsStayReadableAndOrdered) {
  EXPECT_EQ(arrow_length(0.0, 2.0, 1.0), 0.0);
  EXPECT_DOUBLE_EQ(arrow_length(2.0, 2.0, 1.0), 1.0);
  EXPECT_DOUBLE_EQ(arrow_length(1e-6, 2.0, 1.0), 0.35 + 0.65 * 5e-7);
  EXPECT_LT(arrow_length(0.5, 2.0, 1.0), arrow_length(1.0, 2.0, 1.0));
  EXPECT_DOUBLE_EQ(arrow_length(5.0, 2.0, 1.0), 1.0);  // beyond the largest: clamped
}

Vec3 transform_point(const std::array<double, 16>& m, const Vec3& p) {
  Vec3 out;
  for (int r = 0; r < 3; ++r) {
    out[r] = m[size_t(4 * r)] * p.x + m[size_t(4 * r + 1)] * p.y + m[size_t(4 * r + 2)] * p.z +
             m[size_t(4 * r + 3)];
  }
  return out;
}

TEST(WorldGeometry, ArrowMatrixMapsTheUnitArrowOntoTheVector) {
  const Vec3 origin(0.2, -0.1, 2.0), direction(-0.7, 0.7, 0.1);
  const std::array<double, 16> m = arrow_matrix(origin, direction, 0.4);
  const Vec3 tail = transform_point(m, Vec3(0.0)), tip = transform_point(m, Vec3(1, 0, 0));
  EXPECT_NEAR(glm::length(tail - origin), 0.0, 1e-15);
  EXPECT_NEAR(glm::length(tip - (origin + 0.4 * glm::normalize(direction))), 0.0, 1e-12);
  const Vec3 y = transform_point(m, Vec3(0, 1, 0)) - origin,
             z = transform_point(m, Vec3(0, 0, 1)) - origin;
  EXPECT_NEAR(glm::dot(y, tip - origin), 0.0, 1e-12);  // round: a uniform, rigid scale
  EXPECT_NEAR(glm::dot(z, y), 0.0, 1e-12);
  EXPECT_NEAR(glm::length(y), 0.4, 1e-12);
  EXPECT_NEAR(glm::dot(glm::cross(tip - origin, y), z), 0.4 * 0.4 * 0.4, 1e-12);  // proper
  const std::array<double, 16> none = arrow_matrix(origin, Vec3(0.0), 0.4);
  EXPECT_NEAR(glm::length(transform_point(none, Vec3(1, 1, 1)) - origin), 0.0, 1e-15);
}

TEST(WorldGeometry, ViewerToWorldUndoesTheViewerPose) {
  const ViewerPose pose = look_at(Vec3(1.0, 2.0, -3.0), Vec3(0.5, 0.0, 1.0), Vec3(0, 1, 0));
  const Vec3 world(0.3, -1.2, 4.5);
  const Vec3 viewer = pose.rotation * world + pose.translation;
  EXPECT_NEAR(glm::length(viewer_to_world(pose, viewer) - world), 0.0, 1e-12);
  EXPECT_NEAR(glm::length(transform_point(viewer_to_world_matrix(pose), viewer) - world), 0.0,
              1e-12);
  EXPECT_NEAR(glm::length(viewer_to_world(pose, Vec3(0.0)) - Vec3(1.0, 2.0, -3.0)), 0.0, 1e-12);
}

// A plane turning about its centre and drifting for `frames` frames, per-frame motions.
MotionScript turning_script(int frames) {
  MotionScript script;
  script.camera = default_demo_scene().camera;
  PlanePose pose = default_demo_scene().pose;
  for (int k = 0; k < frames; ++k) {
    RigidMotion motion;
    motion.model = MotionModel::kSpinAboutCentre;  // V = v - omega x p (eq. 21)
    motion.velocity = Vec3(0.01 * k, -0.02, 0.005);
    motion.omega = Vec3(0.0, 0.003 * k, 0.01);
    pose.point += Vec3(0.02, 0.0, 0.03);
    script.frames.push_back({pose, motion});
  }
  return script;
}

TEST(WorldGeometry, PlaneLoopHoldsThePathTheLargestSpeedsAndTheDepth) {
  const MotionScript script = turning_script(12);
  const double dt = 1.0 / 30.0;
  const PlaneWorldLoop loop = plane_world_loop(script, script.camera, PlanePose{}, dt);
  ASSERT_EQ(loop.path.size(), 12u);
  ASSERT_EQ(loop.loop_corners.size(), 48u);
  double largest_v = 0.0, largest_w = 0.0, nearest = 1e300;
  Vec3 mean(0.0);
  for (const ScriptFrame& f : script.frames) {
    // V of the body point at the eye (eq. 21): v + omega x (0 - p) = v - omega x p.
    const Vec3 v = f.motion.velocity - glm::cross(f.motion.omega, f.pose.point);
    largest_v = std::max(largest_v, glm::length(v) / dt);
    largest_w = std::max(largest_w, glm::length(f.motion.omega) / dt);
    nearest = std::min(nearest, f.pose.point.z);
    mean += f.pose.point / 12.0;
  }
  EXPECT_NEAR(loop.largest_velocity, largest_v, 1e-12 * largest_v);
  EXPECT_NEAR(loop.largest_omega, largest_w, 1e-12 * largest_w);
  EXPECT_NEAR(loop.depth, 0.5 * nearest, 1e-12);  // the median is not 4 times the nearest
  EXPECT_NEAR(glm::length(loop.world_centre - mean), 0.0, 1e-12);
  const Vec2 size = script.frames.front().pose.size;
  EXPECT_NEAR(loop.full_arrow, 0.6 * std::sqrt(size.x * size.x + size.y * size.y), 1e-12);
}

TEST(WorldGeometry, PlaneFrameImagesItsCornersWhereTheCameraSeesThem) {
  const MotionScript script = turning_script(6);
  const PlaneWorldLoop loop = plane_world_loop(script, script.camera, PlanePose{}, 1.0 / 30.0);
  const ScriptFrame& f = script.frames[3];
  RigidMotion per_second = f.motion;
  per_second.velocity *= 30.0;
  per_second.omega *= 30.0;
  const PlaneWorldFrame frame = plane_world_frame(loop, f.pose, per_second, 3);
  EXPECT_EQ(frame.path_index, 3);
  EXPECT_EQ(plane_world_frame(loop, f.pose, per_second, 99).path_index, 5);  // clamped
  ASSERT_EQ(frame.ray_images.size(), 4u);
  for (int k = 0; k < 4; ++k) {
    const Vec3 corner = frame.plane_corners[size_t(k)];
    const Vec2 drawn =
        pixel_on_image_plane(frame.image_corners, script.camera, frame.ray_images[size_t(k)]);
    const Vec2 seen = centred_to_pixel(script.camera, project_centred(script.camera, corner));
    EXPECT_NEAR(drawn.x, seen.x, 1e-9) << k;
    EXPECT_NEAR(drawn.y, seen.y, 1e-9) << k;
  }
  // V at the centre, Omega at the eye, both along their vectors, within 0.35 .. 1 of the
  // longest arrow; N along the plane's normal.
  EXPECT_NEAR(glm::length(frame.motion.velocity.origin - f.pose.point), 0.0, 1e-15);
  EXPECT_NEAR(glm::length(frame.motion.omega.origin), 0.0, 1e-15);
  const Vec3 v = per_second.velocity - glm::cross(per_second.omega, f.pose.point);
  EXPECT_NEAR(glm::length(frame.velocity - v), 0.0, 1e-12);
  for (const WorldArrow& a : {frame.motion.velocity, frame.motion.omega}) {
    EXPECT_GE(a.length, 0.35 * loop.full_arrow - 1e-12);
    EXPECT_LE(a.length, loop.full_arrow + 1e-12);
  }
  EXPECT_NEAR(glm::dot(glm::normalize(frame.normal.direction), plane_axes(f.pose).normal), 1.0,
              1e-12);
  ASSERT_EQ(frame.motion.omega_axis.size(), 2u);
  EXPECT_NEAR(glm::length(glm::cross(frame.motion.omega_axis[1], per_second.omega)), 0.0, 1e-9);
}

TEST(WorldGeometry, MotionTooSmallToPrintIsNotDrawn) {
  const MotionArrows none = motion_arrows(Vec3(0, 0, 2), Vec3(0.0), Vec3(0.0), Vec3(0.004, 0, 0),
                                          Vec3(0, 0.001, 0), 1.0, 1.0, 0.5);
  EXPECT_EQ(none.velocity.length, 0.0);
  EXPECT_EQ(none.omega.length, 0.0);
  EXPECT_TRUE(none.omega_axis.empty());
  // The control: just above the least shown rate both are drawn.
  const MotionArrows some = motion_arrows(Vec3(0, 0, 2), Vec3(0.0), Vec3(0.0), Vec3(0.006, 0, 0),
                                          Vec3(0, 0.006, 0), 1.0, 1.0, 0.5);
  EXPECT_GT(some.velocity.length, 0.0);
  EXPECT_GT(some.omega.length, 0.0);
  EXPECT_NEAR(glm::length(some.omega_axis[1]), 2.2, 1e-12);  // 1.1 times the eye to V
}

}  // namespace
}  // namespace oflab::test
