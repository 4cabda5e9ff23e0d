// The warp models of today's reprojection (manual/policies.md "Today's reprojection"): the
// homography one plane induces between two views of a rigid world, of which timewarp's
// rotation-only homography (the plane at infinity) and a stabilization plane's are cases.
//
// Frames. Viewer frames as in core/flow/camera.h (X right, Y down, Z forward, world units).
// A rigid step (R, t) maps a point's coordinates in the earlier viewer frame to the later
// one: X_now = R X_then + t. A plane not through the eye is its plane vector m (as
// plane_vector in core/flow/plane.h): its points satisfy m.X = 1, so 1/Z = m.(x/f, y/f, 1) at
// centred pixel (x, y); m = 0 is the plane at infinity.
#pragma once

#include "flow/camera.h"
#include "flow/plane.h"

namespace oflab {

struct RigidStep3 {
  Mat3 rotation{1.0};     // R, a proper rotation
  Vec3 translation{0.0};  // t, world units
};

// The rigid step that carries pose `from` onto pose `to` (two camera-frame poses of the same
// rigid body): R maps from's plane axes onto to's, t = to.point - R from.point.
// Precondition: both poses have usable axes (plane_pose_problem's normal and up are fine).
RigidStep3 rigid_step_between(const PlanePose& from, const PlanePose& to);

// The plane vector of the plane through `point` with normal `normal` (viewer frame).
// Precondition: the plane does not pass through the eye (normal.point != 0).
Vec3 plane_vector_of(const Vec3& point, const Vec3& normal);

// The plane vector m' of the plane m after the rigid step: m' = R m / (1 + (R m).t).
// Precondition: the plane does not pass through the eye after the step.
Vec3 plane_vector_after(const Vec3& m, const RigidStep3& step);

// The homography in top-left pixels (core/flow/camera.h) that the plane m induces between
// the view before and after `step`: P (R + t m^T) P^-1 with P the top-left intrinsics. Exact
// for every pixel showing a point of that plane; m = 0 gives timewarp's rotation-only
// homography K R K^-1, exact for any depth when t = 0.
Mat3 plane_induced_homography(const Camera& camera, const RigidStep3& step, const Vec3& m);

}  // namespace oflab
