// Taylor and exact homographies of a moving plane (manual/flow-math.md section 4).
#include "flow/homography.h"

#include <algorithm>

namespace oflab {

Mat3 taylor_homography(const PlanarFlowCoefficients& c, double dt) {
  const Mat3 h =
      mat3_from_rows({1.0 + c.j11 * dt, c.j12 * dt, c.tx * dt},
                     {c.j21 * dt, 1.0 + c.j22 * dt, c.ty * dt}, {-c.px * dt, -c.py * dt, 1.0});
  const Mat3 about_origin =
      translation_matrix(c.origin.x, c.origin.y) * h * translation_matrix(-c.origin.x, -c.origin.y);
  return normalise_homography(about_origin);
}

Mat3 exact_homography(const Camera& camera, const PlanePose& pose, const RigidStep& step) {
  const Vec3 n = plane_vector(pose);
  const Vec3& s = step.translation;
  const Mat3 m = step.rotation + mat3_from_rows(s.x * n, s.y * n, s.z * n);
  const Mat3 k = centred_intrinsics(camera);
  return normalise_homography(k * m * glm::inverse(k));
}

Mat3 exact_homography(const Camera& camera, const PlanePose& pose, const RigidMotion& motion,
                      double dt) {
  return exact_homography(camera, pose, rigid_step(motion, pose, dt));
}

Mat3 texture_to_image(const Camera& camera, const PlanePose& pose) {
  const PlaneAxes a = plane_axes(pose);
  // Columns R, U, P: (s, r, 1) -> P + s R + r U in the camera frame.
  const Mat3 plane_to_camera(a.right, a.up, pose.point);
  return normalise_homography(centred_intrinsics(camera) * plane_to_camera * texel_to_plane(pose));
}

std::array<Vec2, 4> projected_corners(const Camera& camera, const PlanePose& pose) {
  const std::array<Vec3, 4> c = plane_corners(pose);
  return {project_centred(camera, c[0]), project_centred(camera, c[1]),
          project_centred(camera, c[2]), project_centred(camera, c[3])};
}

double max_corner_distance(const Mat3& h, const std::array<Vec2, 4>& from,
                           const std::array<Vec2, 4>& to) {
  double worst = 0.0;
  for (size_t i = 0; i < from.size(); ++i) {
    worst = std::max(worst, glm::length(apply_homography(h, from[i]) - to[i]));
  }
  return worst;
}

}  // namespace oflab

namespace oflab {

ApproximationErrors approximation_corner_errors(const Camera& camera, const PlanePose& pose,
                                                const RigidMotion& motion, double dt) {
  const std::array<Vec2, 4> now = projected_corners(camera, pose);
  const std::array<Vec2, 4> later =
      projected_corners(camera, advance_pose(pose, rigid_step(motion, pose, dt)));
  const PlanarFlowCoefficients c = planar_flow_coefficients(camera, pose, motion);
  PlanarFlowCoefficients first_order = c;
  first_order.px = first_order.py = 0.0;
  ApproximationErrors e;
  e.none = max_corner_distance(Mat3(1.0), now, later);
  e.translate = max_corner_distance(translation_matrix(c.tx * dt, c.ty * dt), now, later);
  e.affine = max_corner_distance(taylor_homography(first_order, dt), now, later);
  e.taylor = max_corner_distance(taylor_homography(c, dt), now, later);
  return e;
}

}  // namespace oflab
