// Experiment 1 (dissertation sections 6.4 and 6.5): one textured plane, fixed viewer, the
// seven shipped scripts, in perspective, affine and exact mode, each against the
// re-render baseline measured in the same run.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "experiments/experiments.h"
#include "experiments/experiments_runs.h"

namespace oflab {

// The seven scripts in the dissertation's order (section 6.4.8's table).
const std::vector<std::string>& experiment1_scripts();

// The reuse policies Experiment 1 compares, in report order: perspective, affine, exact.
const std::vector<const ReusePolicy*>& experiment1_modes();

struct Experiment1Script {
  std::string script;
  MeasuredRun baseline;            // mode re-render, same frames, same repetitions
  std::vector<MeasuredRun> modes;  // one per experiment1_modes(), same order
  // The run of the policy named `policy`; throws std::logic_error when there is none.
  const MeasuredRun& mode(const std::string& policy) const;
};

struct Experiment1Result {
  RunSpec spec;
  std::vector<Experiment1Script> scripts;
};

// The full run: whole scripts, 15 repetitions, PSNR; quick: at most 60 frames per script,
// 2 repetitions, PSNR.
RunSpec experiment1_spec(bool quick);

// Plays every script in every mode (thresholds 1 px, Delta as the dissertation, nearest
// sampling) and the re-render baseline, interleaved. `progress` may be empty.
Experiment1Result run_experiment1(const Layer& texture, const RunSpec& spec,
                                  const std::function<void(const std::string&)>& progress);

// Frame rate of the videos of write_experiment1_videos, frames per second.
constexpr int kExperiment1VideoFps = 30;

// Plays every script of Experiment 1 once more in each of its modes (the spec's frames, no
// timing) and writes the frames the engine showed as DIR/videos/exp1-SCRIPT-MODE.EXT at
// kExperiment1VideoFps, in the context's video format (formats/video_file.h), overwriting earlier
// videos of the same names. Returns the paths relative to DIR, in script and mode order.
// Precondition: context.video_format() is not empty. Throws VideoFileError naming a file
// that cannot be written.
std::vector<std::string> write_experiment1_videos(ExperimentContext& context, const RunSpec& spec);

// The report section: the comparison table with one reading per oflab row, the cost of
// each level, and per script and mode a chart of frame time and level per frame.
ReportSection experiment1_section(const Experiment1Result& result, ExperimentContext& context);

}  // namespace oflab
