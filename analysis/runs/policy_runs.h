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
#include "runs/statistics.h"  // nearest_rank_percentile

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
//                    (frames over budget, starved layer-frames, mean optimality gap);
//   pixels_written   RunSummary's total over the frames, and the 95th percentile and the
//                    largest of the per-frame pixels written (AnimationFrame::pixels_written)
//                    over frames 1 .. n-1: frame 0 renders every layer under every policy,
//                    so it is left out of the peaks (0 for a run of one frame).
// Predicted against actual expiry (core/engine/lookahead.h ExpiryOutcome), over the lives of
// every layer of a run: lives the rule ended (by_rule; with a prediction, a pair of `pairs`:
// layer, predicted and actual frame), lives the schedule ended early, and lives ended
// otherwise (refusals, the sampling limit, clipped or hidden frames); the median and largest
// |predicted - actual| over the pairs, frames (NaN without pairs), and the exact pairs.
struct ExpiryPair {
  int layer = 0;
  int predicted = -1;
  int actual = -1;
};
struct ExpiryTable {
  std::vector<ExpiryPair> pairs;
  long by_rule = 0, early = 0, other = 0, unpredicted = 0;
  long exact = 0;
  double median_error_frames = std::numeric_limits<double>::quiet_NaN();
  double max_error_frames = std::numeric_limits<double>::quiet_NaN();
};
// The table of `run`'s layer reports (every policy of the threshold rule fills them).
ExpiryTable expiry_table(const AnimationRun& run);

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
  std::int64_t hole_pixels = 0;         // RunSummary's total (0 for a policy without holes)
  std::int64_t inpainted_pixels = 0;    // RunSummary's total (mv-extrapolation's fills)
  int latency_frames = 0;               // the policy's at the run's cadence (latency_frames)
  std::int64_t pixels_written = 0;      // RunSummary::pixels, over every frame
  std::int64_t pixels_written_p95 = 0;  // nearest-rank 95th percentile per frame, frame 0 out
  std::int64_t pixels_written_max = 0;  // the largest per frame, frame 0 out
  // Of the pixels written, those the warp kernels computed (AnimationFrame::pixels_not_warped:
  // fewer under a visible-only warp), over every frame and its per-frame p95, frame 0 out.
  std::int64_t pixels_warped = 0;
  std::int64_t pixels_warped_p95 = 0;
  NodeCacheTotals cache;  // RunSummary's (the hierarchical-cache policy only)
  // `lookahead` only (ReusePolicy::spreads_updates): its predicted against actual expiries.
  bool predicts = false;
  ExpiryTable expiry;
};
PolicyRow policy_row(const PolicyRun& run);

// The row as JSON: {"name", "levels": {level name: percent}, "rerender_share" (fraction),
// "work_saved", "time_saved", "model_work_saved" (fractions), "max_measured_error_px",
// "mean_measured_error_px", "mean_psnr_db", "mean_ssim" (null when NaN), "layer_frames",
// "frames", "hole_pixels" and "inpainted_pixels" (totals over the frames), "latency_frames",
// "pixels_written" (total), "pixels_written_p95" and "pixels_written_max" (per frame),
// "pixels_warped" (total) and "pixels_warped_p95" (per frame), for
// `lookahead` "expiry": {"by_rule", "early", "other", "unpredicted", "exact",
// "median_error_frames", "max_error_frames" (null without pairs), "layers": [{"layer",
// "predicted": [frames], "actual": [frames]}]}, for
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
