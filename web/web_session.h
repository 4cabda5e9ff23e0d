// One browser page's state and the core objects it shows, for the page's JavaScript
// (bound in web/bindings.cpp; manual/web.md). The page holds one WindowState, the same value
// a desktop window, a session file and a lesson file hold (session/state/window_state.h); every
// number it shows comes from core: the flow (core/flow, through session/display/flow_parts.h),
// the bases (session/basis/basis_catalog.h) and the engine's runs (core/engine/animator.h).
//
// Frames: the scene of frame k is the plane of the state moved for k / 30 seconds (the
// desktop's scene panel, 150 frames a loop), or frame k of the state's motion script.
// Positions handed to the page are top-left image pixels of the scene's camera (Y down);
// flows are pixels per second (30 frames per second).
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "engine/animator.h"
#include "engine/script.h"
#include "flow/plane_scene.h"
#include "lessons/lesson_player.h"
#include "lessons/lessons.h"
#include "player/plane_panel.h"
#include "state/window_state.h"

namespace oflab {

// One compared run of the comparison view: a reuse policy playing the source, or the exact
// projection (the `rerender` policy: every frame rendered exactly).
struct WebRun {
  std::string policy;
  std::unique_ptr<Animator> animator;
  AnimationFrame last;
  std::array<int, kLevelCount> level_frames{};  // frames 1 .. now per level
  double max_error_px = 0.0;                    // largest measured error, frames 1 .. now
  std::vector<std::uint8_t> pixels;             // the frame at panel size (frame_pixels.h)
  std::vector<std::uint8_t> heat;               // difference to the exact frame, panel size
  int heat_max = 0;                             // its largest difference, grey levels
  double psnr_db = 0.0;                         // against the exact frame (image_compare.h)
};

class WebSession : public LessonStage {
 public:
  // Reads the shipped butterfly texture from the module's embedded datasets. Throws
  // std::runtime_error when it cannot (a broken build).
  WebSession();

  // The state as a session's state object (session/state/window_state_file.h), JSON text.
  std::string state_json() const;
  // Reads `object_json` (fields of a state object) over the default state and shows it.
  // Returns "" or the reason it was refused (the state is then unchanged): a field the
  // session reader refuses, a script that cannot be read, a plane no view can draw.
  std::string set_state(const std::string& object_json, const std::string& origin);
  // A motion script file of the user's: parsed (analysis/formats/script_file.h) and made
  // known under its script name for set_state's "script" field. Returns "" or the reader's
  // message naming `origin`, the frame or segment and the field.
  std::string add_script(const std::string& text, const std::string& origin);

  // Frames of the loop the views play and the frame shown, on the same frame clock as the
  // desktop's (session/player/plane_panel.h: the script's or the source's length, else 150
  // frames; a frame where the plane cannot be drawn lands on 0). seek(-k) goes k frames
  // back from the loop's end.
  int frame_count() const;
  int frame() const { return panel_.frame(); }
  void seek(int frame);

  // Shows step `step` of the lesson `name` (shipped or read by lesson_file_json) through the
  // one lesson player (session/lessons/lesson_player.h), as the desktop shows it: "" or why
  // not.
  std::string go_to_lesson(const std::string& name, int step);

  // The page as a lesson's stage.
  WindowState stage_state() const override { return shown_state(); }
  std::string stage_apply(const WindowState& state) override { return apply_state(state); }
  void stage_stop() override { state_.playing = false; }
  void stage_seek(int frame) override { panel_.set_frame(frame); }
  int stage_loop_frames() const override { return panel_.loop_frames(); }
  void stage_play(int frames) override;
  void stage_set_step(int step) override { state_.lesson_step = step; }

  // The window state's field table (session/state/state_fields.h state_schema) as JSON:
  // the page takes the fields' names, types and ranges from it.
  static std::string state_schema_json();

  // The scene of the frame shown, and "" or why the flow views cannot draw it.
  PlaneScene scene() const;
  std::string scene_problem() const;

  // The flow view's numbers as JSON: the camera, the plane's outline (top-left pixels), the
  // planar coefficients with their units, the Taylor, Waxman-Ullman and planar-basis terms.
  std::string flow_json() const;
  // The part `part_key` (session/display/flow_parts.h keys) on a grid `spacing_px` apart, as
  // x, y, vx, vy quadruples (top-left pixels; pixels per second). Empty for a scene problem.
  std::vector<double> flow_arrows(const std::string& part_key, double spacing_px) const;
  // Streamlines of the part from seeds `spacing_px` apart, `duration_s` seconds each in
  // `steps` Runge-Kutta steps: x, y pairs (top-left pixels), one NaN pair between lines.
  std::vector<double> flow_streamlines(const std::string& part_key, double spacing_px,
                                       double duration_s, int steps) const;

  // The basis gallery of `basis_key` (session/basis/basis_catalog.h): per term its symbol,
  // description, order, unit, coefficient in the current flow, whether it is negligible
  // within radius_px, and its unit flow on a (2n+1)^2 grid over [-radius_px, radius_px]^2
  // (x, y, vx, vy quadruples, centred pixels). "" for an unknown key.
  std::string basis_json(const std::string& basis_key, double radius_px, int n) const;

  // The comparison: the state's compared policies and the exact projection playing the
  // state's source at the frame shown. Returns "" or why the source cannot be played.
  std::string comparison_problem() const { return comparison_problem_; }
  // Brings the runs to the frame shown (forward frame by frame, backward by a restart; the
  // runs stand still while the page shows another view) and samples their frames and heat
  // maps at panel_width x panel_height display pixels (run_pixels, run_heat). Returns per
  // run: policy, level of the frame, measured error, largest error so far, level shares over
  // frames 1 .. now, the largest difference from the exact frame and the PSNR against it,
  // the outlines of the shown layers (frame pixels). Panel sizes are clamped to 1 .. 4096.
  std::string update_comparison(int panel_width, int panel_height);
  int run_count() const { return static_cast<int>(runs_.size()); }
  const WebRun& run(int index) const { return runs_.at(static_cast<std::size_t>(index)); }
  int frame_width() const;
  int frame_height() const;

  // Every lesson (shipped, teaching order) as JSON: name, title, narrative, the state of
  // its narrative and of each step (state objects), each step's caption, frame and play.
  static std::string lessons_json();
  // A lesson file of the user's, read by the desktop's reader: the same JSON for it alone,
  // or {"error": message naming `origin` and the field}.
  static std::string lesson_file_json(const std::string& text, const std::string& origin);

  // One shipped motion script played by the engine with the default settings (the default
  // policy, as `oflab-cli animate --script NAME`): {"levels": [level of every frame],
  // "coefficients": {tx ... py at frame 0, as `oflab-cli flow`}} or {"error": ...}.
  static std::string script_run_json(const std::string& name);
  // The names of the shipped motion scripts (datasets/scripts), JSON list.
  static std::string script_names_json();

 private:
  // The state with the frame the clock shows.
  WindowState shown_state() const;
  // Shows `state` whole: "" or why it was refused (then nothing changed).
  std::string apply_state(WindowState state);
  void rebuild_comparison();
  void advance_runs_to(int frame);
  // Per run of the frame reached: the pixels at the panel size, heat map, PSNR.
  void finish_runs_frame(int panel_width, int panel_height);

  Image texture_;
  PlanePanel panel_;   // the frame clock: the plane, its script, the source's loop
  WindowState state_;  // the frame is the panel's
  std::map<std::string, MotionScript> scripts_;  // shipped (read on demand) and added
  std::vector<WebRun> runs_;                     // compared policies, then the exact run
  std::string comparison_problem_;
  int sampled_frame_ = -1;  // the frame whose pixels the runs hold, at sampled_size_
  glm::ivec2 sampled_size_{0, 0};
};

}  // namespace oflab
