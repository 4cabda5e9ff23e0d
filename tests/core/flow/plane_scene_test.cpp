// The flow views' scene: the default demo is drawable, and each way a scene cannot be drawn
// is named.
#include "flow/plane_scene.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include "flow/flow_field.h"
#include "scene/view_culling.h"

namespace oflab {
namespace {

TEST(PlaneScene, DemoIsValidAndImpossibleScenesAreNamed) {
  PlaneScene s = default_demo_scene();
  EXPECT_EQ(plane_scene_problem(s), "");
  s.pose.point = s.pose.point * (-1.0 / s.pose.point.z);  // same ray, centre at depth -1
  EXPECT_NE(plane_scene_problem(s).find("behind"), std::string::npos);
  s = default_demo_scene();
  s.pose.normal = glm::cross(s.pose.point, Vec3(0, 1, 0));  // N.P = 0
  EXPECT_NE(plane_scene_problem(s).find("eye"), std::string::npos);
  s = default_demo_scene();
  s.pose.point = Vec3(0.15, -0.1, 0.3);  // centre in front, a corner behind the eye
  s.pose.normal = Vec3(1.0, 0.0, 0.2);
  EXPECT_NE(plane_scene_problem(s).find("corner"), std::string::npos);
  s = default_demo_scene();
  s.camera.focal_px = 0.0;
  EXPECT_NE(plane_scene_problem(s).find("focal"), std::string::npos);
}

constexpr int kLoopFrames = 150;  // the scene panel's loop: kDemoTurnSeconds at 30 per second
constexpr double kNear = 0.05;

// Every corner of the pose projects inside the image, `margin` pixels from its border.
bool corners_inside(const Camera& camera, const PlanePose& pose, double margin) {
  for (const Vec3& corner : plane_corners(pose)) {
    if (corner.z <= 0.0) return false;
    const Vec2 p = centred_to_pixel(camera, project_centred(camera, corner));
    if (p.x < margin || p.y < margin || p.x > camera.width - margin ||
        p.y > camera.height - margin) {
      return false;
    }
  }
  return true;
}

// The default demo keeps the whole plane in the picture in every frame of the loop, and the
// loop is seamless: one turn brings the plane back to its start.
TEST(PlaneScene, DefaultDemoStaysInsideTheImageForTheWholeLoop) {
  {
    const PlaneScene scene = default_demo_scene();
    ASSERT_EQ(plane_scene_problem(scene), "");
    for (int k = 0; k < kLoopFrames; ++k) {
      const PlanePose pose = pose_at_time(scene, k * kDemoTurnSeconds / kLoopFrames);
      EXPECT_TRUE(plane_meets_image(scene.camera, pose, kNear)) << "frame " << k;
      EXPECT_TRUE(corners_inside(scene.camera, pose, 20.0)) << "frame " << k;
      EXPECT_GT(glm::dot(glm::normalize(pose.normal), glm::normalize(pose.point)), 0.5)
          << "frame " << k << ": the plane must face the viewer, never near edge-on";
    }
    const PlanePose back = pose_at_time(scene, kDemoTurnSeconds);
    EXPECT_LT(glm::length(back.point - scene.pose.point), 1e-9);
    EXPECT_LT(glm::length(glm::normalize(back.normal) - glm::normalize(scene.pose.normal)), 1e-9);
    EXPECT_LT(glm::length(back.up - scene.pose.up), 1e-9);
  }
}

// The default demo shows every term of the planar flow at some frame of its loop:
// translation (of the plane's centre; at the principal point, about which the plane
// circles, it is small), scale, rotation, squash, shear and both perspective terms.
TEST(PlaneScene, DefaultDemoShowsEveryFlowTerm) {
  const PlaneScene scene = default_demo_scene();
  double t = 0, scale = 0, rotation = 0, squash = 0, shear = 0, px = 0, py = 0;
  double min_scale = 1e9, max_scale = -1e9;
  for (int k = 0; k < kLoopFrames; ++k) {
    const PlanePose pose = pose_at_time(scene, k * kDemoTurnSeconds / kLoopFrames);
    const PlanarFlowCoefficients c = planar_flow_coefficients(scene.camera, pose, scene.motion);
    // The image of the plane centre moves (the translation term about that point).
    const Vec2 centre = project_centred(scene.camera, pose.point);
    t = std::max(t, glm::length(flow_at(c, centre)));
    scale = std::max(scale, std::abs(c.j11 + c.j22) / 2);
    min_scale = std::min(min_scale, (c.j11 + c.j22) / 2);
    max_scale = std::max(max_scale, (c.j11 + c.j22) / 2);
    rotation = std::max(rotation, std::abs(c.j21 - c.j12) / 2);
    squash = std::max(squash, std::abs(c.j11 - c.j22) / 2);
    shear = std::max(shear, std::abs(c.j12 + c.j21) / 2);
    px = std::max(px, std::abs(c.px));
    py = std::max(py, std::abs(c.py));
  }
  EXPECT_GT(t, 50.0);         // px/s
  EXPECT_GT(scale, 0.05);     // per second
  EXPECT_LT(min_scale, 0.0);  // it comes nearer and goes away again
  EXPECT_GT(max_scale, 0.0);
  EXPECT_GT(rotation, 0.5);
  EXPECT_GT(squash, 0.05);
  EXPECT_GT(shear, 0.05);
  EXPECT_GT(px, 1e-4);  // per pixel per second
  EXPECT_GT(py, 1e-4);
}

}  // namespace
}  // namespace oflab
