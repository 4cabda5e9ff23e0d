// Rival reuse policies side by side (beyond the dissertation; manual/policies.md): every
// Experiment 1 script and the four cubes under the compound viewer script played under every
// policy of the registry (core/engine/reuse_policy.h) through analysis/runs/policy_runs.h,
// the `dissertation` rows (Algorithm 1 as printed) beside the published tables with a
// reading of how much of each published-vs-oflab gap the printed rule explains, and a chart
// of measured error against work saved.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "experiments/experiments.h"
#include "runs/policy_runs.h"

namespace oflab {

struct PoliciesSpec {
  int max_frames = -1;                          // per script and for the scene (-1: whole scripts)
  int repetitions = kDefaultTimingRepetitions;  // timed passes after a warm-up
};
// Full: whole scripts, kDefaultTimingRepetitions (as `oflab-cli compare`, which therefore
// reproduces a row up to noise); quick: 40 frames, 1 repetition.
PoliciesSpec policies_spec(bool quick);

struct PoliciesSource {
  std::string name;  // the script ("loop"), or "four-cubes" for the scene
  bool scene = false;
  std::vector<PolicyRun> runs;  // one per registry policy, in registry order
};

// The budget policy on the four cubes at one pixel budget per frame.
struct BudgetRun {
  double budget_pixels = 0.0;
  PolicyRun run;
};
// The pixel budgets per frame of the four cubes' budget runs: about 1 %, 4 % and 16 % of
// the 640 x 480 frame's pixels.
constexpr double kFourCubesBudgets[] = {3000.0, 12000.0, 48000.0};

struct PoliciesResult {
  PoliciesSpec spec;
  std::vector<PoliciesSource> sources;  // the Experiment 1 scripts, then four-cubes
  std::vector<BudgetRun> budgets;       // four-cubes under `budget`, one per kFourCubesBudgets
};

PoliciesResult run_policies_experiment(const Layer& texture, const PoliciesSpec& spec,
                                       const std::function<void(const std::string&)>& progress);

// Percent of layer-frames per level as the published tables count them: a plane's frames
// after the first (frame 0 is the initial render), a scene's drawn polygons over all frames.
std::array<double, kLevelCount> published_style_levels(const PoliciesSource& source,
                                                       const PolicyRun& run);

// How much of the distance between the published level mix and oflab's corrected rule
// (`perspective`) the printed rule (`dissertation`) removes. Distances are total variation,
// half the sum over levels of |published - measured|, in percentage points; the fraction is
// (d_perspective - d_dissertation) / d_perspective (NaN when d_perspective is 0): 1 means
// the rule explains the whole gap, 0 none of it, negative that the printed rule is further.
struct GapAttribution {
  double corrected_points = 0.0;  // d_perspective
  double printed_points = 0.0;    // d_dissertation
  double explained = 0.0;         // the fraction above
};
GapAttribution attribute_gap(const std::array<double, kLevelCount>& published,
                             const std::array<double, kLevelCount>& corrected,
                             const std::array<double, kLevelCount>& printed);

ReportSection policies_section(const PoliciesResult& result, ExperimentContext& context);

}  // namespace oflab
