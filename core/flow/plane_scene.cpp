#include "flow/plane_scene.h"

#include <cmath>

namespace oflab {
namespace {

bool finite(const Vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Corners closer than this (world units) are treated as reaching the eye: their image
// would be thousands of pixels wide.
constexpr double kMinCornerDepth = 1e-3;

constexpr double kPi = 3.14159265358979323846;

// A plane turning once every kDemoTurnSeconds about the axis `axis` through `centre`: a
// screw motion of zero pitch (V = -Omega x centre keeps the centre still).
RigidMotion turning_motion(const Vec3& axis, const Vec3& centre) {
  RigidMotion motion;
  motion.omega = glm::normalize(axis) * (2.0 * kPi / kDemoTurnSeconds);
  motion.velocity = -glm::cross(motion.omega, centre);
  motion.model = MotionModel::kScrew;
  return motion;
}

}  // namespace

PlaneScene default_demo_scene() {
  PlaneScene scene;
  scene.camera = make_camera(600.0, 800, 600);
  scene.pose.point = Vec3(0.2, 0.0, 2.0);
  scene.pose.normal = Vec3(0.4, -0.2, 1.0);
  scene.pose.up = Vec3(0.0, -1.0, 0.0);
  scene.pose.size = Vec2(1.0, 0.8);
  scene.pose.texture_size = glm::ivec2(243, 198);
  scene.motion = turning_motion(Vec3(0.3, 0.3, 1.0), Vec3(0.0, 0.0, 2.06));
  return scene;
}

std::string plane_scene_problem(const PlaneScene& scene) {
  const std::string camera = camera_problem(scene.camera);
  if (!camera.empty()) return "camera: " + camera;
  const PoseProblem pose = plane_pose_problem(scene.pose);
  if (!pose.field.empty()) return pose.message;  // it names the field: "plane up must be ..."
  for (const Vec3& corner : plane_corners(scene.pose)) {
    if (!(corner.z > kMinCornerDepth)) {
      return "plane: a corner of the plane is behind the camera or at the eye; move the plane "
             "further away or tilt it less";
    }
  }
  if (!finite(scene.motion.velocity) || !finite(scene.motion.omega)) {
    return "motion: V and Omega must be finite numbers";
  }
  return {};
}

PlanePose pose_at_time(const PlaneScene& scene, double t) {
  if (t == 0.0) return scene.pose;
  return advance_pose(scene.pose, rigid_step(scene.motion, scene.pose, t));
}

}  // namespace oflab
