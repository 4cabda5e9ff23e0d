// The command line of oflab:
//   oflab [--session FILE] [--lesson NAME] [--scene S] [--script T] [--source KIND] [--mode M]
//         [--compare P1,P2,...] [--view NAME] [--animation-show LAYOUT]
//         [--animation-exact RENDERER]
//         [--screenshot FILE --frames N] [--benchmark N] [--size W H]
//         [--flow-show PART] [--flow-draw LIST] [--basis NAME] [--presentation] [--help]
// Plain C++ over analysis/cli/cli_args.h, so it is checked before any window opens and bad
// input never needs a display.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "adapters/flow_display.h"
#include "cli/cli_args.h"
#include "engine/engine.h"
#include "engine/script.h"
#include "formats/session_file.h"
#include "views/basis_catalog.h"

namespace oflab {

struct LaunchOptions {
  // --session FILE: a saved session (analysis/formats/session_file.h), read and checked here;
  // the files it names are checked when the window applies it, before the other options.
  std::optional<Session> session;
  std::string lesson;      // a lesson preset name (gui/app/lessons.h), empty for the demo
  std::string view;        // view in front and the one captured; "window" = whole window
  std::string screenshot;  // PNG path; when set, play `frames` frames, save, exit
  int frames = 0;          // frames to play before the screenshot (>= 0)
  // --whole-window: the screenshot is of the whole window, with `view` in front.
  bool whole_window = false;
  int benchmark = 0;  // frames of the flow view to render as fast as possible (> 0)
  int width = 1280;   // window size in pixels
  int height = 800;
  // Overrides applied after the lesson: the flow part shown, what the flow view draws
  // (only the booleans of `flow_draw` are used), the gallery's basis.
  std::optional<FlowPart> flow_part;
  std::optional<FlowDisplay> flow_draw;
  std::optional<BasisKind> basis;
  // --script NAME|FILE: a shipped script name or a script file, read and checked. With
  // --scene it names a viewer script instead (default "circle"), kept in viewer_script.
  std::optional<MotionScript> script;
  std::string script_name;
  // --scene NAME|FILE: a multi-plane scene for the animation and analysis views, checked.
  std::string scene;
  std::string viewer_script;
  // --source KIND: how the scene plays, a source kind with a viewer script
  // (gui/models/animation_sources.h): "scene" (the default) or "scene-shifting".
  std::string source_kind = "scene";
  // --mode NAME: the animation engine's reuse policy (core/engine/reuse_policy.h); null
  // when not given.
  const ReusePolicy* mode = nullptr;
  // --animation-show side-by-side|difference|blink|comparison: how the animation view shows its
  // panels.
  std::string animation_show;
  // --compare P1,P2,...: the policies of the comparison layout (1 .. kMaxComparedPolicies
  // distinct names of the registry); empty when not given.
  std::vector<const ReusePolicy*> compared;
  // --animation-exact NAME: who draws the animation view's exact panel, an entry of
  // gui/adapters/exact_frames.h exact_renderers() ("core" or "vtk"); empty when not given.
  std::string animation_exact;
  bool presentation = false;  // start in presentation mode
  bool help = false;          // --help: print the usage and exit 0
};

// The view names a screenshot can capture, in order: the view table's
// (gui/app/view_table.h), then "window".
const std::vector<std::string>& screenshot_view_names();

// Parses the arguments after the program name. Throws UsageError with one line naming
// the option for: unknown options or values, a missing value, --frames without
// --screenshot, --screenshot with --benchmark, a size outside 320..8192, a negative frame
// count, a non-positive benchmark count, a script that is neither a file nor a shipped name
// or that analysis/formats/script_file.h rejects (the message names the file and field), a scene
// or viewer script that is neither a file nor a shipped name or that its reader rejects,
// a session file that analysis/formats/session_file.h rejects, an unknown --mode or
// --animation-exact, a --compare list that is empty, longer than kMaxComparedPolicies,
// repeats a policy or names an unknown one, and a --source that is not a kind with a viewer
// script or comes without --scene.
LaunchOptions parse_launch_options(const std::vector<std::string>& args);

// The flow view's display with the options' overrides applied.
FlowDisplay with_overrides(FlowDisplay display, const LaunchOptions& options);

// Usage text, a few lines.
std::string launch_usage();

}  // namespace oflab
