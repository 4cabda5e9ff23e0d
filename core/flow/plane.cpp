#include "flow/plane.h"

#include <cmath>

namespace oflab {
namespace {

bool finite(const Vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

PoseProblem plane_pose_problem(const PlanePose& pose) {
  if (!finite(pose.point)) return {"point", "plane point must be three finite numbers"};
  if (!finite(pose.normal)) return {"normal", "plane normal must be three finite numbers"};
  if (!finite(pose.up)) return {"up", "plane up must be three finite numbers"};
  const double n_len = glm::length(pose.normal);
  if (n_len < 1e-12) return {"normal", "plane normal must not be zero"};
  if (pose.point.z <= 0.0) {
    return {"point", "plane centre is behind the camera (its Z must be positive)"};
  }
  const double d = glm::dot(pose.normal, pose.point);
  if (std::abs(d) <= 1e-12 * n_len * glm::length(pose.point)) {
    return {"point", "plane passes through the eye (N.P = 0): it is seen edge-on as a line"};
  }
  const double u_len = glm::length(pose.up);
  if (u_len < 1e-12 || glm::length(glm::cross(pose.normal, pose.up)) < 1e-9 * n_len * u_len) {
    return {"up", "plane up must be non-zero and not parallel to the normal"};
  }
  if (!(pose.size.x > 0.0) || !(pose.size.y > 0.0) || !std::isfinite(pose.size.x) ||
      !std::isfinite(pose.size.y)) {
    return {"size", "plane size must be two positive numbers"};
  }
  if (pose.texture_size.x < 0 || pose.texture_size.y < 0) {
    return {"texture_size", "texture size must not be negative"};
  }
  return {};
}

Vec3 plane_vector(const PlanePose& pose) { return pose.normal / glm::dot(pose.normal, pose.point); }

PlaneAxes plane_axes(const PlanePose& pose) {
  PlaneAxes axes;
  axes.normal = glm::normalize(pose.normal);
  axes.up = glm::normalize(pose.up - glm::dot(pose.up, axes.normal) * axes.normal);
  axes.right = glm::cross(axes.normal, axes.up);
  return axes;
}

std::array<Vec3, 4> plane_corners(const PlanePose& pose) {
  const PlaneAxes a = plane_axes(pose);
  const Vec3 half_r = 0.5 * pose.size.x * a.right;
  const Vec3 half_u = 0.5 * pose.size.y * a.up;
  return {pose.point - half_r + half_u, pose.point + half_r + half_u, pose.point + half_r - half_u,
          pose.point - half_r - half_u};
}

Mat3 texel_to_plane(const PlanePose& pose) {
  const double tw = pose.texture_size.x > 0 ? pose.texture_size.x : 1.0;
  const double th = pose.texture_size.y > 0 ? pose.texture_size.y : 1.0;
  return mat3_from_rows({pose.size.x / tw, 0.0, -0.5 * pose.size.x},
                        {0.0, -pose.size.y / th, 0.5 * pose.size.y}, {0.0, 0.0, 1.0});
}

Vec3 plane_point_at_pixel(const PlanePose& pose, double focal_px, const Vec2& centred) {
  const Vec3 ray(centred.x / focal_px, centred.y / focal_px, 1.0);
  const double inverse_depth = glm::dot(plane_vector(pose), ray);
  return ray / inverse_depth;
}

}  // namespace oflab
