// Homographies of a moving plane (dissertation eq. 15-19, 52-53, 56; corrected as in
// manual/theory.md#errata, items 2, 16, 17, 20). All map centred pixels to centred pixels
// (see core/flow/camera.h) and are normalised so that entry (3,3) is 1, unless stated otherwise.
#pragma once

#include "flow/camera.h"
#include "flow/flow_field.h"
#include "flow/motion.h"
#include "flow/plane.h"

namespace oflab {

// First-order (Taylor) frame-to-frame homography over time dt (units of the coefficients'
// time), about the coefficients' expansion origin o:
//   T(o) [[1 + J11 dt, J12 dt, tx dt], [J21 dt, 1 + J22 dt, ty dt], [-px dt, -py dt, 1]] T(-o).
// The perspective row carries a minus sign (erratum 16; the dissertation prints +).
// Its error against the exact motion is O(dt^2).
Mat3 taylor_homography(const PlanarFlowCoefficients& c, double dt);

// The exact homography of a rigid step R' = Q R + s of the plane n.R = 1:
// K (Q + s n^T) K^-1 with K = diag(f, f, 1), normalised. Precondition: valid pose.
Mat3 exact_homography(const Camera& camera, const PlanePose& pose, const RigidStep& step);

// The exact frame-to-frame homography over dt for a motion model.
Mat3 exact_homography(const Camera& camera, const PlanePose& pose, const RigidMotion& motion,
                      double dt);

// The texture-to-image homography (eq. 56 in pixels): texel coordinates (top-left origin,
// see core/flow/plane.h) to centred pixels, K [R U P] composed with the texel-to-plane map.
Mat3 texture_to_image(const Camera& camera, const PlanePose& pose);

// Images of the plane's four corners (plane_corners order) in centred pixels.
// Precondition: every corner is in front of the eye (Z > 0).
std::array<Vec2, 4> projected_corners(const Camera& camera, const PlanePose& pose);

// Largest distance, pixels, between H applied to each point of `from` and `to`.
double max_corner_distance(const Mat3& h, const std::array<Vec2, 4>& from,
                           const std::array<Vec2, 4>& to);

}  // namespace oflab

namespace oflab {

// Largest corner error, pixels, of each level of approximation of the plane's image after
// time dt, against the exact corners (manual/flow-math.md section 4.2, default case):
//  none: the corners do not move; translate: by (tx, ty) dt; affine: by the first-order
//  (affine) part of the Taylor homography; taylor: by the full Taylor homography.
// Coefficients are taken about the principal point. Precondition: valid camera and pose,
// plane corners in front of the eye now and after dt.
struct ApproximationErrors {
  double none = 0.0, translate = 0.0, affine = 0.0, taylor = 0.0;
};
ApproximationErrors approximation_corner_errors(const Camera& camera, const PlanePose& pose,
                                                const RigidMotion& motion, double dt);

}  // namespace oflab
