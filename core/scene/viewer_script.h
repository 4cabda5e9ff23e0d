// The viewer of a walkthrough (dissertation section 6.6): a camera moving through a static
// scene. Reading viewer scripts from files is analysis/formats/viewer_script_file.h; this is the
// data model and the exact integration of the camera's motion.
//
// Frames. The world frame is any right-handed frame the scene is written in (the shipped
// scenes use Y up). The viewer frame is core/flow/camera.h's: eye at the origin, X right, Y down,
// Z forward. A ViewerPose maps world points to viewer points, x_view = Q x_world + s.
//
// Motion. The camera moves with velocity V_cam and angular velocity Omega_cam, both in its
// own (viewer) frame, per frame. Seen from the viewer, every scene point then moves with the
// screw motion V = -V_cam, Omega = -Omega_cam (manual/flow-math.md section 1):
// the same RigidMotion drives every polygon's PlaneEngine.
#pragma once

#include <string>
#include <vector>

#include "flow/camera.h"
#include "flow/geometry.h"
#include "flow/motion.h"

namespace oflab {

struct ViewerPose {
  Mat3 rotation{1.0};     // Q: world directions -> viewer directions (a proper rotation)
  Vec3 translation{0.0};  // s: the world origin in viewer coordinates
};

// The viewer at `position` (world) looking at `target` with `up` giving the image's up
// direction (the viewer's -Y). Throws std::invalid_argument when the inputs are not finite,
// target == position, or up is parallel to the view direction.
ViewerPose look_at(const Vec3& position, const Vec3& target, const Vec3& up);

// Empty when look_at would accept the inputs, else the reason.
std::string look_at_problem(const Vec3& position, const Vec3& target, const Vec3& up);

Vec3 to_view(const ViewerPose& pose, const Vec3& world_point);
Vec3 direction_to_view(const ViewerPose& pose, const Vec3& world_direction);
// The eye position in world coordinates, -Q^T s.
Vec3 eye_position(const ViewerPose& pose);

// The motion of scene points in the viewer frame when the camera moves with (V_cam,
// Omega_cam) in its own frame: a Screw motion with V = -V_cam, Omega = -Omega_cam.
RigidMotion scene_motion(const Vec3& camera_velocity, const Vec3& camera_omega);

// The viewer pose after one frame of `motion` (a scene motion, see scene_motion): the exact
// rigid step composed with `pose`, so that advance_pose of any plane seen from `pose` gives
// the plane seen from the result.
ViewerPose advance_viewer(const ViewerPose& pose, const RigidMotion& motion);

struct ViewerFrame {
  ViewerPose pose;     // the viewer at this frame
  RigidMotion motion;  // scene motion from this frame to the next (dt = 1 frame)
};

struct ViewerScript {
  std::string name;
  std::string description;
  Camera camera;
  std::vector<ViewerFrame> frames;
};

// A stretch of frames with constant camera velocities (per frame, viewer frame).
struct ViewerSegment {
  int frames = 0;  // >= 1
  Vec3 camera_velocity{0.0};
  Vec3 camera_omega{0.0};
};

// Frame 0 shows `initial`; each next pose is the exact step of the previous frame's motion.
// Precondition: every segment has frames >= 1.
std::vector<ViewerFrame> expand_viewer_segments(const ViewerPose& initial,
                                                const std::vector<ViewerSegment>& segments);

}  // namespace oflab
