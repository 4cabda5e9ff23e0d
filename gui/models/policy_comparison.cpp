#include "models/policy_comparison.h"

#include <stdexcept>

#include "models/animation_model.h"

namespace oflab {

PolicyComparison::PolicyComparison(AnimationModel* model)
    : model_(model), policies_{&reuse_policy("affine"), &reuse_policy("perspective")} {}

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
  for (const ReusePolicy* policy : policies_) {
    ComparedRun run;
    run.policy = policy;
    EngineSettings settings = model_->settings();
    settings.policy = policy;
    try {
      run.animator = model_->source_kind().make(model_->source(), *model_->scene_model(), settings);
      restart(run);
    } catch (const std::exception& e) {  // the model plays it, so this is unexpected
      run.animator.reset();
      run.problem = e.what();
    }
    runs_.push_back(std::move(run));
  }
}

void PolicyComparison::restart(ComparedRun& run) {
  run.last = run.animator->start();
  run.pixels_written = run.last.pixels_written;
  run.time_ms = run.last.time_ms;
}

void PolicyComparison::seek(ComparedRun& run, int frame) {
  if (!run.animator) return;
  if (frame < run.animator->frame()) restart(run);
  while (run.animator->frame() < frame) {
    run.last = run.animator->advance();
    run.pixels_written += run.last.pixels_written;
    run.time_ms += run.last.time_ms;
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
  for (ComparedRun& run : runs_) seek(run, main->frame());
  return runs_;
}

}  // namespace oflab
