// When reuse pays (beyond the dissertation; its sections 6.4.8 and 7 say its savings were
// conservative because a bitmap is cheap to re-render): every Experiment 1 script and the
// street scene with contents (core/content/layer_content.h) whose re-render costs from one
// perspective warp (the texture) through tens (the facade impostor) to hundreds (the shaded
// brick, per sample) of warps per pixel, under several reuse policies (the corrected rule
// `perspective`, `affine`, the printed rule `dissertation`, `talisman`), time saved measured
// against the re-render of the same content in the same run and the cost model's work saved
// (analysis/runs/run_driver.h model_work_saved); the break-even cost at which reuse starts to
// pay, per script and policy; the published time saved beside the first cost of at least ten
// warps; and what the printed rule's choices (zoom's published flow_3 among them) cost in
// error beside the corrected rule's at that cost.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "experiments/experiments.h"
#include "runs/run_driver.h"

namespace oflab {

struct CostSweepSpec {
  // The contents, in increasing cost (quality: detail or samples per pixel).
  std::vector<LayerContent> contents;
  int max_frames = -1;     // per Experiment 1 script (-1: whole scripts)
  int street_frames = -1;  // of the walk through the street (-1: all)
  int repetitions = 1;     // timed passes after a warm-up
  // Reuse policies by registry name (core/engine/reuse_policy.h), each swept in turn.
  std::vector<std::string> policies;
};
// The policy of the printed rule and of the corrected one (the printed-choice table).
constexpr const char* kPrintedPolicy = "dissertation";
constexpr const char* kCorrectedPolicy = "perspective";

// Full: texture, impostor detail 1 and 3, shaded 1 and 2 samples; 150 frames per script,
// the walk's first 60 frames, 1 repetition; policies perspective, affine, dissertation,
// talisman. Quick: texture, impostor 1, shaded 1; 12 frames, 4 street frames; policies
// perspective and dissertation.
CostSweepSpec cost_sweep_spec(bool quick);

struct CostPoint {
  LayerContent content;
  // Re-render cost per pixel in perspective-warp pixels: the cost model's work of the run's
  // re-render baseline over the pixels it wrote.
  double render_cost = 0.0;
  RunSummary summary;  // time_saved, model_work_saved, errors, of the run
};

struct CostScript {
  std::string script;             // an Experiment 1 script, or "street/walk"
  std::string policy;             // the reuse policy's registry name
  std::vector<CostPoint> points;  // one per content, in order
};

struct CostSweepResult {
  CostSweepSpec spec;
  // Per policy of the spec (in its order), every Experiment 1 script then the street.
  std::vector<CostScript> scripts;
};

// The sweep of `script` under `policy`, or nullptr when the result has none.
const CostScript* find_cost_script(const CostSweepResult& result, const std::string& script,
                                   const std::string& policy);

// The index of the first point whose re-render costs at least `cost` warp pixels per
// pixel, or -1 when none does.
int first_point_costing(const CostScript& script, double cost);

// Break-even per script (rows, in sweep order) and policy (columns, in the spec's order):
// the break_even_cost of each, as text ("pays already", "4.8", "never").
ReportTable break_even_table(const CostSweepResult& result);

// The printed rule beside the corrected one at the first content costing at least ten
// warps: per Experiment 1 script with both policies swept, the published time saved, and
// for kCorrectedPolicy and kPrintedPolicy the content, time saved and largest measured
// error in pixels. What a published figure resting on the printed rule's choice (zoom's
// flow_3) costs in error.
ReportTable printed_choice_table(const CostSweepResult& result);

// The re-render cost at which time saved crosses zero, by linear interpolation between the
// sweep's points: 0 when reuse already pays at the first point, NaN when it never does.
double break_even_cost(const CostScript& script);

// "texture", "impostor 3", "shaded 2 spp".
std::string content_label(const LayerContent& content);

// Runs the sweep; `progress` (may be empty) gets a line per script and content. Throws
// ScriptError, SceneError or std::runtime_error for a missing shipped file.
CostSweepResult run_cost_sweep(const Layer& texture, const CostSweepSpec& spec,
                               const std::function<void(const std::string&)>& progress);

ReportSection cost_sweep_section(const CostSweepResult& result, ExperimentContext& context);

}  // namespace oflab
