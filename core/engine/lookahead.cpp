// The `lookahead` policy's prediction and schedule (see core/engine/lookahead.h).
#include "engine/lookahead.h"

#include <algorithm>
#include <limits>

namespace oflab {
namespace {

bool writes(Level level) { return level >= Level::kAffine; }

std::int64_t cost_of(const LayerCandidates& c, Level level) {
  return c.pixels[static_cast<int>(level)];
}

// A layer's predicted write within the horizon: the frames ahead (1..kLookaheadHorizon), or 0
// when none is predicted there.
int predicted_write(const LayerCandidates& c) {
  const int ahead = writes(c.choice) ? c.rerender_expiry : c.write_expiry;
  return ahead >= 1 && ahead <= kLookaheadHorizon ? ahead : 0;
}

// What updating layer `c` now, early, writes and costs beyond its own choice.
Level early_level(const LayerCandidates& c) {
  return writes(c.choice) ? Level::kRerender : c.early_write;
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
  double planned = 0.0, ahead = 0.0, movable = 0.0;
  std::vector<std::size_t> pending;
  for (std::size_t i = 0; i < layers.size(); ++i) {
    const LayerCandidates& c = layers[i];
    if (c.kind == LayerCandidates::Kind::kNotShown) continue;
    planned += static_cast<double>(cost_of(c, c.choice));
    // A fresh (or clipped) render is no update the schedule can move: left out of the
    // movable pixels and of the target.
    if (c.kind != LayerCandidates::Kind::kChoice) continue;
    movable += static_cast<double>(cost_of(c, c.choice));
    if (predicted_write(c) == 0) continue;
    ahead += static_cast<double>(cost_of(c, early_level(c)));
    pending.push_back(i);
  }
  double past_sum = 0.0;
  for (double p : past) past_sum += p;
  const double target =
      (past_sum + movable + ahead) / static_cast<double>(past.size() + kLookaheadHorizon + 1);
  std::stable_sort(pending.begin(), pending.end(), [&](std::size_t x, std::size_t y) {
    return predicted_write(layers[x]) < predicted_write(layers[y]);
  });
  for (std::size_t i : pending) {
    const LayerCandidates& c = layers[i];
    const double extra = static_cast<double>(cost_of(c, early_level(c)) - cost_of(c, c.choice));
    if (movable >= target) break;
    if (movable + 0.5 * extra >= target) continue;
    a.levels[i] = early_level(c);
    a.early[i] = 1;
    movable += extra;
    planned += extra;
  }
  a.planned = planned;
  a.movable = movable;
}

}  // namespace oflab
