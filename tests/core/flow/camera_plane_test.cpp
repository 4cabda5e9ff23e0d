// Camera and plane pose: projection conventions and input validation.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "flow/camera.h"
#include "flow/motion.h"
#include "flow/plane.h"

namespace oflab {
namespace {

TEST(Camera, PrincipalPointIsTheImageCentreAndYGrowsDownwards) {
  const Camera c = make_camera(500.0, 640, 480);
  EXPECT_EQ(c.cx, 320.0);
  EXPECT_EQ(c.cy, 240.0);
  const Vec2 below = centred_to_pixel(c, project_centred(c, Vec3(0.0, 1.0, 5.0)));
  EXPECT_EQ(below.x, 320.0);
  EXPECT_EQ(below.y, 340.0);
  EXPECT_STREQ(camera_problem(c), "");
  EXPECT_STRNE(camera_problem(make_camera(-1.0, 640, 480)), "");
  EXPECT_STRNE(camera_problem(make_camera(500.0, 0, 480)), "");
}

TEST(PlanePose, ProblemsNameTheField) {
  PlanePose p;
  EXPECT_TRUE(plane_pose_problem(p).field.empty());
  p.normal = Vec3(0.0);
  EXPECT_EQ(plane_pose_problem(p).field, "normal");
  p = PlanePose();
  p.point.z = -1.0;
  EXPECT_EQ(plane_pose_problem(p).field, "point");
  p = PlanePose();
  p.point = Vec3(0.0, 0.0, 2.0);
  p.normal = Vec3(1.0, 0.0, 0.0);  // contains the eye
  EXPECT_EQ(plane_pose_problem(p).field, "point");
  p = PlanePose();
  p.up = Vec3(0.0, 0.0, 3.0);  // parallel to the normal
  EXPECT_EQ(plane_pose_problem(p).field, "up");
  p = PlanePose();
  p.point.x = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(plane_pose_problem(p).field, "point");
  p = PlanePose();
  p.size.y = 0.0;
  EXPECT_EQ(plane_pose_problem(p).field, "size");
}

TEST(PlanePose, PlaneVectorGivesInverseDepthAlongEveryRay) {
  PlanePose p;
  p.point = Vec3(0.2, -0.1, 2.5);
  p.normal = Vec3(0.3, 0.2, 1.0);
  const double f = 400.0;
  for (double x : {-100.0, 0.0, 50.0}) {
    for (double y : {-80.0, 10.0}) {
      const Vec3 r = plane_point_at_pixel(p, f, Vec2(x, y));
      EXPECT_NEAR(glm::dot(p.normal, r - p.point), 0.0, 1e-12);
      EXPECT_NEAR(f * r.x / r.z, x, 1e-9);
      EXPECT_NEAR(f * r.y / r.z, y, 1e-9);
    }
  }
}

TEST(PlanePose, CornersFollowTextureOrderAndRightIsNormalCrossUp) {
  PlanePose p;
  p.point = Vec3(0.0, 0.0, 2.0);
  p.normal = Vec3(0.0, 0.0, 1.0);  // facing away from the viewer: texture unmirrored
  p.up = Vec3(0.0, -1.0, 0.0);
  p.size = Vec2(2.0, 1.0);
  const auto c = plane_corners(p);
  EXPECT_LT(glm::length(c[0] - Vec3(-1.0, -0.5, 2.0)), 1e-12);  // top-left on screen
  EXPECT_LT(glm::length(c[2] - Vec3(1.0, 0.5, 2.0)), 1e-12);
  const PlaneAxes a = plane_axes(p);
  EXPECT_LT(glm::length(a.right - Vec3(1.0, 0.0, 0.0)), 1e-12);
}

TEST(Motion, ScrewStepIntegratesTheVelocityField) {
  // d/dt (Q R + s) at t must equal V + Omega x (Q R + s) for the screw model.
  RigidMotion m;
  m.velocity = Vec3(0.3, -0.2, 0.5);
  m.omega = Vec3(0.4, -0.3, 0.6);
  PlanePose pose;
  const Vec3 r0(0.1, 0.2, 3.0);
  for (double t : {0.0, 0.005, 0.3, 2.0}) {
    const double h = 1e-5;
    auto at = [&](double s) {
      const RigidStep st = rigid_step(m, pose, s);
      return st.rotation * r0 + st.translation;
    };
    const Vec3 fd = (at(t + h) - at(t - h)) / (2 * h);
    const Vec3 want = m.velocity + glm::cross(m.omega, at(t));
    EXPECT_LT(glm::length(fd - want), 1e-8) << "t = " << t;
  }
}

TEST(Motion, SpinAboutCentreKeepsTheCentreOnItsPath) {
  RigidMotion m;
  m.model = MotionModel::kSpinAboutCentre;
  m.velocity = Vec3(0.1, 0.0, 0.2);
  m.omega = Vec3(0.0, 0.0, 1.0);
  PlanePose pose;
  pose.point = Vec3(0.5, 0.5, 3.0);
  const PlanePose next = advance_pose(pose, rigid_step(m, pose, 0.5));
  EXPECT_LT(glm::length(next.point - (pose.point + 0.5 * m.velocity)), 1e-12);
  const Mat3 q = rigid_step(m, pose, 0.5).rotation;
  EXPECT_NEAR(glm::determinant(q), 1.0, 1e-12);
}

}  // namespace
}  // namespace oflab
