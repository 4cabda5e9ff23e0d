// The moving viewer: camera poses and their exact integration (see core/scene/viewer_script.h).
#include "scene/viewer_script.h"

#include <cmath>
#include <stdexcept>

namespace oflab {
namespace {

bool finite(const Vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

std::string look_at_problem(const Vec3& position, const Vec3& target, const Vec3& up) {
  if (!finite(position) || !finite(target) || !finite(up)) return "values must be finite";
  const Vec3 forward = target - position;
  if (glm::length(forward) < 1e-12) return "the target must differ from the position";
  if (glm::length(up) < 1e-12 ||
      glm::length(glm::cross(forward, up)) < 1e-9 * glm::length(forward) * glm::length(up)) {
    return "up must be non-zero and not parallel to the view direction";
  }
  return "";
}

ViewerPose look_at(const Vec3& position, const Vec3& target, const Vec3& up) {
  const std::string problem = look_at_problem(position, target, up);
  if (!problem.empty()) throw std::invalid_argument("look_at: " + problem);
  // Viewer axes in world coordinates: Z forward, Y down (= -up made orthogonal), X = Y x Z.
  const Vec3 z = glm::normalize(target - position);
  const Vec3 y = -glm::normalize(up - glm::dot(up, z) * z);
  const Vec3 x = glm::cross(y, z);
  ViewerPose pose;
  pose.rotation = mat3_from_rows(x, y, z);
  pose.translation = -(pose.rotation * position);
  return pose;
}

Vec3 to_view(const ViewerPose& pose, const Vec3& world_point) {
  return pose.rotation * world_point + pose.translation;
}

Vec3 direction_to_view(const ViewerPose& pose, const Vec3& world_direction) {
  return pose.rotation * world_direction;
}

Vec3 eye_position(const ViewerPose& pose) {
  return -(glm::transpose(pose.rotation) * pose.translation);
}

RigidMotion scene_motion(const Vec3& camera_velocity, const Vec3& camera_omega) {
  RigidMotion m;
  m.velocity = -camera_velocity;
  m.omega = -camera_omega;
  m.model = MotionModel::kScrew;
  return m;
}

ViewerPose advance_viewer(const ViewerPose& pose, const RigidMotion& motion) {
  // A Screw step does not depend on the pose it is applied to; any pose will do.
  const RigidStep step = rigid_step(motion, PlanePose{}, 1.0);
  ViewerPose next;
  next.rotation = step.rotation * pose.rotation;
  next.translation = step.rotation * pose.translation + step.translation;
  return next;
}

std::vector<ViewerFrame> expand_viewer_segments(const ViewerPose& initial,
                                                const std::vector<ViewerSegment>& segments) {
  std::vector<ViewerFrame> frames;
  ViewerPose pose = initial;
  for (const ViewerSegment& s : segments) {
    for (int i = 0; i < s.frames; ++i) {
      ViewerFrame f;
      f.pose = pose;
      f.motion = scene_motion(s.camera_velocity, s.camera_omega);
      frames.push_back(f);
      pose = advance_viewer(pose, f.motion);
    }
  }
  return frames;
}

}  // namespace oflab
