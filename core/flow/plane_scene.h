// The "current scene" every view draws: one camera, one textured plane and its rigid
// motion (core types only; no Qt, no VTK). The default demo is the default case of
// manual/flow-math.md section 4.2.
#pragma once

#include <string>

#include "flow/camera.h"
#include "flow/motion.h"
#include "flow/plane.h"

namespace oflab {

struct PlaneScene {
  Camera camera;
  PlanePose pose;
  RigidMotion motion;
};

// The default demo: 800 x 600 image, f = 600 px, the butterfly on a 1 x 0.8 plane at
// P = (0.2, 0, 2) tilted towards the viewer (N = (0.4, -0.2, 1), U = (0, -1, 0)) turning
// once every kDemoTurnSeconds about the axis (0.3, 0.3, 1) through (0, 0, 2.06): a screw
// motion of zero pitch, Omega = 2 pi / 5 s along that axis and V = -Omega x (0, 0, 2.06).
// The plane circles about the axis (translation), comes nearer and goes away (scale),
// turns in the image (rotation) and changes its tilt (shear and the perspective terms); its
// whole rectangle stays inside the image in every frame, and after one turn (the scene
// panel's 150-frame loop at 30 frames per second) it is back at its start, so the loop
// is seamless. The texture size is the bundled butterfly's (243 x 198 texels); SceneModel
// sets it to whatever texture is loaded.
PlaneScene default_demo_scene();

// Seconds of one turn of the default demo: the scene panel's loop (150 frames at 30 per second).
constexpr double kDemoTurnSeconds = 5.0;

// Empty when every view can draw the scene, otherwise one line saying what is wrong:
// core's camera_problem and plane_pose_problem, plus a check that all four plane corners
// are in front of the eye (a plane that reaches behind the camera has no finite image)
// and that the velocities are finite.
std::string plane_scene_problem(const PlaneScene& scene);

// The plane pose after t seconds of the scene's motion (core's rigid_step and
// advance_pose; exact for every motion model).
PlanePose pose_at_time(const PlaneScene& scene, double t);

}  // namespace oflab
