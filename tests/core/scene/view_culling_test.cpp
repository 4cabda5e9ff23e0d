// Culling and clipping against independent checks: the side of the plane the eye is on,
// per-pixel ray casts of single polygons, and the texture mapping of clipped points.
#include "scene/view_culling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "flow/plane.h"
#include "scene/scene.h"
#include "scene/scene_animator.h"
#include "scene_cases.h"

namespace oflab {
namespace {

using testing::random_polygons;
using testing::ray_cast_scene;
using testing::scene_with;

bool any_pixel_drawn(const Image& image) {
  for (const Pixel& p : image.pixels()) {
    if (p.a != 0) return true;
  }
  return false;
}

TEST(ViewCulling, BackFacingIsTheEyeBehindThePlane) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    const Vec3 front = glm::normalize(Vec3(u(rng), u(rng), u(rng)));
    const Vec3 point(3 * u(rng), 3 * u(rng), 3 * u(rng));
    // The eye (origin) is on the front side iff it lies beyond the plane along +front.
    const double eye_side = glm::dot(front, Vec3(0.0) - point);
    if (std::abs(eye_side) < 1e-2 * glm::length(point)) continue;  // near edge-on
    EXPECT_EQ(is_back_facing(front, point), eye_side < 0.0) << i;
  }
  EXPECT_TRUE(is_back_facing(Vec3(1, 0, 0), Vec3(0, 0, 2)));  // edge-on counts as culled
}

TEST(ViewCulling, ClippedPointsKeepTheirTextureCoordinates) {
  const ScenePolygon p =
      testing::square("s", Vec3(0.3, 0.2, 0.4), Vec3(0.2, 0.1, -1.0), Vec3(0, -1, 0), 3.0);
  const ViewerPose view;  // identity: world = viewer frame
  ViewPolygon outline{polygon_vertices(p), polygon_outline(p)};
  const Camera camera = make_camera(300.0, 320, 240);
  const ViewPolygon clipped = clip_to_frustum(outline, view_frustum(camera, 0.1, 1.0));
  ASSERT_FALSE(clipped.empty());
  for (std::size_t k = 0; k < clipped.points.size(); ++k) {
    EXPECT_LT(glm::length(polygon_point(p, clipped.uv[k]) - clipped.points[k]), 1e-12);
    EXPECT_GE(clipped.points[k].z, 0.1 - 1e-12);
    const Vec2 px = centred_to_pixel(camera, project_centred(camera, clipped.points[k]));
    EXPECT_GE(px.x, -1.0 - 1e-9);
    EXPECT_LE(px.x, 321.0 + 1e-9);
    EXPECT_GE(px.y, -1.0 - 1e-9);
    EXPECT_LE(px.y, 241.0 + 1e-9);
  }
}

// Culling removes exactly the polygons that draw nothing: each polygon of random scenes
// seen from random viewers is ray cast alone; culled ones must show no pixel, and the ones
// kept whose clipped image covers whole pixels must show some.
TEST(ViewCulling, CullingRemovesExactlyThePolygonsThatDrawNothing) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Camera camera = make_camera(120.0, 96, 72);
  int culled = 0, kept = 0, back = 0;
  for (int trial = 0; trial < 10; ++trial) {
    const Scene scene = scene_with(random_polygons(rng, 12));
    const Vec3 eye(2 * u(rng), 2 * u(rng), 2 * u(rng));
    // Looking at one of the polygons, so that some are in view and some are not.
    const Vec3 target = scene.polygons[trial].centre + Vec3(u(rng), u(rng), u(rng));
    const ViewerPose view = look_at(eye, target, Vec3(0.1, 1, 0));
    SceneSettings settings;
    settings.skip_hidden = false;
    SceneEngine animator(scene, camera, settings);
    animator.start(view);
    for (std::size_t i = 0; i < scene.polygons.size(); ++i) {
      const Scene alone = scene_with({scene.polygons[i]});
      const Image reference = ray_cast_scene(alone, camera, view, settings.near);
      const PolygonStatus status = animator.statuses()[i];
      if (status == PolygonStatus::kBackFacing || status == PolygonStatus::kOutsideFrustum) {
        EXPECT_FALSE(any_pixel_drawn(reference)) << "trial " << trial << " polygon " << i;
        ++culled;
        back += status == PolygonStatus::kBackFacing;
      } else {
        ++kept;
        ViewPolygon outline;
        for (const Vec3& v : polygon_vertices(scene.polygons[i])) {
          outline.points.push_back(to_view(view, v));
        }
        outline.uv = polygon_outline(scene.polygons[i]);
        const ViewPolygon clipped =
            clip_to_frustum(outline, view_frustum(camera, settings.near, 0.0));
        const double area = clipped.empty() ? 0.0 : project_to_pixels(camera, clipped).area();
        if (area > 20.0) {
          EXPECT_TRUE(any_pixel_drawn(reference)) << "trial " << trial << " polygon " << i;
        }
      }
    }
  }
  EXPECT_GT(culled, 5);
  EXPECT_GT(back, 2);
  EXPECT_GT(kept, 3);
}

// Independent count: the pixel centres whose ray meets the plane rectangle at Z >= near,
// found by intersecting each ray with the plane and testing the in-plane coordinates.
int pixels_seeing_plane(const Camera& camera, const PlanePose& pose, double near) {
  const PlaneAxes axes = plane_axes(pose);
  int hits = 0;
  for (int j = 0; j < camera.height; ++j) {
    for (int i = 0; i < camera.width; ++i) {
      const Vec3 ray((i + 0.5 - camera.cx) / camera.focal_px,
                     (j + 0.5 - camera.cy) / camera.focal_px, 1.0);
      const double along = glm::dot(axes.normal, ray);
      if (std::abs(along) < 1e-15) continue;
      const double z = glm::dot(axes.normal, pose.point) / along;  // the ray's Z = t
      if (!(z >= near)) continue;
      const Vec3 offset = z * ray - pose.point;
      hits += std::abs(glm::dot(offset, axes.right)) <= 0.5 * pose.size.x &&
              std::abs(glm::dot(offset, axes.up)) <= 0.5 * pose.size.y;
    }
  }
  return hits;
}

TEST(ViewCulling, PlaneImagePolygonCoversThePixelsThatSeeThePlane) {
  const Camera camera = make_camera(64.0, 96, 64);
  const double near = 0.05;
  std::mt19937 rng(20261123);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int seen = 0, unseen = 0;
  for (int trial = 0; trial < 400; ++trial) {
    PlanePose pose;
    pose.point = Vec3(3.0 * u(rng), 2.0 * u(rng), 1.5 + 2.5 * u(rng));
    pose.normal = Vec3(u(rng), u(rng), u(rng));
    pose.up = Vec3(u(rng), u(rng), u(rng));
    pose.size = Vec2(1.0 + 0.8 * u(rng), 1.0 + 0.8 * u(rng));
    const ConvexPolygon shown = plane_image_polygon(camera, pose, near);
    const int hits = pixels_seeing_plane(camera, pose, near);
    double perimeter = 0.0;
    const auto& v = shown.vertices();
    for (std::size_t k = 0; k < v.size(); ++k)
      perimeter += glm::length(v[(k + 1) % v.size()] - v[k]);
    // Pixel centres inside a convex polygon number its area, give or take its boundary.
    EXPECT_NEAR(shown.area(), hits, perimeter + 4.0) << "trial " << trial;
    EXPECT_EQ(plane_meets_image(camera, pose, near), !shown.empty());
    if (hits > 0) {
      EXPECT_TRUE(plane_meets_image(camera, pose, near)) << "trial " << trial;
    }
    (shown.empty() ? unseen : seen) += 1;
  }
  EXPECT_GT(seen, 40);  // the random poses exercise both outcomes
  EXPECT_GT(unseen, 40);
}

TEST(ViewCulling, PlaneBesideBehindOrEdgeOnIsNotInTheImage) {
  const Camera camera = make_camera(256.0, 320, 240);
  PlanePose pose;
  pose.point = Vec3(0.0, 0.0, 2.0);
  EXPECT_TRUE(plane_meets_image(camera, pose, 0.05));
  pose.point = Vec3(5.0, 0.0, 2.0);  // projects at u = 160 + 640, far right of the image
  EXPECT_FALSE(plane_meets_image(camera, pose, 0.05));
  pose.point = Vec3(0.0, 0.0, -2.0);  // behind the eye
  EXPECT_FALSE(plane_meets_image(camera, pose, 0.05));
  pose.point = Vec3(0.0, 0.0, 2.0);
  pose.normal = Vec3(1.0, 0.0, 0.0);  // edge-on through the optical axis: no area
  pose.up = Vec3(0.0, -1.0, 0.0);
  EXPECT_FALSE(plane_meets_image(camera, pose, 0.05));
  pose.normal = Vec3(0.0, 0.0, 1.0);
  pose.point = Vec3(0.0, 0.0, 0.2);  // straddles nothing, fills the whole view
  EXPECT_NEAR(plane_image_polygon(camera, pose, 0.05).area(), 320.0 * 240.0, 1e-6);
}

}  // namespace
}  // namespace oflab
