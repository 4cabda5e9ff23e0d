// Rigid motion of a plane relative to the viewer (dissertation eq. 21 and section 4.2;
// manual/flow-math.md section 4.2).
//
// Velocities are in world units per unit time and radians per unit time, in the viewer
// frame. The unit of time is the caller's (the scripts use frames); every result scales
// with it consistently.
//
// Three motion models describe how (velocity, omega) act over a finite step dt:
//  - Screw (default): the exact integral of dR/dt = V + Omega x R with constant V and
//    Omega; Omega rotates about the eye, and V is the velocity of the body point at the eye.
//  - RotateThenTranslate: rotate by |Omega| dt about Omega through the eye, then translate
//    by V dt. Same instantaneous flow as Screw; positions differ at O(dt^2).
//  - SpinAboutCentre: `velocity` is V_c, the velocity of the plane centre P, and the plane
//    spins with Omega about P. Its instantaneous flow is that of eq. 21 with
//    V = V_c - Omega x P (plugging V_c in directly is wrong whenever Omega x P != 0).
#pragma once

#include <string>

#include "flow/geometry.h"
#include "flow/plane.h"

namespace oflab {

enum class MotionModel { kScrew, kRotateThenTranslate, kSpinAboutCentre };

struct RigidMotion {
  Vec3 velocity{0.0, 0.0, 0.0};  // V (Screw, RotateThenTranslate) or V_c (SpinAboutCentre)
  Vec3 omega{0.0, 0.0, 0.0};     // Omega, radians per unit time
  MotionModel model = MotionModel::kScrew;
};

// The one vocabulary of motion models, in the order of the enum: motion_model_name gives
// "screw", "rt" or "centre" (the words of options, script and session files and JSON);
// parse_motion_model accepts those (and "center" for "centre") and returns false, leaving
// *model unchanged, for anything else; motion_model_name_list joins the names with
// `separator`: "screw, rt, centre" for error messages, "screw|rt|centre" for usage lines.
bool parse_motion_model(const char* text, MotionModel* model);
const char* motion_model_name(MotionModel model);
std::string motion_model_name_list(const std::string& separator = ", ");

// V of eq. 21 (velocity of the body point at the eye) for the given pose.
Vec3 eye_velocity(const RigidMotion& motion, const PlanePose& pose);

// The reference velocity V_ref of the image-acceleration formula: 0 for Screw, V for
// RotateThenTranslate, V_c for SpinAboutCentre (manual/flow-math.md section 2).
Vec3 acceleration_reference_velocity(const RigidMotion& motion, const PlanePose& pose);

// A finite rigid step R' = Q R + s of every body point over time dt.
struct RigidStep {
  Mat3 rotation{1.0};               // Q, a proper rotation
  Vec3 translation{0.0, 0.0, 0.0};  // s, world units
};
RigidStep rigid_step(const RigidMotion& motion, const PlanePose& pose, double dt);

// The pose after the step: P' = Q P + s, N' = Q N, U' = Q U (size and texture unchanged).
PlanePose advance_pose(const PlanePose& pose, const RigidStep& step);

// Rotation by angle |axis_angle| about axis_angle (Rodrigues), exact for any angle.
Mat3 rotation_matrix(const Vec3& axis_angle);

}  // namespace oflab
