// The scene panel's plane as a value, without Qt: the plane at frame 0 (what the controls
// edit), its texture, the frame shown, and a motion script whose frames give the pose and
// motion of each frame. Every front-end's frame clock: the desktop's scene model
// (gui/models/scene_model.h) wraps one, the browser page and the headless lab
// (player/lab.h) hold one, so a frame lands on the same frame everywhere.
//
// Time: frames are 1/30 s apart. The scene's V and Omega are per second; a script's
// per-frame velocities (core/engine/script.h) are converted to per second at that rate.
#pragma once

#include <optional>
#include <string>

#include "engine/script.h"
#include "flow/plane_scene.h"
#include "image/image.h"

namespace oflab {

class PlanePanel {
 public:
  static constexpr double kSecondsPerFrame = 1.0 / 30.0;
  static constexpr int kLoopFrames = 150;

  // The default demo scene with `texture` (its size becomes the pose's texture size), at
  // frame 0. Precondition: the texture is not empty.
  explicit PlanePanel(Image texture);

  // The scene at frame 0 (with a script: the script's camera, first pose and motion).
  const PlaneScene& scene() const { return scene_; }
  const Image& texture() const { return texture_; }
  // The file the texture came from, empty for the default texture.
  const std::string& texture_source() const { return texture_source_; }
  int frame() const { return frame_; }
  // Frames in one loop: a loop override, else the script's length, else kLoopFrames.
  int loop_frames() const;

  // The scene (pose, and motion per second) at `frame` of the plane's own loop.
  PlaneScene scene_at(int frame) const;
  PlanePose current_pose() const { return scene_at(frame_).pose; }
  RigidMotion current_motion() const { return scene_at(frame_).motion; }

  // The script being played (and its name), or nullptr when the scene's own motion plays.
  const MotionScript* script() const { return script_ ? &*script_ : nullptr; }
  const std::string& script_name() const { return script_name_; }

  // The motion of one loop as a script (per-frame velocities): the script itself, or the
  // scene's motion sampled every frame up to kLoopFrames or the first frame the plane cannot
  // be drawn in.
  MotionScript as_script() const;

  // Frames in one loop while another source plays (its length); 0 restores the plane's own.
  // The frame goes to 0 when it is beyond the new loop.
  void set_loop_override(int frames);

  // Replaces the scene (and drops any script): "" when accepted, else why not
  // (plane_state_problem), changing nothing. The frame is kept unless the new scene cannot
  // be drawn at it (then frame 0).
  std::string set_scene(const PlaneScene& scene);
  // Plays a script from frame 0: "" when accepted, else why not ("script NAME has no
  // frames", "script NAME, frame 0: ..."), changing nothing.
  std::string set_script(const MotionScript& script, const std::string& name);
  // Replaces the texture; its size becomes the pose's texture size. "" or why not (an
  // empty image), changing nothing.
  std::string set_texture(Image texture, const std::string& source_name);

  // Moves to `frame` (>= 0), looping over loop_frames(); returns to frame 0 when the plane
  // cannot be drawn at that frame (for instance behind the eye). The frame a seek lands on
  // is what every front-end shows.
  void set_frame(int frame);
  // The frame set_frame(frame) lands on, without moving.
  int landing_frame(int frame) const;

 private:
  bool drawable_at(int frame) const;

  PlaneScene scene_;
  std::optional<MotionScript> script_;
  std::string script_name_;
  Image texture_;
  std::string texture_source_;
  int frame_ = 0;
  int loop_override_ = 0;
};

}  // namespace oflab
