// Predictive reuse, the `lookahead` policy (dissertation section 7.5.4, "Predictive use of
// optic flow"; the regulation of Horvitz & Lengyel 97): from each layer's error and how fast
// it grows, predict the frame in which the layer expires, and schedule its pixel-writing
// updates ahead of that frame so that they do not all fall on the same frames
// (manual/policies.md, "lookahead").
//
// Slack. In frame t the corrected rule (choose_level) accepts level L when its error
// (LayerCandidates::error[L]: the larger of the books and the exact pending error, pixels)
// stays within thresholds[L]. A layer's slack for a set of levels is
//   s(t) = max over those levels L of (thresholds[L] - error_t[L]),   pixels,
// and the layer expires for them in the first frame with s < 0. Two slacks are followed:
//   re-render slack: the perspective level's (the highest reuse level): the layer expires,
//     and the rule re-renders it, when it is negative; it starts at thresholds[3] after a
//     render (every error 0);
//   write slack: the free levels' (none, translate: they write no pixel): when negative the
//     layer must write pixels (an affine or perspective warp, or a render); it restarts after
//     every update that writes pixels;
//   upgrade slack: the levels up to affine (when a perspective level lies above them): when
//     negative an affine layer must move up to a perspective warp (two passes) or a render;
//     it restarts after every perspective warp or render.
// Prediction. The last three samples s0 = s(t), s1 = s(t-1), s2 = s(t-2) give the growth
// g = s0 - s1 (this frame's flow term, carried into the error) and its time derivative
// c = g - (s1 - s2); the slack k frames ahead is extrapolated as
//   s(t + k) = s0 + k g + k (k + 1) / 2 c,
// exact when s is a quadratic in t (constant acceleration of the error); with two samples c
// is taken as 0. The predicted expiry is t + the first k >= 1 with s(t + k) < 0.
//
// Schedule (spread_updates, the allocate phase of `lookahead`; frames after the first). Only
// the warped layers' updates are movable: a fresh or clipped render is fixed (no schedule moves
// it) and takes no part. The frame's movable load is the pixels of the warped layers' own
// choices; each layer that would write pixels within the next kLookaheadHorizon frames by
// prediction (a free layer at its write expiry, a writing layer at its re-render expiry) adds
// its cost there to the load of its due frame; so does an affine layer at its upgrade expiry
// (the cost of the perspective warp), when that comes before its re-render expiry. The target
// is the mean movable load per frame over the last kLookaheadHorizon frames as allocated
// (`past`: FrameAllocation::movable), this frame and the horizon. The layers due soonest (then
// the lowest index) are updated now, early, each only where that lowers the peak of this frame
// and its due frame (this frame's load with it stays below the due frame's without it), no
// frame between is cheaper for it (else a later frame takes it), and, if it adds to this
// frame, while the frame's load is below the target: a free layer at its cheapest acceptable
// writing level (LayerCandidates::early_write), a writing layer by a re-render (for an affine
// layer often no dearer than its affine warp: a move that adds nothing). An early update is
// a level the rule accepts (or a render), so no shown error grows; it costs pixels only by
// shortening the layer's current reuse.
#pragma once

#include <array>
#include <vector>

#include "engine/budget.h"
#include "engine/decision.h"

namespace oflab {

// Frames ahead within which `lookahead` schedules updates early, and how far it predicts.
constexpr int kLookaheadHorizon = 3;
constexpr int kMaxPredictedFrames = 240;

// The last three samples of a slack, one per frame, pixels.
class SlackSeries {
 public:
  void clear() { count_ = 0; }
  void push(double slack);
  int count() const { return count_; }
  // Frames after the latest sample until the slack is predicted negative (>= 1), or -1 with
  // fewer than two samples or no crossing within kMaxPredictedFrames.
  int frames_to_expiry() const;
  // The same as if `slack` were pushed (this series unchanged).
  int frames_to_expiry_with(double slack) const;

 private:
  std::array<double, 3> s_{};  // s_[0] the latest
  int count_ = 0;
};

// How one life of a layer (from a render to the next) ended, for the report of predicted
// against actual expiry (FrameReport::expiry): set in the frame that ends it.
struct ExpiryOutcome {
  bool ended = false;  // this frame re-rendered the layer (or hid it) after a life
  // Why: the rule's own re-render (by_rule: the layer expired this frame), a re-render the
  // schedule brought forward (early: the actual expiry is not seen), or neither (a
  // refusal, the sampling limit, a clipped or hidden frame).
  bool by_rule = false;
  bool early = false;
  int predicted = -1;  // the predicted expiry frame (absolute), -1 when none was predicted
  int actual = -1;     // by_rule: this frame
  // The frame the prediction was made in: kLookaheadHorizon frames before the end, or the
  // life's first frame after the render when it is shorter.
  int made = -1;
};

// The first k in 1..max_frames with slack + k growth + k (k + 1) / 2 change < 0, or -1.
int predict_expiry_frames(double slack, double growth, double change, int max_frames);

// The slack of `levels` (see above): max over the levels L in `levels` (none..perspective)
// of thresholds[L] - error[L]; -infinity when `levels` holds none of them.
double level_slack(const TermArray& error, const TermArray& thresholds, const LevelSet& levels);

// The allocate phase of `lookahead` (see Schedule above) over the layers of one frame,
// starting from each layer's own choice in `a` (allocate_frame's); marks the early updates
// in a.early.
void spread_updates(const std::vector<LayerCandidates>& layers, const std::vector<double>& past,
                    FrameAllocation& a);

}  // namespace oflab
