// Everything the window shows, as one value: the view in front, each view's options, what
// plays and how, the frame, presentation mode and the play rate. One model holds it
// (gui/models/window_model.h); a lesson (session/lessons/lessons.h), the command line
// (gui/app/launch_options.h) and a saved session (session/state/window_state_file.h) are each a
// WindowState, and the window applies one with WindowModel::apply and captures one with
// WindowModel::state. Plain C++ over core: no Qt, no VTK.
#pragma once

#include <string>
#include <vector>

#include "basis/basis_catalog.h"
#include "basis/basis_explorer.h"
#include "display/flow_display.h"
#include "engine/engine.h"
#include "flow/plane_scene.h"
#include "state/source_choice.h"

namespace oflab {

// How the animation view shows the engine's frame and the exact one; kComparison plays
// several reuse policies at once beside the exact frame (session/player/policy_comparison.h).
enum class PanelDisplay { kSideBySide, kDifference, kBlink, kComparison };
// "side-by-side", "difference", "blink", "comparison"
const char* panel_display_name(PanelDisplay display);
bool parse_panel_display(const std::string& text, PanelDisplay* display);
// The names of every display joined by `separator`, for help texts and error messages.
std::string panel_display_names(const std::string& separator = ", ");

// Where the world view's camera looks from: kOrbit frames the whole world from beside the
// eye (the mouse orbits it; "Reset view"), kEye looks through the eye with the camera's
// field of view ("View from the camera").
enum class WorldCamera { kOrbit, kEye };
// "orbit", "eye"
const char* world_camera_name(WorldCamera camera);
bool parse_world_camera(const std::string& text, WorldCamera* camera);

// How the animation view frames its panels, one framing shared by every panel so the
// approximations and the exact picture stay comparable: the plane's or scene's whole loop, or
// what is drawn around the frame shown (its exact outlines over kFramingFrames frames either
// side), so a small or far plane fills its panel; auto is the second in presentation mode and
// the first otherwise. Display only: no measured error depends on it.
enum class PanelFraming { kAuto, kLoop, kContent };
// "auto", "loop", "content"
const char* panel_framing_name(PanelFraming framing);
bool parse_panel_framing(const std::string& text, PanelFraming* framing);
// The names of every framing joined by `separator`, for help texts and error messages.
std::string panel_framing_names(const std::string& separator = ", ");
// Whether `framing` frames what is drawn now (content) in presentation mode `presentation`.
inline bool frames_content(PanelFraming framing, bool presentation) {
  return framing == PanelFraming::kContent || (framing == PanelFraming::kAuto && presentation);
}
// Frames either side of the frame shown whose exact outlines content framing holds: a sixth
// of a second at 30 frames per second, so the framing follows the motion smoothly.
constexpr int kFramingFrames = 5;

// The most policies the comparison layout plays at once.
constexpr int kMaxComparedPolicies = 4;

struct WindowState {
  // The view in front, by its name in the view table (gui/app/view_table.h).
  std::string view = "flow";
  FlowDisplay flow;  // the flow view's part and drawing options
  BasisKind basis = BasisKind::kPlanar;
  bool basis_playing = false;  // the gallery animates its deformation amount
  // The basis view shows the explorer (session/basis/basis_explorer.h) with these eight values
  // on its sliders, each within its term's limit.
  bool basis_explorer = false;
  ExplorerTerms explorer_terms = default_explorer_terms();

  // The scene panel's plane at frame 0, the motion script it plays (a shipped name or a
  // file; empty for the plane's own constant motion) and its texture file (empty for the
  // default butterfly).
  PlaneScene plane = default_demo_scene();
  std::string script;
  std::string texture;
  // What the animation and analysis views play (session/player/animation_sources.h), and how.
  SourceChoice source;
  EngineSettings settings;
  // The animation view: its layout, the policies its comparison plays (1 ..
  // kMaxComparedPolicies distinct registry names, in panel order), who draws its exact panel
  // (gui/adapters/exact_frames.h), how the panels are framed and the zoom on top of that
  // framing (limits::kZoom).
  PanelDisplay display = PanelDisplay::kSideBySide;
  std::vector<std::string> compared = {"affine", "perspective"};
  std::string exact_renderer = "core";
  PanelFraming framing = PanelFraming::kAuto;
  double zoom = 1.0;

  bool presentation = false;  // large text and thick lines for a projector
  bool scene_panel = true;    // the scene panel (plane, motion, camera) is shown
  // The cause-and-effect layout: the world view (the cause) beside the flow view (the
  // effect) instead of the tabs.
  bool cause_and_effect = false;
  WorldCamera world_camera = WorldCamera::kOrbit;  // where the world view looks from
  int play_rate = 30;    // live play, frames per second (limits::kPlayRate)
  bool playing = false;  // the scene's motion plays
  int frame = 0;         // the frame shown (limits::kFrameCount)
  // The lesson whose narrative shows above the views (session/lessons/lessons.h); empty for none.
  std::string lesson;
  // The lesson's step on screen: 0 for its narrative, k for its k-th step (whose text is the
  // caption then); 0 without a lesson.
  int lesson_step = 0;
  // The threshold study's window (manual/study.md): open on its set-up page with this shipped
  // study (datasets/studies/) chosen when the value changes to it; empty: closed when the
  // value changes to empty. A window opened from the Study menu is not in the state.
  std::string study_open;
  // The reuse thresholds, when this state is applied, become the threshold the study window
  // measured last (its "Use X px"), when it has results; the state's own thresholds otherwise
  // (and on a front-end without a study window: `oflab-cli lesson`).
  bool study_use_threshold = false;
};

// `names` joined by `separator`, for messages and help texts: "flow, basis, animation".
inline std::string joined_names(const std::vector<std::string>& names,
                                const std::string& separator = ", ") {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : separator) + name;
  return text;
}

// Field by field over the field table (state/state_fields.h), numbers exactly (a saved
// state reads back bit for bit).
bool operator==(const WindowState& a, const WindowState& b);
inline bool operator!=(const WindowState& a, const WindowState& b) { return !(a == b); }

// "" when every bounded number of `state` is within its limit (core/flow/limits.h) and
// the compared list names 1 .. kMaxComparedPolicies distinct registry policies, and, for
// the plane source, a given stabilization plane passes at least 0.01 u from the eye and meets
// the optical axis in front of it (or is parallel to it); otherwise one phrase naming the field as
// a session file spells it, the value and the allowed range or names: "animation.thresholds: 1e+06
// is outside 0..100 px". The view name, the source kind, the exact renderer, the lesson and the
// files the state names are checked where they are known (the view table, the source-kind and
// renderer tables, the lesson catalogue, the file system: WindowModel::apply); a study.open
// that names no shipped study is refused here ("study.open: unknown study 'x' (one of class,
// lesson, reuse-threshold)"). Plain C++ over core and the datasets folder.
std::string window_state_problem(const WindowState& state);

// The parts of window_state_problem that the scene and animation models check themselves
// on every edit: the plane's limits and plane_scene_problem ("plane..." fields), and the
// engine settings' limits ("animation..." fields). "" when accepted.
std::string plane_state_problem(const PlaneScene& plane);
std::string settings_state_problem(const EngineSettings& settings);

}  // namespace oflab
