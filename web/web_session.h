// One browser page's state and the core objects it shows, for the page's JavaScript
// (bound in web/bindings.cpp; manual/web.md). The page holds the teaching layer's headless
// lab (session/player/lab.h), the one the desktop window and `oflab-cli lesson` hold: its
// state is the same WindowState a session file and a lesson file hold, its sources are
// every kind the desktop plays (the plane, motion scripts, scenes with viewer scripts, scene
// shifting; session/player/animation_sources.h), lessons play on it through the one lesson
// player and their engine claims are measured on it (session/player/engine_claims.h). Every
// number the page shows comes from core through it: the flow (session/display/flow_parts.h),
// the bases (session/basis/basis_catalog.h) and the engine's runs (core/engine/animator.h).
//
// Frames: the lab's frame clock (session/player/plane_panel.h): the plane of the state moved
// for k / 30 seconds (150 frames a loop), frame k of the state's motion script, or of the
// source's own length (a viewer script's frames).
// Positions handed to the page are top-left image pixels of the scene's camera (Y down);
// flows are pixels per second (30 frames per second).
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "display/world_geometry.h"
#include "engine/animator.h"
#include "flow/plane_scene.h"
#include "frame_pixels.h"
#include "lessons/lessons.h"
#include "plane_image.h"
#include "player/engine_claims.h"
#include "player/lab.h"
#include "state/window_state.h"

namespace oflab {

// One panel of the comparison view: a compared policy's run (the lab's,
// player/policy_comparison.h), the source's own run when its kind has no reuse policy, or the exact
// projection (the `rerender` policy: every frame rendered exactly), sampled for the page.
struct WebPanel {
  std::string policy;
  std::vector<std::uint8_t> pixels;  // the frame at panel size (frame_pixels.h)
  std::vector<std::uint8_t> heat;    // difference to the exact frame, panel size
  int heat_max = 0;                  // its largest difference, grey levels
  double psnr_db = 0.0;              // against the exact frame (image_compare.h)
};

class WebSession {
 public:
  // The policy whose runs draw the exact projection: every frame rendered exactly.
  static constexpr const char* kExactPolicy = "rerender";

  // A lab with the shipped butterfly texture from the module's embedded datasets. Throws
  // std::runtime_error when it cannot be read (a broken build).
  WebSession();

  // The state as a session's state object (session/state/window_state_file.h), JSON text.
  std::string state_json() const;
  // The state as a session file's text (format "oflab-session", version 2), as the desktop
  // saves it.
  std::string session_file_text() const;
  // The per-frame figures of the whole source the animation plays, as CSV: the columns of
  // `oflab-cli animate` for its kind (RunPlayer::write_csv, as the desktop's File > Export
  // per-frame CSV), one row per frame. {"csv": text} or {"error": why it cannot be played}.
  std::string run_csv_json();
  // Reads `object_json` (fields of a state object) over the default state and shows it.
  // Returns "" or the reason it was refused naming `origin` (the state is then unchanged):
  // a field the session reader refuses, a file the state names that cannot be read, a
  // source that cannot be played (Lab::apply).
  std::string set_state(const std::string& object_json, const std::string& origin);
  // A session file's text (version 1 or 2) read by the desktop's reader and shown whole:
  // "" or the reader's or the lab's message naming `origin` and the field (nothing changed).
  std::string open_session(const std::string& text, const std::string& origin);
  // A motion script file of the user's: parsed (analysis/formats/script_file.h) and kept in
  // the module's file system, where a state's "script" or script source names it by the
  // path returned: {"path": ...} or {"error": the reader's message naming `origin`, the
  // frame or segment and the field}.
  std::string add_script(const std::string& text, const std::string& origin);

  // Frames of the loop the views play and the frame shown, on the lab's frame clock (the
  // script's or the source's length, else 150 frames; a frame where the plane cannot be
  // drawn lands on 0). seek(-k) goes k frames back from the loop's end.
  int frame_count() const;
  int frame() const { return lab_.panel().frame(); }
  void seek(int frame);

  // Shows step `step` of the lesson `name` (shipped or read by lesson_file_json) through the
  // one lesson player (session/lessons/lesson_player.h) on the lab, as the desktop and
  // `oflab-cli lesson state` show it: "" or why not.
  std::string go_to_lesson(const std::string& name, int step);
  // The claims of the lesson part shown (the state's lesson and lesson_step; [] without a
  // lesson), each measured on the lab now when its kind is the engine's (session/lessons/
  // claim_kinds.h): [{"says", "kind", "source": "engine"|"screen", "measured" (engine
  // kinds and the page's panel_fill; null for NaN), "at_least", "at_most" (null when open),
  // "holds" (where measured), "line": player/engine_claims.h describe(), as `oflab-cli lesson
  // check` prints it}]. panel_fill is measured on the page with the animation view alone in
  // front (page_panel_fill); the other screen kinds by `oflab --check-lesson`.
  std::string check_claims_json();

  // The window state's field table (session/state/state_fields.h state_schema) as JSON:
  // the page takes the fields' names, types and ranges from it.
  static std::string state_schema_json();

  // The state as the lab holds it (the fields the page's JSON carries, typed).
  const WindowState& values() const { return lab_.values(); }
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

  // The world view (web/world_json.h): the loop of the panel's plane, or of a scene source's
  // walk (a source kind that uses a viewer: the scene's polygons in their levels' colours and
  // the viewer's path, as the desktop's world view), built once per state (every call that
  // may change the state rebuilds it), and the frame shown.
  std::string world_loop_json();
  std::string world_frame_json();
  // The plane's texture (premultiplied RGBA, top row first), which the world view's plane shows.
  const Image& plane_texture() const { return lab_.panel().texture(); }
  // The flow view's texture: the exact image of the plane at the frame shown
  // (web/plane_image.h) with the lab's texture and the run's sampling.
  const PlaneImage& exact_plane_image();
  // The run's animator when its source uses a viewer (a scene walked), else nullptr: the
  // engine whose frame the world view's image plane shows (the plane's shows the exact frame).
  const Animator* scene_animator();

  // The basis gallery of `basis_key` (session/basis/basis_catalog.h): per term its symbol,
  // description, order, unit, coefficient in the current flow, whether it is negligible
  // within radius_px, and its unit flow on a (2n+1)^2 grid over [-radius_px, radius_px]^2
  // (x, y, vx, vy quadruples, centred pixels). "" for an unknown key.
  std::string basis_json(const std::string& basis_key, double radius_px, int n) const;

  // The animation view's runs (web/shown_runs.h shown_runs, by the state's display: the
  // compared runs in the comparison layout, else the model's own engine) and the exact
  // projection, at the frame shown: "" or why the source cannot be played.
  std::string comparison_problem();
  // Brings the runs to the frame shown (the lab's runs: forward frame by frame, backward by a
  // restart; they stand still while another view shows) and samples their frames and heat
  // maps (run_pixels, run_heat) framed by the desktop's rule (display/panel_framing.h) in a
  // cell of cell_width x cell_height display pixels (each clamped to 1 .. 4096). Returns
  // "panel": [width, height], "shown": [x0, y0, pixel] (PanelView), and per panel: policy,
  // level (a scene's drawn layers per level), measured error, largest error so far, level
  // shares over frames 1 .. now, the largest difference from the exact frame and the PSNR
  // against it (whole frames), the shown layers' outlines (camera pixels).
  std::string update_comparison(int cell_width, int cell_height);
  // The analysis charts' history, by the desktop's rule: while the state's display is the
  // comparison layout ("comparing": true), per compared run; otherwise the model's one engine
  // (its policy, or the source's kind when the kind has no reuse policy), with "thresholds"
  // (pixels, none .. perspective). Frames max(0, now - frames + 1) .. now of the current pass
  // as {"first", "last", "comparing", "runs": [{"policy", "frames": [{"frame", "levels":
  // [drawn layers per level, the levels' order], "error_px": largest measured error (null:
  // nothing drawn), "time_ms": the frame's wall time in this page, "model_work": the engine's
  // cost model (perspective-warp pixels, AnimationFrame::model_work)}, and for the one engine
  // "approximated_percent" (null: nothing drawn) and "budgets": per level none .. perspective
  // the error it would leave (session/player/run_player.h level_budget_at; null where
  // undefined)]}]}, or {"problem": why not}. `frames` is clamped to 1 .. 1000.
  std::string analysis_json(int frames);
  int run_count();
  const WebPanel& run(int index) const { return panels_.at(static_cast<std::size_t>(index)); }
  int frame_width();
  int frame_height();

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
  // The names of the shipped scenes and viewer scripts: {"scenes": [...], "viewers": [...]}.
  static std::string scene_names_json();

 private:
  // The engines the comparison shows at the lab's frame: compared runs (or the source's own
  // run), then the exact run; empty with comparison_problem_ set when nothing plays.
  std::vector<const Animator*> shown_animators();  // memoised per frame and epoch_
  std::vector<const Animator*> find_shown_animators();
  void rebuild_exact();
  void advance_exact_to(int frame);
  // Per panel of the frame reached: the pixels of `view`, heat map, PSNR.
  void sample_panels(const std::vector<const Animator*>& animators, const PanelView& view);
  // The panel_fill claim of the animation view alone in front, measured on the page: the
  // share (percent) of its exact panel, as drawn now in the cell it was last drawn in, inside
  // the exact outlines (display/panel_framing.h outline_fill, as the desktop measures it);
  // NaN when another view shows or the panels were never drawn (left to the desktop).
  double page_panel_fill();
  // The framed part of the camera image of the frame `exact` is at, fitted into the cell.
  PanelView panel_view(const Animator& exact, int cell_width, int cell_height);
  const PlaneWorldLoop& world_loop();  // world_loop_, rebuilt when epoch_ moved

  Lab lab_;
  LabStage stage_{&lab_};            // lessons play on the lab, as `oflab-cli lesson` plays them
  std::unique_ptr<Animator> exact_;  // the exact projection of the lab's source
  AnimationFrame exact_last_;
  std::string exact_key_;  // the source and settings exact_ plays (JSON text)
  // The exact panel's engine and record: exact_, or a compared `rerender` run's.
  const Animator* exact_shown_ = nullptr;
  const AnimationFrame* exact_record_ = nullptr;
  int epoch_ = 0;  // counts the calls that may change the state (set_state, lessons, ...)
  int memo_epoch_ = -1, memo_frame_ = -1;
  std::vector<const Animator*> memo_;  // shown_animators() of memo_frame_ at memo_epoch_
  std::vector<WebPanel> panels_;       // compared runs (or the source's), then the exact one
  PlaneWorldLoop world_loop_;          // the world view's loop at world_epoch_
  int world_epoch_ = -1;
  SceneWorldLoop scene_world_loop_;  // a scene source's walk at scene_world_epoch_
  int scene_world_epoch_ = -1;
  std::string comparison_problem_;
  int sampled_frame_ = -1;       // the frame whose pixels the panels hold, at sampled_cell_
  PlaneImageCache plane_image_;  // exact_plane_image()
  glm::ivec2 sampled_cell_{0, 0};
  PanelView sampled_view_;    // the view the panels hold
  int sampled_epoch_ = -1;    // the state (epoch_) whose runs the panels hold
  FrameBounds frame_bounds_;  // what the source shows at each frame at bounds_epoch_
  int bounds_epoch_ = -1;
};

}  // namespace oflab
