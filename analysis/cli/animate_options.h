// Options shared by both forms of `oflab-cli animate` (one plane, analysis/cli/animate_command.cpp;
// a scene, analysis/cli/animate_scene.cpp).
#pragma once

#include <fstream>
#include <functional>
#include <iosfwd>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli/cli_args.h"
#include "engine/engine.h"
#include "formats/atomic_file.h"
#include "formats/video_file.h"
#include "formats/vtk_export.h"
#include "image/image.h"
#include "runs/policy_runs.h"
#include "runs/source_kinds.h"
#include "scene/scene.h"
#include "scene/viewer_script.h"

namespace oflab {

// --mode (a reuse policy of core/engine/reuse_policy.h; a mode that selects a source kind,
// analysis/runs/source_kinds.h, is handled before),
// --threshold / --thresholds (pixels, limits::kThreshold), --delta, --sampling, --content
// texture|shaded|impostor, --quality N (its samples per pixel or detail,
// limits::kContentQuality) and the frame budget (read_frame_budget), which needs --mode
// budget unless the command takes --policies. Throws UsageError naming the option and the
// accepted values or range for a bad value.
EngineSettings read_engine_settings(const CliArgs& args);

// The single-plane source of the options: the motion script of --script (a shipped name or
// a file; required), the texture of --texture (default: the shipped butterfly) and the
// engine settings (read_engine_settings); plays the script once. Throws UsageError naming
// the option for an unknown --script name or a bad option, ScriptError for a broken script
// file and ImageFileError for an unreadable texture.
RunSource read_plane_source(const CliArgs& args);

// --repeat N (default 1): within limits::kRepeat, and N times the script's frames fits an
// int. Throws UsageError naming --repeat, the value as typed and the limit.
int read_repeat(const CliArgs& args, const MotionScript& script);

// The options both `oflab-cli animate` and `compare` accept, name (with "--") -> number of
// values: the source (--script, --scene, --texture, --frames), the engine's and the scene's
// settings (read_engine_settings, read_scene_settings) and the output (--out, --force,
// --json, --quiet, --repeat-timing).
const std::map<std::string, int>& run_options();

// The options `oflab-cli animate` accepts (run_options and its own): the one table of its
// CliArgs, which the Python module reads too (manual/python.md).
const std::map<std::string, int>& animate_options();

// The JSON of `animate --script ... --json` for a single plane: the plane kind's summary of
// `run` (analysis/runs/source_kinds.h) with the script's name (its file's "name", else
// `script_arg` as given), the mode, Delta, thresholds, content and quality, and for a
// policy with holes its cadence and latency. `source` is the run's (read_plane_source).
nlohmann::json plane_animate_json(const RunSource& source, const AnimationRun& run,
                                  const std::string& script_arg);

// What `oflab-cli animate` plays for its options, in its plane and scene forms (scene
// shifting, selected by --mode scene-shifting, is refused here: only the command plays it):
// the kind (analysis/runs/source_kinds.h), the source (read_plane_source with --repeat, or
// the scene's read_scene_source) and --script as given. Every refusal of those forms is
// made (scene options without --scene, --repeat with --scene, a policy that needs a scene).
// Throws UsageError naming the option, and the readers' errors (ScriptError, SceneError,
// ViewerScriptError, ImageFileError) for broken files.
struct AnimateInputs {
  const SourceKind* kind = nullptr;
  RunSource source;
  std::string script_arg;
};
AnimateInputs read_animate_inputs(const CliArgs& args);
// `animate --json`'s object for a run of `inputs`: plane_animate_json or, for a scene,
// scene_animate_json (analysis/cli/animate_scene.h).
nlohmann::json animate_json(const AnimateInputs& inputs, const AnimationRun& run);

// `oflab-cli compare`'s reading of its options (analysis/cli/compare_command.cpp): the
// source's kind (plane, or scene with --scene), the source as animate reads it, and the
// policies of --policies, every refusal of compare made (a policy that needs a scene, an
// option no compared policy reads, a frame budget without `budget`). Throws UsageError
// naming the option, and the readers' errors for broken files.
struct CompareInputs {
  const SourceKind* kind = nullptr;
  RunSource source;
  std::vector<const ReusePolicy*> policies;
};
CompareInputs read_compare_inputs(const CliArgs& args);
// The options `oflab-cli compare` accepts: run_options and --policies (as animate_options).
const std::map<std::string, int>& compare_options();
// The JSON of `compare --json`: {"script", "scene" (with a scene), "thresholds",
// "policies": a policy_row_json per row} (analysis/runs/policy_runs.h).
nlohmann::json compare_json(const CompareInputs& inputs, const std::vector<PolicyRow>& rows);
// What a comparison measures beyond a run's own (every row's mean SSIM against the exact
// frames: PlayOptions::measure_ssim), set on `options`; `oflab-cli compare` and the Python
// module's compare both call it, so their rows are the same.
void add_compare_measures(PlayOptions& options);

// --budget-pixels N (pixels written per frame, limits::kBudgetPixels) or --budget-ms T
// (milliseconds per frame, limits::kBudgetMs, converted with the run's measured cost per
// pixel of each level, core/engine/budget.h), at most one of them;
// FrameBudget::Unit::kNone with neither. Throws UsageError naming the option for a bad
// value or when both are given.
FrameBudget read_frame_budget(const CliArgs& args);

// --sampling nearest|bilinear|mipmap (default nearest). Throws UsageError naming the option and the
// accepted values for any other word.
Sampling read_sampling(const CliArgs& args);

// What every form of `oflab-cli animate` does with its output and timing options: --frames N
// (at most N frames, limits::kPlayedFrames; -1 for all when not given), --repeat-timing N (timed
// passes after an untimed warm-up, limits::kTimingPasses, default kDefaultTimingRepetitions,
// or 1 when --repeat is given, so that a long run streams its records;
// analysis/runs/run_driver.h),
// --no-warm-up (the timed passes only), --out DIR (a new or empty DIR; --force for a
// non-empty one, which is then replaced whole; written whole or not at all: the files go
// into a temporary directory beside DIR, formats/atomic_file.h, renamed into place by
// write_summary; DIR/frames.csv is written row by row as the run plays, so a long run keeps
// no per-frame records, and DIR/summary.json after it), --frames-png
// (each frame as DIR/frame_NNNNN.png; needs --out), --video FILE (the frames as an MP4, GIF
// or Ogg Theora video by FILE's extension, formats/video_file.h, written through a
// temporary file renamed over FILE by finish(); an existing FILE needs --force) at --fps N
// (default 30), --vtk-series DIR (each frame's shown, exact and difference images and its
// layers' outlines as ParaView data with a .pvd series of each, formats/vtk_export.h; DIR
// written whole like --out's, replacing a non-empty one only with --force, completed by
// finish()) and --quiet (no progress lines; otherwise runs of 200 frames or more report
// every tenth on `err`). Every refusal of these options comes before anything is created.
// Throws UsageError naming the option; a write that fails during the run throws
// FileWriteError naming the file. `err` must outlive the returned callbacks.
constexpr int kMaxTimingRepetitions = static_cast<int>(limits::kTimingPasses.maximum);

struct RunOutput {
  int max_frames = -1;
  int timing_repetitions = kDefaultTimingRepetitions;
  bool warm_up = true;                 // false with --no-warm-up
  std::string dir;                     // --out DIR as given; empty without --out
  std::shared_ptr<AtomicDir> out;      // where DIR's files go until write_summary
  std::shared_ptr<std::ofstream> csv;  // DIR/frames.csv (opened by apply_to), empty without --out
  std::function<void(int, const Image&)> on_frame;  // empty without --frames-png and --video
  std::function<void(int, int)> progress;
  std::shared_ptr<VideoWriter> video;           // empty without --video
  std::string vtk_series_dir;                   // --vtk-series DIR as given; empty without it
  std::shared_ptr<AtomicDir> vtk_series_out;    // where its files go until finish()
  std::shared_ptr<VtkSeriesWriter> vtk_series;  // empty without --vtk-series

  // Completes the --video file and the --vtk-series directory after the run (nothing
  // without them). Throws UsageError naming --video when the video cannot be completed,
  // FileWriteError naming the file of the series that cannot be written.
  void finish() const;

  // Sets max_frames, the timing (warm-up, timing_repetitions timed passes), on_frame,
  // progress and the records of a run's options: the run keeps no frames, and with --out
  // each frame's row of `kind`'s CSV goes into DIR/frames.csv as the run hands it on.
  void apply_to(RunOptions& options, const SourceKind& kind) const;
  // Only max_frames, the timing and progress (the run keeps its frames; no CSV, no images):
  // for commands that write their own outputs from the returned run.
  void apply_timing_to(RunOptions& options) const;

  // Writes DIR/summary.json (`summary`), completes DIR/frames.csv and renames the directory
  // into place after the run (nothing without --out). Throws FileWriteError naming the file
  // when any of them cannot be written; DIR is then as it was.
  void write_summary(const nlohmann::json& summary) const;
};
RunOutput read_run_output(const CliArgs& args, std::ostream& err);

// The scene forms of `oflab-cli animate` (analysis/cli/animate_scene.cpp,
// analysis/cli/animate_scene_shifting.cpp).
//
// Runs `body`, the whole of a scene form, and turns the errors of reading its inputs (the
// scene, the viewer script, image files, a scene the core rejects) into a message on `err`
// naming the option, returning exit status 2. Other exceptions pass through. `command`
// names the command in the message ("oflab-cli COMMAND: ...").
int report_scene_input_errors(const std::function<int()>& body, std::ostream& err,
                              const char* command = "animate");

// The scene of --scene: a shipped scene name, a scene file or a Wavefront OBJ file (with
// the tile texture, analysis/formats/obj_scene.h); --texture, when given, replaces every texture.
// Throws UsageError for an unknown name or unreadable --texture, and the readers' errors
// (SceneError, ImageFileError) for a broken file.
Scene read_scene_option(const CliArgs& a);

// The viewer script of --script (required): a shipped name or a file. Throws UsageError
// when missing or unknown, ViewerScriptError for a broken file.
ViewerScript read_viewer_script_option(const CliArgs& a);

}  // namespace oflab
