// When reuse pays (beyond the dissertation; its sections 6.4.8 and 7 say its savings were
// conservative because a bitmap is cheap to re-render): every Experiment 1 script and the
// street scene with contents (core/content/layer_content.h) whose re-render costs from one
// perspective warp (the texture) through tens (the facade impostor) to hundreds (the shaded
// brick, per sample) of warps per pixel, perspective mode, time saved measured against the
// re-render of the same content in the same run and the cost model's work saved
// (analysis/runs/run_driver.h model_work_saved); the break-even cost at which reuse starts to pay,
// per script; the published time saved beside the first cost of at least ten warps.
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
};
// Full: texture, impostor detail 1 and 3, shaded 1 and 2 samples; 150 frames per script,
// the walk's first 60 frames, 1 repetition. Quick: texture, impostor 1, shaded 1; 12
// frames, 4 street frames.
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
  std::vector<CostPoint> points;  // one per content, in order
};

struct CostSweepResult {
  CostSweepSpec spec;
  std::vector<CostScript> scripts;
};

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
