// The handful of numbers the scene controls show, and how they map onto a PlaneScene.
// Plain C++: a parametrisation for people, not new geometry (the geometry stays in core).
//
// Orientation: the unit normal is N = (cos(tilt) sin(turn), sin(tilt), cos(tilt) cos(turn)),
// so turn (degrees) tilts the plane about the vertical image axis and tilt (degrees) about
// the horizontal one; turn = tilt = 0 is a plane facing the viewer (N along +Z, pointing
// away from the eye). Distance is the depth Z of the plane centre P; changing it slides P
// along its viewing ray, so the centre's image stays where it is.
#pragma once

#include "flow/plane_scene.h"

namespace oflab {

struct PlaneOrientation {
  double turn_deg = 0.0;  // about the vertical axis, degrees, positive turns N towards +X
  double tilt_deg = 0.0;  // about the horizontal axis, degrees, positive turns N towards +Y
};

// Orientation of a non-zero normal (any length).
PlaneOrientation orientation_of(const Vec3& normal);

// Unit normal of an orientation.
Vec3 normal_of(const PlaneOrientation& orientation);

// The pose with its centre moved along its viewing ray to depth `depth` (world units).
// Precondition: pose.point.z != 0. A non-positive depth gives a pose that
// plane_pose_problem rejects (the centre goes behind the eye).
PlanePose with_centre_depth(const PlanePose& pose, double depth);

}  // namespace oflab
