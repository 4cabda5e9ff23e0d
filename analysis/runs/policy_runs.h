// One source played under several reuse policies (core/engine/reuse_policy.h), each run
// exactly as `oflab-cli animate` plays it (warm-up, timed passes interleaved with the exact
// re-render, medians: analysis/runs/run_driver.h), so that the policies' rows compare like
// with like. Used by `oflab-cli compare` and `oflab-cli experiments --only policies`; the
// rows are documented in manual/policies.md.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/reuse_policy.h"
#include "runs/source_kinds.h"

namespace oflab {

struct PolicyRun {
  const ReusePolicy* policy = nullptr;
  AnimationRun run;
  std::vector<ViewerPose> views;  // per frame, what the frame showed (RunOptions::on_view)
  int cadence = 2;                // the run's EngineSettings::cadence
};

// Plays `source` once per policy with the kind's play ("plane" or "scene": the policy goes
// into source.settings.engine.policy, nothing else changes). `options` as for
// SourceKind::play; its on_view is replaced. Throws what play throws.
std::vector<PolicyRun> run_policies(const SourceKind& kind, const RunSource& source,
                                    const std::vector<const ReusePolicy*>& policies,
                                    const PlayOptions& options);

// The policies of a comma-separated list of registry names ("perspective,talisman"), in the
// order given. Throws std::invalid_argument naming the unknown or repeated entry and the
// known names, or saying the list is empty.
std::vector<const ReusePolicy*> parse_policy_list(const std::string& text);

// The figures of one policy's row, over every layer-frame of the run (a layer-frame: one
// drawn layer in one frame; a plane has one per visible frame):
//   level_share[l]   fraction of the drawn layer-frames updated at level l;
//   work_saved, time_saved   RunSummary's (against the exact re-render of the same run);
//   max_measured_error_px, mean_measured_error_px   over the visible layer reports;
//   mean_psnr_db, mean_ssim   RunSummary's (SSIM NaN unless PlayOptions::measure_ssim);
//   max_measured_error_px also takes each frame's own largest error, so a frame warped as a
//                    whole (per-pixel policies: no layer reports) counts;
//   model_work_saved RunSummary's: the deterministic cost model's (core/engine/cost_model.h), as
//                    `animate` reports it for the same policy;
//   budget           a policy sharing a per-frame budget only: RunSummary's budget figures
//                    (frames over budget, starved layer-frames, mean optimality gap).
struct PolicyRow {
  std::string name;
  std::array<double, kLevelCount> level_share{};
  double work_saved = 0.0;
  double time_saved = 0.0;
  double model_work_saved = 0.0;
  bool budgeted = false;  // the policy shares a per-frame budget
  long frames_over_budget = 0;
  long starved_layer_frames = 0;
  long gap_frames = 0;
  double mean_optimality_gap = std::numeric_limits<double>::quiet_NaN();
  double max_measured_error_px = 0.0;
  double mean_measured_error_px = 0.0;
  double mean_psnr_db = 0.0;
  double mean_ssim = std::numeric_limits<double>::quiet_NaN();  // RunSummary's
  long layer_frames = 0;
  int frames = 0;
  std::int64_t hole_pixels = 0;       // RunSummary's total (0 for a policy without holes)
  std::int64_t inpainted_pixels = 0;  // RunSummary's total (mv-extrapolation's fills)
  int latency_frames = 0;             // the policy's at the run's cadence (latency_frames)
  NodeCacheTotals cache;              // RunSummary's (the hierarchical-cache policy only)
};
PolicyRow policy_row(const PolicyRun& run);

// The row as JSON: {"name", "levels": {level name: percent}, "rerender_share" (fraction),
// "work_saved", "time_saved", "model_work_saved" (fractions), "max_measured_error_px",
// "mean_measured_error_px", "mean_psnr_db", "mean_ssim" (null when NaN), "layer_frames",
// "frames", "hole_pixels" and "inpainted_pixels" (totals over the frames), "latency_frames"}, for
// the hierarchical cache "cache": node_cache_json (analysis/runs/run_driver.h), and for a budgeted
// row "budget": {"frames_over_budget", "starved_layer_frames", "gap_frames", "mean_optimality_gap"
// (fraction, null when no frame was checked)}.
nlohmann::json policy_row_json(const PolicyRow& row);

// A text table, one row per policy: the level percents, work, time and model work saved,
// max and mean measured error and mean PSNR; then a line per budgeted row with its frames
// over budget, starved layer-frames and mean optimality gap, and a line per hierarchical
// cache row with its nodes, node renders by cause, holes, overlaps and per-pixel error.
void print_policy_table(const std::vector<PolicyRow>& rows, std::ostream& out);

}  // namespace oflab
