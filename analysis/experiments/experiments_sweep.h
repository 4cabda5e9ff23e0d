// Threshold sweep (beyond the dissertation; its section 7.5.1 asks how the thresholds
// should be chosen): every Experiment 1 script in perspective mode with all four
// thresholds set to one value from 0.25 to 4 px, time saved against the re-render
// baseline of the same run and the error actually measured (largest corner distance from
// the exact projection, PSNR against an exact render).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "experiments/experiments.h"
#include "experiments/experiments_runs.h"

namespace oflab {

struct SweepSpec {
  std::vector<double> thresholds_px;
  RunSpec run;
};
// Full: 0.25, 0.5, 1, 2, 4 px, whole scripts, 5 repetitions; quick: 0.25, 1, 4 px,
// 40 frames, 1 repetition. PSNR in both.
SweepSpec sweep_spec(bool quick);

struct SweepScript {
  std::string script;
  MeasuredRun baseline;           // re-render
  std::vector<MeasuredRun> runs;  // one per threshold, same order as the spec
};

struct SweepResult {
  SweepSpec spec;
  std::vector<SweepScript> scripts;
};

SweepResult run_threshold_sweep(const Layer& texture, const SweepSpec& spec,
                                const std::function<void(const std::string&)>& progress);

ReportSection sweep_section(const SweepResult& result, ExperimentContext& context);

}  // namespace oflab
