// `oflab-cli animate --scene NAME|FILE --script NAME|FILE`: a viewer script through a scene
// of many polygons (Experiment 2), with the exact re-render and, on request, the VTK
// renderer timed in the same run (manual/scenes.md).
#pragma once

#include <iosfwd>
#include <nlohmann/json.hpp>

#include "cli/cli_args.h"
#include "runs/source_kinds.h"
#include "scene/scene_animator.h"

namespace oflab {

// Runs the scene form of animate. Returns the exit code: 0, 2 for bad input (one line on
// `err` naming the option or the file, polygon and field), 1 when the VTK renderer cannot
// start. Throws UsageError for bad options (the caller prints it).
int animate_scene(const CliArgs& args, std::ostream& out, std::ostream& err);

// The scene settings of the options: the engine's (read_engine_settings), --near,
// --guard-band (0..16 image sizes), --no-skip-hidden and --warp visible|whole (what of each
// layer is warped, EngineSettings::warp_area). Throws UsageError naming the option.
SceneSettings read_scene_settings(const CliArgs& args);

// The run source of --scene NAME|FILE and --script NAME|FILE with the settings of the options
// (read_scene_settings), the polygons at the scene's content_quality unless --quality gives
// one. The one reading of a scene run that `animate` and `compare` share, so the same options
// give the same run. Throws UsageError naming the option, SceneFileError / ScriptError for
// bad files.
RunSource read_scene_source(const CliArgs& args);

// The JSON of `animate --scene ... --json` (and its --out DIR/summary.json): the scene kind's
// summary of `run` (analysis/runs/source_kinds.h) with the scene's and viewer script's names,
// the mode, thresholds and skip_hidden, and for a policy with holes its cadence, latency and
// hole fill. `source` is the run's (read_scene_source); the Python module returns it too.
nlohmann::json scene_animate_json(const RunSource& source, const AnimationRun& run);

}  // namespace oflab
