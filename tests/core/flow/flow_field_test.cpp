// The planar flow coefficients against independent computations: central finite
// differences of the exact projection of moving plane points, and the projected 3D
// velocity.
#include "flow/flow_field.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "flow/homography.h"
#include "random_cases.h"

namespace oflab {
namespace {

using testing::FlowCase;

// Image position at time t of the plane point seen at centred pixel p at time 0.
Vec2 moved_pixel(const FlowCase& c, const Vec2& p, double t) {
  const Vec3 r = plane_point_at_pixel(c.pose, c.camera.focal_px, p);
  const RigidStep step = rigid_step(c.motion, c.pose, t);
  return project_centred(c.camera, step.rotation * r + step.translation);
}

Vec2 finite_difference_velocity(const FlowCase& c, const Vec2& p, double h) {
  return (moved_pixel(c, p, h) - moved_pixel(c, p, -h)) / (2.0 * h);
}

double relative_error(const Vec2& got, const Vec2& want, double floor) {
  return glm::length(got - want) / std::max(glm::length(want), floor);
}

TEST(PlanarFlow, AnalyticCoefficientsMatchFiniteDifferencesOfExactProjection) {
  std::mt19937 rng(1234);
  int checked = 0;
  for (int i = 0; i < 300; ++i) {
    const FlowCase c = testing::random_flow_case(rng, i);
    ASSERT_TRUE(plane_pose_problem(c.pose).field.empty()) << plane_pose_problem(c.pose).message;
    const PlanarFlowCoefficients k = planar_flow_coefficients(c.camera, c.pose, c.motion);
    for (const Vec2& p : testing::sample_plane_pixels(c)) {
      const Vec2 fd = finite_difference_velocity(c, p, 1e-4);
      EXPECT_LT(relative_error(flow_at(k, p), fd, 1.0), 1e-6)
          << "case " << i << " at (" << p.x << ", " << p.y << ")";
      ++checked;
    }
  }
  EXPECT_GT(checked, 2000);
}

TEST(PlanarFlow, ExactFlowOfProjectedVelocityEqualsQuadraticFlow) {
  std::mt19937 rng(99);
  for (int i = 0; i < 200; ++i) {
    const FlowCase c = testing::random_flow_case(rng, i);
    const PlanarFlowCoefficients k = planar_flow_coefficients(c.camera, c.pose, c.motion);
    for (const Vec2& p : testing::sample_plane_pixels(c)) {
      EXPECT_LT(relative_error(flow_at(k, p), exact_flow_at(c.camera, c.pose, c.motion, p), 1.0),
                1e-10);
    }
  }
}

TEST(PlanarFlow, PlaneSeenEdgeOnThroughTheAxisHasFiniteCoefficients) {
  FlowCase c;
  c.camera = make_camera(500.0, 640, 480);
  c.pose.point = Vec3(0.5, 0.0, 3.0);
  c.pose.normal = Vec3(1.0, 0.0, 0.0);  // N3 = 0: the plane X = 0.5
  c.pose.up = Vec3(0.0, -1.0, 0.0);
  c.motion.velocity = Vec3(0.1, 0.2, 0.3);
  c.motion.omega = Vec3(0.0, 0.2, 0.0);
  const PlanarFlowCoefficients k = planar_flow_coefficients(c.camera, c.pose, c.motion);
  for (double v : {k.tx, k.ty, k.j11, k.j12, k.j21, k.j22, k.px, k.py}) {
    EXPECT_TRUE(std::isfinite(v));
  }
  const Vec2 p(200.0, -30.0);  // right of the image centre, where X = 0.5 is seen
  EXPECT_LT(relative_error(flow_at(k, p), finite_difference_velocity(c, p, 1e-5), 1.0), 1e-6);
}

TEST(PlanarFlow, PureRotationFlowDoesNotDependOnThePlane) {
  std::mt19937 rng(5);
  for (int i = 0; i < 50; ++i) {
    FlowCase c = testing::random_flow_case(rng, i);
    c.motion.velocity = Vec3(0.0);
    c.motion.model = MotionModel::kScrew;
    const PlanarFlowCoefficients a = planar_flow_coefficients(c.camera, c.pose, c.motion);
    c.pose.normal = Vec3(0.3, -0.2, 1.0);
    c.pose.point.z += 2.0;
    const PlanarFlowCoefficients b = planar_flow_coefficients(c.camera, c.pose, c.motion);
    EXPECT_NEAR(a.tx, b.tx, 1e-9);
    EXPECT_NEAR(a.j12, b.j12, 1e-12);
    EXPECT_NEAR(a.px, b.px, 1e-15);
  }
}

TEST(PlanarFlow, ReexpandedCoefficientsDescribeTheSameFlow) {
  std::mt19937 rng(7);
  for (int i = 0; i < 100; ++i) {
    const FlowCase c = testing::random_flow_case(rng, i);
    const PlanarFlowCoefficients k = planar_flow_coefficients(c.camera, c.pose, c.motion);
    const Vec2 origin(37.0 * (i % 5) - 60.0, -11.0 * (i % 7) + 20.0);
    const PlanarFlowCoefficients r = reexpand(k, origin);
    EXPECT_EQ(r.px, k.px);
    EXPECT_EQ(r.py, k.py);
    const Vec2 at_origin = flow_at(r, origin);
    EXPECT_NEAR(at_origin.x, r.tx, 1e-9);
    for (const Vec2& p : testing::sample_plane_pixels(c)) {
      EXPECT_LT(relative_error(flow_at(r, p), flow_at(k, p), 1.0), 1e-12);
    }
    // Re-expanding back gives the original coefficients.
    const PlanarFlowCoefficients back = reexpand(r, Vec2(0.0));
    EXPECT_NEAR(back.j11, k.j11, 1e-12);
    EXPECT_NEAR(back.j22, k.j22, 1e-12);
  }
}

TEST(PlanarFlow, ImageAccelerationMatchesSecondDifferenceForEveryMotionModel) {
  std::mt19937 rng(11);
  for (int i = 0; i < 150; ++i) {
    FlowCase c = testing::random_flow_case(rng, i);
    c.motion.model = static_cast<MotionModel>(i % 3);
    for (const Vec2& p : testing::sample_plane_pixels(c)) {
      const double h = 1e-3;
      const Vec2 fd = (moved_pixel(c, p, h) - 2.0 * p + moved_pixel(c, p, -h)) / (h * h);
      const Vec2 a = image_acceleration(c.camera, c.pose, c.motion, p);
      EXPECT_LT(glm::length(a - fd), 1e-4 * std::max(1.0, glm::length(fd)))
          << "model " << motion_model_name(c.motion.model) << " case " << i;
    }
  }
}

// The worked example of manual/flow-math.md section 4.2 ("Default case").
TEST(PlanarFlow, DefaultCaseMatchesPublishedWorkedExample) {
  const FlowCase c = testing::default_case();
  const PlanarFlowCoefficients k = planar_flow_coefficients(c.camera, c.pose, c.motion);
  EXPECT_NEAR(k.tx, -121.03, 0.01);
  EXPECT_NEAR(k.ty, -279.31, 0.01);
  EXPECT_NEAR(k.j11, -0.13923, 1e-5);
  EXPECT_NEAR(k.j12, -0.61474, 1e-5);
  EXPECT_NEAR(k.j21, 0.58362, 1e-5);
  EXPECT_NEAR(k.j22, -0.15397, 1e-5);
  EXPECT_NEAR(k.px, -5.6825e-4, 1e-8);
  EXPECT_NEAR(k.py, -6.2572e-4, 1e-8);
}

TEST(MotionModels, NamesParseBackAndJoinInOrder) {
  for (MotionModel m :
       {MotionModel::kScrew, MotionModel::kRotateThenTranslate, MotionModel::kSpinAboutCentre}) {
    MotionModel q = MotionModel::kScrew;
    ASSERT_TRUE(parse_motion_model(motion_model_name(m), &q));
    EXPECT_EQ(q, m);
  }
  MotionModel q = MotionModel::kScrew;
  EXPECT_TRUE(parse_motion_model("center", &q));
  EXPECT_EQ(q, MotionModel::kSpinAboutCentre);
  EXPECT_FALSE(parse_motion_model("twist", &q));
  EXPECT_EQ(motion_model_name_list(), "screw, rt, centre");
  EXPECT_EQ(motion_model_name_list("|"), "screw|rt|centre");
}

}  // namespace
}  // namespace oflab
