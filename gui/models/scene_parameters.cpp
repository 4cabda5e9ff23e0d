#include "models/scene_parameters.h"

#include <cmath>

namespace oflab {
namespace {

constexpr double kDegreesPerRadian = 57.29577951308232;

}  // namespace

PlaneOrientation orientation_of(const Vec3& normal) {
  const Vec3 n = glm::normalize(normal);
  PlaneOrientation o;
  o.turn_deg = std::atan2(n.x, n.z) * kDegreesPerRadian;
  o.tilt_deg = std::asin(glm::clamp(n.y, -1.0, 1.0)) * kDegreesPerRadian;
  return o;
}

Vec3 normal_of(const PlaneOrientation& orientation) {
  const double turn = orientation.turn_deg / kDegreesPerRadian;
  const double tilt = orientation.tilt_deg / kDegreesPerRadian;
  return Vec3(std::cos(tilt) * std::sin(turn), std::sin(tilt), std::cos(tilt) * std::cos(turn));
}

PlanePose with_centre_depth(const PlanePose& pose, double depth) {
  PlanePose moved = pose;
  moved.point = pose.point * (depth / pose.point.z);
  return moved;
}

}  // namespace oflab
