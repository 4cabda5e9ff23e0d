// The plane-induced homography of today's reprojection (core/flow/reprojection.h) against
// exact projections of points moved by the rigid step, computed independently.
#include "flow/reprojection.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "random_cases.h"

namespace oflab {
namespace {

Mat3 random_rotation(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  // Rodrigues: R = I + sin(a) K + (1 - cos(a)) K^2, K the cross-product matrix of the axis.
  const Vec3 v(u(rng), u(rng), u(rng));
  const double a = glm::length(v);
  if (a == 0.0) return Mat3(1.0);
  const Vec3 n = v / a;
  const Mat3 k = mat3_from_rows({0.0, -n.z, n.y}, {n.z, 0.0, -n.x}, {-n.y, n.x, 0.0});
  return Mat3(1.0) + std::sin(a) * k + (1.0 - std::cos(a)) * k * k;
}

Vec2 pixel_of(const Camera& camera, const Vec3& x) {
  return centred_to_pixel(camera, project_centred(camera, x));
}

TEST(Reprojection, RigidStepBetweenPosesIsTheStepThatMadeThem) {
  std::mt19937 rng(27);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  for (int k = 0; k < 30; ++k) {
    const testing::FlowCase c = testing::random_flow_case(rng, k);
    const Mat3 r = random_rotation(rng);
    const Vec3 t(u(rng), u(rng), u(rng));
    PlanePose to = c.pose;
    to.point = r * c.pose.point + t;
    to.normal = r * c.pose.normal;
    to.up = r * c.pose.up;
    const RigidStep3 step = rigid_step_between(c.pose, to);
    const auto before = plane_corners(c.pose);
    const auto after = plane_corners(to);
    for (int i = 0; i < 4; ++i) {
      EXPECT_LT(glm::length(step.rotation * before[i] + step.translation - after[i]), 1e-9);
    }
  }
}

TEST(Reprojection, PlaneHomographyMapsThePlanesPointsExactly) {
  std::mt19937 rng(2727);
  std::uniform_real_distribution<double> u(-0.2, 0.2), s(-0.5, 0.5);
  for (int k = 0; k < 30; ++k) {
    const testing::FlowCase c = testing::random_flow_case(rng, k);
    if (k % 3 == 1) continue;  // edge-on through the axis: no image to warp
    const RigidStep3 step{random_rotation(rng), Vec3(u(rng), u(rng), u(rng))};
    const Mat3 h = plane_induced_homography(c.camera, step, plane_vector(c.pose));
    const PlaneAxes axes = plane_axes(c.pose);
    for (int i = 0; i < 10; ++i) {
      const Vec3 x = c.pose.point + s(rng) * axes.right + s(rng) * axes.up;
      const Vec3 moved = step.rotation * x + step.translation;
      if (x.z < 0.2 || moved.z < 0.2) continue;
      EXPECT_LT(glm::length(apply_homography(h, pixel_of(c.camera, x)) - pixel_of(c.camera, moved)),
                1e-6);
    }
  }
}

TEST(Reprojection, TimewarpIsExactForAnyDepthUnderRotation) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0), depth(0.3, 100.0);
  const Camera camera = make_camera(500.0, 640, 480);
  for (int k = 0; k < 50; ++k) {
    const RigidStep3 step{random_rotation(rng), Vec3(0.0)};
    const Mat3 h = plane_induced_homography(camera, step, Vec3(0.0));
    const double z = depth(rng);
    const Vec3 x(0.3 * u(rng) * z, 0.3 * u(rng) * z, z);
    const Vec3 moved = step.rotation * x;
    if (moved.z < 0.1) continue;
    EXPECT_LT(glm::length(apply_homography(h, pixel_of(camera, x)) - pixel_of(camera, moved)),
              1e-6);
  }
}

TEST(Reprojection, TimewarpMissesATranslationByItsParallax) {
  // A sideways step t_x: a point at depth Z moves by f t_x / Z pixels, which the rotation-only
  // homography (here the identity) does not move at all.
  const Camera camera = make_camera(500.0, 640, 480);
  const RigidStep3 step{Mat3(1.0), Vec3(0.04, 0.0, 0.0)};
  const Mat3 h = plane_induced_homography(camera, step, Vec3(0.0));
  for (double z : {1.0, 2.0, 5.0, 20.0}) {
    const Vec3 x(0.1, -0.2, z);
    const double error = glm::length(apply_homography(h, pixel_of(camera, x)) -
                                     pixel_of(camera, x + step.translation));
    EXPECT_NEAR(error, camera.focal_px * 0.04 / z, 1e-9);
  }
}

TEST(Reprojection, PlaneVectorFollowsTheStep) {
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  for (int k = 0; k < 30; ++k) {
    const Vec3 point(u(rng), u(rng), 3.0 + u(rng));
    const Vec3 normal(u(rng), u(rng), 1.0);
    const Vec3 m = plane_vector_of(point, normal);
    const RigidStep3 step{random_rotation(rng), Vec3(u(rng), u(rng), u(rng))};
    const Vec3 m2 = plane_vector_after(m, step);
    const Vec3 side = glm::normalize(glm::cross(normal, Vec3(0.3, 1.0, 0.1)));
    for (double a : {-1.0, 0.0, 2.0}) {
      const Vec3 x = point + a * side;  // a point of the plane
      EXPECT_NEAR(glm::dot(m, x), 1.0, 1e-9);
      EXPECT_NEAR(glm::dot(m2, step.rotation * x + step.translation), 1.0, 1e-9);
    }
  }
}

}  // namespace
}  // namespace oflab
