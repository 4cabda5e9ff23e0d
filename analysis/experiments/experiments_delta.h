// The Delta comparison (dissertation section 6.3, Fig. 20): the loop script in perspective
// mode under each DeltaPolicy (core/flow/decomposition.h), frame time per frame and image
// quality (PSNR against an exact render). Delta sets the scale of the cached perspective
// warp: 1 keeps the cache at texture size, sqrt|det A| at output size, |det A| below it
// (the affine step then magnifies it back); see manual/theory.md.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "experiments/experiments.h"
#include "experiments/experiments_runs.h"
#include "flow/decomposition.h"

namespace oflab {

struct DeltaResult {
  RunSpec spec;
  MeasuredRun baseline;           // re-render, same frames
  std::vector<MeasuredRun> runs;  // one per delta_policies(), same order
};

// Full: the whole loop (629 frames), 9 repetitions; quick: 150 frames, 1 repetition. PSNR
// in both.
RunSpec delta_spec(bool quick);

DeltaResult run_delta_comparison(const Layer& texture, const RunSpec& spec,
                                 const std::function<void(const std::string&)>& progress);

ReportSection delta_section(const DeltaResult& result, ExperimentContext& context);

}  // namespace oflab
