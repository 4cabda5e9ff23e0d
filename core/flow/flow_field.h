// Instantaneous optic flow of a moving plane (dissertation sections 4.4-4.8, eq. 22, 33-34,
// 44, 46-47, 51; corrected as in manual/theory.md#errata).
//
// Every plane point satisfies n.R = 1, so dR/dt = B R with B = [Omega]x + V n^T, and the
// image flow is exactly quadratic in centred pixels (x, y):
//   v_x = tx + J11 x + J12 y + px x^2 + py x y
//   v_y = ty + J21 x + J22 y + px x y + py y^2
// Units: tx, ty in pixels per unit time; Jij per unit time; px, py per pixel per unit time.
#pragma once

#include "flow/camera.h"
#include "flow/motion.h"
#include "flow/plane.h"

namespace oflab {

// The 8 planar coefficients, expanded about the centred image point `origin`
// (the principal point (0, 0) unless re-expanded); (x, y) in the formula above are
// measured from `origin`.
struct PlanarFlowCoefficients {
  double tx = 0.0, ty = 0.0;
  double j11 = 0.0, j12 = 0.0, j21 = 0.0, j22 = 0.0;
  double px = 0.0, py = 0.0;
  Vec2 origin{0.0, 0.0};
};

// The velocity-gradient matrix B = [Omega]x + V n^T of eq. 21 restricted to the plane,
// with V = eye_velocity(motion, pose). Units: per unit time. Precondition: the pose is
// valid (plane_pose_problem is empty).
Mat3 velocity_gradient(const PlanePose& pose, const RigidMotion& motion);

// The 8 coefficients at the principal point, in centred pixels (table of
// manual/flow-math.md section 2). Preconditions: valid camera and pose.
PlanarFlowCoefficients planar_flow_coefficients(const Camera& camera, const PlanePose& pose,
                                                const RigidMotion& motion);

// The quadratic flow at centred pixel p, pixels per unit time.
Vec2 flow_at(const PlanarFlowCoefficients& c, const Vec2& p);

// The same coefficients re-expanded about the centred point `origin` (px, py unchanged).
PlanarFlowCoefficients reexpand(const PlanarFlowCoefficients& c, const Vec2& origin);

// The exact flow at centred pixel p: the projection of the 3D velocity V + Omega x R of the
// plane point R seen at p. Independent of the coefficient formulas (used to check them).
// Precondition: the ray through p meets the plane in front of the eye.
Vec2 exact_flow_at(const Camera& camera, const PlanePose& pose, const RigidMotion& motion,
                   const Vec2& p);

// Image acceleration (second time derivative of the image position) at time 0 of the plane
// point seen at centred pixel p, pixels per unit time squared, for the given motion model
// (manual/flow-math.md section 2; it replaces the dissertation's eq. 48).
Vec2 image_acceleration(const Camera& camera, const PlanePose& pose, const RigidMotion& motion,
                        const Vec2& p);

}  // namespace oflab
