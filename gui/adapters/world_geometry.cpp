#include "adapters/world_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace oflab {

std::array<Vec3, 4> image_plane_corners(const Camera& camera, double depth) {
  const double k = depth / camera.focal_px;  // world units per pixel on the image plane
  const double left = -camera.cx * k, right = (camera.width - camera.cx) * k;
  const double top = -camera.cy * k, bottom = (camera.height - camera.cy) * k;
  return {Vec3(left, top, depth), Vec3(right, top, depth), Vec3(right, bottom, depth),
          Vec3(left, bottom, depth)};
}

Vec3 ray_at_depth(const Vec3& point, double depth) { return point * (depth / point.z); }

double plane_image_depth(const std::vector<Vec3>& centres) {
  if (centres.empty()) return 1.0;
  std::vector<double> depths;
  for (const Vec3& c : centres) depths.push_back(c.z);
  std::sort(depths.begin(), depths.end());
  const double median = depths[depths.size() / 2];
  if (!(median > 0.0)) return 1.0;
  return std::max(0.5 * depths.front(), 0.25 * median);
}

double scene_image_depth(const std::vector<Vec3>& points) {
  if (points.empty()) return 1.0;
  Vec3 lo = points.front(), hi = points.front();
  for (const Vec3& p : points) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const double diagonal = glm::length(hi - lo);
  return diagonal > 0.0 ? 0.1 * diagonal : 1.0;
}

double arrow_length(double magnitude, double largest, double full_length) {
  if (!(magnitude > 0.0)) return 0.0;
  const double ratio = largest > 0.0 ? std::min(1.0, magnitude / largest) : 1.0;
  return full_length * (0.35 + 0.65 * ratio);
}

std::array<double, 16> arrow_matrix(const Vec3& origin, const Vec3& direction, double length) {
  const double norm = glm::length(direction);
  Vec3 x(0.0), y(0.0), z(0.0);
  if (norm > 0.0 && length > 0.0) {
    const Vec3 d = direction / norm;
    // Any unit vector not parallel to d completes the frame; the arrow is round.
    const Vec3 helper = std::abs(d.x) < 0.9 ? Vec3(1.0, 0.0, 0.0) : Vec3(0.0, 1.0, 0.0);
    const Vec3 e1 = glm::normalize(glm::cross(d, helper));
    x = d * length;
    y = e1 * length;
    z = glm::cross(d, e1) * length;
  }
  return {x.x, y.x, z.x, origin.x,  //
          x.y, y.y, z.y, origin.y,  //
          x.z, y.z, z.z, origin.z,  //
          0.0, 0.0, 0.0, 1.0};
}

std::array<double, 16> viewer_to_world_matrix(const ViewerPose& pose) {
  const Mat3 qt = glm::transpose(pose.rotation);
  const Vec3 t = -(qt * pose.translation);
  std::array<double, 16> m{};
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) m[size_t(4 * r + c)] = entry(qt, r, c);
    m[size_t(4 * r + 3)] = t[r];
  }
  m[15] = 1.0;
  return m;
}

Vec3 viewer_to_world(const ViewerPose& pose, const Vec3& viewer_point) {
  return glm::transpose(pose.rotation) * (viewer_point - pose.translation);
}

}  // namespace oflab
