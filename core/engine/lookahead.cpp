// The `lookahead` policy's prediction and schedule (see core/engine/lookahead.h).
#include "engine/lookahead.h"

#include <algorithm>
#include <array>
#include <limits>

namespace oflab {
namespace {

bool writes(Level level) { return level >= Level::kAffine; }

std::int64_t cost_of(const LayerCandidates& c, Level level) {
  return c.pixels[static_cast<int>(level)];
}

// A layer's predicted write within the horizon: the frames ahead it falls in
// (1..kLookaheadHorizon, 0 when none is predicted there), the level it writes then, and the
// level that updates the layer now, early, instead.
struct PredictedWrite {
  int due = 0;
  Level then = Level::kRerender;
  Level early = Level::kRerender;
};

PredictedWrite predicted_write(const LayerCandidates& c) {
  const auto within = [](int ahead) {
    return ahead >= 1 && ahead <= kLookaheadHorizon ? ahead : 0;
  };
  // A free layer must write when its free levels expire: its cheapest writing level.
  if (!writes(c.choice)) return {within(c.write_expiry), c.early_write, c.early_write};
  // A writing layer is re-rendered when its reuse levels expire, and an affine one moves up to
  // a perspective warp when its levels up to affine expire first; a render now spares either.
  const int render = within(c.rerender_expiry);
  const int upgrade = c.choice == Level::kAffine ? within(c.upgrade_expiry) : 0;
  if (upgrade > 0 && (render == 0 || upgrade < render)) {
    return {upgrade, Level::kPerspective, Level::kRerender};
  }
  return {render, Level::kRerender, Level::kRerender};
}

}  // namespace

void SlackSeries::push(double slack) {
  s_ = {slack, s_[0], s_[1]};
  count_ = std::min(count_ + 1, 3);
}

int SlackSeries::frames_to_expiry() const {
  if (count_ < 2) return -1;
  const double growth = s_[0] - s_[1];
  const double change = count_ >= 3 ? growth - (s_[1] - s_[2]) : 0.0;
  return predict_expiry_frames(s_[0], growth, change, kMaxPredictedFrames);
}

int SlackSeries::frames_to_expiry_with(double slack) const {
  SlackSeries next = *this;
  next.push(slack);
  return next.frames_to_expiry();
}

int predict_expiry_frames(double slack, double growth, double change, int max_frames) {
  double s = slack;
  for (int k = 1; k <= max_frames; ++k) {
    s += growth + k * change;  // s(t + k) - s(t + k - 1)
    if (s < 0.0) return k;
  }
  return -1;
}

double level_slack(const TermArray& error, const TermArray& thresholds, const LevelSet& levels) {
  double slack = -std::numeric_limits<double>::infinity();
  for (int l = 0; l < kTermCount; ++l) {
    if (levels[l]) slack = std::max(slack, thresholds[l] - error[l]);
  }
  return slack;
}

void spread_updates(const std::vector<LayerCandidates>& layers, const std::vector<double>& past,
                    FrameAllocation& a) {
  a.early.assign(layers.size(), 0);
  // Movable pixels: this frame's warped layers' own choices (load[0]) and, per frame ahead,
  // the writes predicted there (load[k]). Fresh and clipped renders are fixed: no schedule
  // moves them, so they take no part in the comparisons below.
  std::array<double, kLookaheadHorizon + 1> load{};
  double fixed = 0.0;
  std::vector<std::size_t> pending;
  for (std::size_t i = 0; i < layers.size(); ++i) {
    const LayerCandidates& c = layers[i];
    if (c.kind == LayerCandidates::Kind::kNotShown) continue;
    const double own = static_cast<double>(cost_of(c, c.choice));
    if (c.kind == LayerCandidates::Kind::kFresh) {
      fixed += own;
      continue;
    }
    load[0] += own;
    const PredictedWrite p = predicted_write(c);
    if (p.due == 0) continue;
    load[static_cast<std::size_t>(p.due)] += static_cast<double>(cost_of(c, p.then));
    pending.push_back(i);
  }
  double sum = 0.0;
  for (double p : past) sum += p;
  for (double l : load) sum += l;
  const double target = sum / static_cast<double>(past.size() + load.size());
  std::stable_sort(pending.begin(), pending.end(), [&](std::size_t x, std::size_t y) {
    return predicted_write(layers[x]).due < predicted_write(layers[y]).due;
  });
  for (std::size_t i : pending) {
    const LayerCandidates& c = layers[i];
    const PredictedWrite p = predicted_write(c);
    const auto due = static_cast<std::size_t>(p.due);
    const double then = static_cast<double>(cost_of(c, p.then));
    const double early = static_cast<double>(cost_of(c, p.early));
    const double now = load[0] + early - static_cast<double>(cost_of(c, c.choice));
    // A move that adds to this frame only while the frame is below the target.
    if (now > load[0] && load[0] >= target) continue;
    // Moved only where it lowers the peak of this frame and its due frame, and into the
    // cheapest frame of the window up to the due one (else a later frame takes it).
    bool cheapest = now < load[due];
    for (std::size_t k = 1; k < due && cheapest; ++k) cheapest = now <= load[k] + early;
    if (!cheapest) continue;
    a.levels[i] = p.early;
    a.early[i] = 1;
    load[0] = now;
    load[due] -= then;
  }
  a.movable = load[0];
  a.planned = load[0] + fixed;
}

}  // namespace oflab
