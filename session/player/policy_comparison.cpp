#include "player/policy_comparison.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include "image/thread_pool.h"
#include "player/plane_panel.h"
#include "player/run_player.h"
#include "player/stage_times.h"
#include "scene/scene_resources.h"

namespace oflab {

ComparedFrame ComparedFrame::of(const AnimationFrame& record) {
  ComparedFrame f;
  f.frame = record.frame;
  f.levels = record.levels;
  f.max_measured_error_px = record.max_measured_error_px;
  f.time_ms = record.time_ms;
  f.model_work = record.model_work;
  f.pixels_written = record.pixels_written;
  return f;
}

int ComparedFrame::drawn() const { return std::accumulate(levels.begin(), levels.end(), 0); }

const ComparedFrame* ComparedRun::at(int frame) const {
  if (history.empty()) return nullptr;
  const long index = long(frame) - history.front().frame;
  return index >= 0 && index < long(history.size()) ? &history[size_t(index)] : nullptr;
}

std::array<std::int64_t, kLevelCount> ComparedRun::level_totals(int first, int last) const {
  std::array<std::int64_t, kLevelCount> totals{};
  for (int k = first; k <= last; ++k) {
    const ComparedFrame* f = at(k);
    if (!f) continue;
    for (int level = 0; level < kLevelCount; ++level)
      totals[size_t(level)] += f->levels[size_t(level)];
  }
  return totals;
}

PolicyComparison::PolicyComparison(RunPlayer* model, int history_frames)
    : model_(model),
      history_frames_(std::max(1, history_frames)),
      policies_{&reuse_policy("affine"), &reuse_policy("perspective")} {}

PolicyComparison::~PolicyComparison() = default;

void PolicyComparison::set_policies(const std::vector<const ReusePolicy*>& policies) {
  if (policies.empty() || int(policies.size()) > kMaxComparedPolicies) {
    throw std::invalid_argument("a comparison takes 1 to " + std::to_string(kMaxComparedPolicies) +
                                " policies, not " + std::to_string(policies.size()));
  }
  for (const ReusePolicy* p : policies) {
    if (!p) throw std::invalid_argument("a compared policy is missing");
  }
  policies_ = policies;
  reset();
}

std::vector<const ReusePolicy*> PolicyComparison::policies() const { return policies_; }

void PolicyComparison::reset() {
  runs_.clear();
  stale_ = true;
}

void PolicyComparison::build() {
  runs_.clear();
  stale_ = false;
  if (!model_->animator() || !model_->source_kind().uses_reuse_policy) return;
  const std::string too_large = memory_problem();
  for (const ReusePolicy* policy : policies_) {
    ComparedRun run;
    run.policy = policy;
    if (!too_large.empty()) {  // none is made: together they would pass the run's memory
      run.problem = too_large;
      runs_.push_back(std::move(run));
      continue;
    }
    if (policy == model_->settings().policy) {  // the model's own run, played once
      runs_.push_back(std::move(run));
      continue;
    }
    EngineSettings settings = model_->settings();
    settings.policy = policy;
    try {
      run.owned = model_->source_kind().make(model_->source(), model_->panel(), settings);
      restart(run);
    } catch (const std::exception& e) {  // a scene-only policy (hierarchical-cache) on a plane
      run.owned.reset();
      run.problem = e.what();
    }
    runs_.push_back(std::move(run));
  }
}

std::string PolicyComparison::memory_problem() const {
  const Animator& main = *model_->animator();
  const int own = int(std::count_if(policies_.begin(), policies_.end(), [&](const ReusePolicy* p) {
    return p != model_->settings().policy;  // the model's own policy plays no second engine
  }));
  const int engines = kEnginesBesideComparedRuns + own;
  const std::string problem =
      run_memory_problem(main.scene(), main.camera(), model_->settings().guard_band, engines);
  if (problem.empty()) return "";
  return "not compared: " + problem + " (the animation, its exact projection and " +
         std::to_string(policies_.size()) + " compared policies)";
}

void PolicyComparison::restart(ComparedRun& run) const {
  run.last = run.owned->start();
  run.pixels_written = run.last.pixels_written;
  run.pixels_warped = run.last.pixels_written - run.last.pixels_not_warped;
  run.time_ms = run.last.time_ms;
  run.history.clear();
  record(run);
}

void PolicyComparison::record(ComparedRun& run) const {
  run.history.push_back(ComparedFrame::of(run.last));
  if (int(run.history.size()) > history_frames_) run.history.pop_front();
}

void PolicyComparison::seek(ComparedRun& run, int frame) const {
  if (!run.owned) return;
  if (frame < run.owned->frame()) restart(run);
  while (run.owned->frame() < frame) {
    run.last = run.owned->advance();
    run.pixels_written += run.last.pixels_written;
    run.pixels_warped += run.last.pixels_written - run.last.pixels_not_warped;
    run.time_ms += run.last.time_ms;
    record(run);
  }
}

const std::vector<ComparedRun>& PolicyComparison::runs() {
  if (stale_) build();
  const Animator* main = model_->animator();
  if (!main) {
    runs_.clear();
    stale_ = true;
    return runs_;
  }
  // One run after another, each run's pixel loops (warps, composites, splats) on all the
  // worker threads: the runs' costs differ by far (a depth reprojection splats every pixel,
  // a cadence run mostly copies), so one run per thread would leave a core idle while the
  // dearest run plays alone on the other.
  const int frame = main->frame();
  const StageTimer timer(FrameStage::kComparedRuns);
  for (ComparedRun& run : runs_) {
    if (run.problem.empty() && !run.owned) {
      run.model = main;
      follow_model(run, frame);
    } else {
      seek(run, frame);
    }
  }
  return runs_;
}

void PolicyComparison::follow_model(ComparedRun& run, int frame) const {
  const std::vector<AnimationFrame>& records = model_->history();
  int next = run.history.empty() ? 0 : run.history.back().frame + 1;
  if (next > frame + 1) {  // the model went back: its run restarted from frame 0
    run.history.clear();
    next = 0;
  }
  if (next == 0) run.pixels_written = 0, run.pixels_warped = 0, run.time_ms = 0.0;
  for (int k = next; k <= frame && k < int(records.size()); ++k) {
    run.last = records[size_t(k)];
    run.pixels_written += run.last.pixels_written;
    run.pixels_warped += run.last.pixels_written - run.last.pixels_not_warped;
    run.time_ms += run.last.time_ms;
    record(run);
  }
}

}  // namespace oflab
