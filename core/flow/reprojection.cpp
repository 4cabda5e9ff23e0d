// The plane-induced homography of today's reprojection (core/flow/reprojection.h).
#include "flow/reprojection.h"

namespace oflab {
namespace {

Mat3 axes_matrix(const PlanePose& pose) {
  const PlaneAxes a = plane_axes(pose);
  return Mat3(a.right, a.up, a.normal);  // columns
}

}  // namespace

RigidStep3 rigid_step_between(const PlanePose& from, const PlanePose& to) {
  RigidStep3 step;
  step.rotation = axes_matrix(to) * glm::transpose(axes_matrix(from));
  step.translation = to.point - step.rotation * from.point;
  return step;
}

Vec3 plane_vector_of(const Vec3& point, const Vec3& normal) {
  return normal / glm::dot(normal, point);
}

Vec3 plane_vector_after(const Vec3& m, const RigidStep3& step) {
  const Vec3 rm = step.rotation * m;
  return rm / (1.0 + glm::dot(rm, step.translation));
}

Mat3 plane_induced_homography(const Camera& camera, const RigidStep3& step, const Vec3& m) {
  const Mat3 k = centred_intrinsics(camera);
  const Mat3 h = step.rotation + glm::outerProduct(step.translation, m);
  return centred_to_pixel_homography(camera, k * h * glm::inverse(k));
}

}  // namespace oflab
