// The registry of reuse policies (see core/engine/reuse_policy.h and manual/animation.md).
#include "engine/reuse_policy.h"

#include <stdexcept>

namespace oflab {
namespace {

constexpr LevelSet kNoPerspective{true, true, true, false, true};
constexpr LevelSet kOnlyRerender{false, false, false, false, true};
constexpr LevelSet kAffineOnly{false, false, true, false, true};

Level always_rerender(const ReusePolicy&, const FrameInputs&) { return Level::kRerender; }

}  // namespace

LevelPixels estimate_level_pixels(std::int64_t displayed_px, std::int64_t cache_px) {
  return {0, 0, displayed_px, cache_px + displayed_px, displayed_px};
}

bool ReusePolicy::allows_reuse() const {
  for (int l = 0; l < static_cast<int>(Level::kRerender); ++l) {
    if (allowed[l]) return true;
  }
  return false;
}

Level threshold_choice(const ReusePolicy& policy, const FrameInputs& inputs) {
  return choose_level(inputs.carried, inputs.flow, inputs.thresholds, policy.allowed,
                      inputs.pending);
}

Level printed_choice(const ReusePolicy&, const FrameInputs& inputs) {
  return printed_cascade(inputs.carried, inputs.flow, inputs.thresholds);
}

Level talisman_choice(const ReusePolicy&, const FrameInputs& inputs) {
  const FitFiducials& f = inputs.fit;
  const bool geometric = f.geometric_px <= inputs.thresholds[static_cast<int>(Level::kAffine)];
  const bool sampling = f.sigma_max <= kTalismanMaxMagnification &&
                        f.sigma_min >= kTalismanMinMagnification &&
                        f.sigma_max <= kTalismanMaxAnisotropy * f.sigma_min;
  return geometric && sampling && !f.facing_changed ? Level::kAffine : Level::kRerender;
}

const std::vector<ReusePolicy>& reuse_policies() {
  static const std::vector<ReusePolicy> policies = {
      {"perspective", "Algorithm 1, corrected: every level, first-order Taylor flow model",
       InitialView::kExact, ModelUpdate::kTaylor, kAllLevels, threshold_choice},
      {"affine", "section 6.5: affine initial view and flow model, no perspective level",
       InitialView::kAffinePart, ModelUpdate::kAffineTaylor, kNoPerspective, threshold_choice},
      {"exact", "every level, but the model follows the exact warp of each pose",
       InitialView::kExact, ModelUpdate::kExact, kAllLevels, threshold_choice},
      {"rerender", "the baseline: no reuse, every frame rendered exactly", InitialView::kExact,
       ModelUpdate::kExact, kOnlyRerender, always_rerender},
      {"dissertation", "Algorithm 1 as printed: per-term cascade, bounding-box size, |Omega|^2",
       InitialView::kExact, ModelUpdate::kTaylor, kAllLevels, printed_choice, FlowBooks::kPrinted,
       false},
      {"talisman", "Lengyel & Snyder 97: least-squares affine warp of the layer, fiducials",
       InitialView::kExact, ModelUpdate::kAffineFit, kAffineOnly, talisman_choice},
      {"budget", "section 7.5.2: a per-frame pixel or time budget allocated over the layers",
       InitialView::kExact, ModelUpdate::kTaylor, kAllLevels, threshold_choice, FlowBooks::kCorners,
       false, true},
  };
  return policies;
}

const ReusePolicy* find_reuse_policy(const std::string& name) {
  for (const ReusePolicy& p : reuse_policies()) {
    if (name == p.name) return &p;
  }
  return nullptr;
}

const ReusePolicy& reuse_policy(const std::string& name) {
  const ReusePolicy* p = find_reuse_policy(name);
  if (!p) {
    throw std::invalid_argument("unknown reuse policy '" + name + "' (one of " +
                                reuse_policy_names() + ")");
  }
  return *p;
}

const ReusePolicy& default_reuse_policy() { return reuse_policies().front(); }

std::string reuse_policy_names(const std::string& separator) {
  std::string names;
  for (const ReusePolicy& p : reuse_policies()) {
    names += (names.empty() ? "" : separator) + std::string(p.name);
  }
  return names;
}

}  // namespace oflab
