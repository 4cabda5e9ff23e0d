// The budget policy's allocation: a per-frame budget shared by all layers, spent where it
// removes the most error. The dissertation proposes it as future work (section 7.5.2: a
// fixed frame time allocated over the layers, a knapsack problem); Horvitz & Lengyel 97
// solved Talisman's version by cost-benefit. manual/policies.md ("budget") documents the
// rule, the conversion of milliseconds and the optimality gap.
//
// Phases. Every animator plays a frame in three phases: measure (each layer says what it
// could do: LayerCandidates, from PlaneEngine::measure_*), allocate (allocate_frame, over
// all the layers of the frame) and apply (each layer shows its allocated level). Every
// policy but `budget` allocates each layer its own choice, so only `budget` sees the others.
//
// Costs and benefits. A level's cost is the pixels it would write (an upper bound: the
// integer box of the polygon it would warp, LayerCandidates::pixels), or those pixels times
// the run's measured milliseconds per pixel of that level (LevelRates) for a time budget.
// Its benefit is the error it removes: error(none) - error(level), in pixels, where
// error(level) is what the corrected rule reads (the larger of the books and the exact
// pending error of that level; 0 for a re-render). A layer that has no image to keep (its
// first frame after being stale, or a clipped render) can be shown (cost: its render;
// benefit: its extent, the diagonal of its box, the error of a missing layer) or not.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "engine/decision.h"
#include "engine/reuse_policy.h"
#include "image/polygon.h"

namespace oflab {

// The budget of one frame (after the first, which renders every layer).
struct FrameBudget {
  enum class Unit { kNone, kPixels, kMilliseconds };
  Unit unit = Unit::kNone;  // kNone: no budget (every policy but `budget`)
  double amount = 0.0;      // pixels written, or milliseconds, per frame; finite, >= 0
};

// The budget of a policy that shares one (ReusePolicy::shares_budget) when none is given:
// a quarter of the camera's pixels (width x height / 4) written per frame.
FrameBudget budget_or_default(const FrameBudget& budget, int camera_width, int camera_height);

// Empty when `budget` is valid (kNone, or a finite amount >= 0), else why not.
std::string frame_budget_problem(const FrameBudget& budget);

// What one layer could do this frame: the measure phase's answer.
struct LayerCandidates {
  enum class Kind {
    kNotShown,  // nothing to draw (outside the image, not visible): no cost, no choice
    kFresh,     // no image to reuse: a render (pixels[kRerender]) or nothing
    kChoice,    // a reuse decision: every level in `feasible`
  };
  Kind kind = Kind::kNotShown;
  Level choice = Level::kRerender;  // the policy's own level (kFresh: re-render)
  LevelSet feasible{};              // kChoice: allowed and within the sampling limit
  LevelPixels pixels{};             // upper bounds of the pixels each level would write
  TermArray error{};                // kChoice: error each level none..perspective leaves, px
  double extent_px = 0.0;           // kFresh: diagonal of the render's box, pixels
  // kChoice, policies of the threshold rule (core/engine/lookahead.h): frames after this one
  // until the layer is predicted to expire for its reuse levels (the rule re-renders it), for
  // its free levels (it must write pixels) and for its levels up to affine (it must write a
  // perspective warp or a render), if it takes its own choice; -1 when no expiry is
  // predicted. early_write: its cheapest writing level the rule accepts now (affine,
  // perspective, else re-render).
  int rerender_expiry = -1;
  int write_expiry = -1;
  int upgrade_expiry = -1;
  Level early_write = Level::kRerender;
};

// The upper bound of the pixels a warp into the box of `polygon` writes: the area of its
// integer box (as the warps size their layers) grown by one pixel on every side against
// rounding. 0 for an empty polygon.
std::int64_t box_pixels(const ConvexPolygon& polygon);

// Measured milliseconds per pixel written, per level, over the layer updates recorded so far.
class LevelRates {
 public:
  // One layer update: `ms` of wall time (FrameReport::time_ms) writing `pixels` at `level`.
  // Updates that wrote nothing are not recorded.
  void record(Level level, double ms, std::int64_t pixels);
  // ms / pixel of `level`; a level not recorded yet takes the re-render's rate (frame 0
  // renders every layer), and 0 when nothing was recorded at all.
  double ms_per_pixel(Level level) const;

 private:
  std::array<double, kLevelCount> ms_{};
  std::array<double, kLevelCount> pixels_{};
};

// One option of one layer: its cost in budget units and benefit in pixels of error removed.
struct BudgetOption {
  Level level = Level::kNone;
  double cost = 0.0;
  double benefit = 0.0;
  bool shown = true;  // false: the layer shows nothing (kFresh left without its render)
};
// A layer's options; options[0] costs nothing (keep the image, or show nothing).
using BudgetLayer = std::vector<BudgetOption>;

// One option per layer (indices into each layer's options) and the totals.
struct BudgetSolution {
  std::vector<int> chosen;
  double cost = 0.0;
  double benefit = 0.0;
};

// Greedy cost-benefit allocation within `budget` (>= 0): per layer, the options that fit
// and are not dominated (more cost for no more benefit, or below the upper convex hull of
// (cost, benefit)); their increments taken in decreasing benefit/cost order while they fit;
// then, if better, the best single option alone. The better of the two is at least half the
// optimum (the LP bound of the multiple-choice knapsack), so optimality_gap <= 0.5.
// Precondition: every layer has options, options[0] costs 0; costs and benefits finite.
BudgetSolution greedy_allocation(const std::vector<BudgetLayer>& layers, double budget);

// Layers offering a choice (more than one option within the budget) up to which
// exhaustive_allocation runs.
constexpr int kExhaustiveMaxLayers = 6;

// The optimum by trying every combination of options within `budget`. Throws
// std::invalid_argument when more than kExhaustiveMaxLayers layers offer a choice.
BudgetSolution exhaustive_allocation(const std::vector<BudgetLayer>& layers, double budget);

// The optimum's benefit for whole-number costs (pixel budgets) by dynamic programming over
// the budget (the multiple-choice knapsack: for each layer and each whole budget c, the best
// benefit within c), in layers x (budget + 1) x options steps; when every layer's dearest
// option within the budget fits at once, that is the optimum without the table. NaN when a
// cost is not a whole number or the table would pass kMaxOptimalTableCells.
constexpr double kMaxOptimalTableCells = 6e7;
double optimal_benefit(const std::vector<BudgetLayer>& layers, double budget);

// Layers of `layers` with more than one option costing at most `budget`.
int competing_layers(const std::vector<BudgetLayer>& layers, double budget);

// (best - greedy) / best: the fraction of the optimum's benefit the greedy allocation
// misses; 0 when best is 0.
double optimality_gap(double best_benefit, double greedy_benefit);

// The allocate phase for one frame: each layer's level and whether it is shown, in the order
// of `layers`. Every policy but a budget-sharing one (ReusePolicy::shares_budget) gives each
// layer its own choice. A budget-sharing policy with a budget allocates greedily; a layer is
// "starved" when the rule would have spent pixels on it (its own choice writes some, or it
// is kFresh) and it got none. When the budget affords nothing, every layer keeps its image
// (none or translate, which write nothing) and kFresh layers show nothing.
struct FrameAllocation {
  std::vector<Level> levels;
  std::vector<char> shown;
  std::vector<char> starved;
  double planned = 0.0;  // cost of the allocation, budget units (pixels for `lookahead`)
  // `lookahead` (core/engine/lookahead.h spread_updates): the layers updated early, ahead of
  // their predicted expiry; empty for every other policy.
  std::vector<char> early;
  // `lookahead`: the planned pixels of the warped layers' updates (`planned` without the fresh
  // and clipped renders): what its schedule moves, and keeps the running mean of.
  double movable = 0.0;
  // Optimality gap against the optimum: for a pixel budget optimal_benefit's, otherwise (or
  // when that gives NaN) exhaustive search's with at most kExhaustiveMaxLayers competing
  // layers; NaN when not checked (more competing layers, or no budget).
  double optimality_gap = std::numeric_limits<double>::quiet_NaN();
  // Wall time of that check, milliseconds: a diagnostic, which animators leave out of the
  // frame's time (AnimationFrame::time_ms) as they leave out the measured error.
  double check_ms = 0.0;
};
// `past_pixels`: the movable pixels allocated in the last frames (FrameAllocation::movable),
// read by `lookahead` only.
FrameAllocation allocate_frame(const ReusePolicy& policy, const FrameBudget& budget,
                               const LevelRates& rates, const std::vector<LayerCandidates>& layers,
                               const std::vector<double>& past_pixels = {});

// The cost of writing `pixels` at `level` in `budget`'s unit: the pixels themselves, or
// pixels x rates.ms_per_pixel(level) for a time budget.
double budget_cost(const FrameBudget& budget, const LevelRates& rates, Level level,
                   std::int64_t pixels);

// What a frame reports of its budget (AnimationFrame::budget); `active` false when the
// policy shares no budget or the frame is the first.
struct BudgetReport {
  bool active = false;
  double amount = 0.0;   // the budget, its unit's
  double planned = 0.0;  // the allocation's cost
  double spent = 0.0;    // what the layers wrote: pixels, or pixels x the rates of the frame
  int starved = 0;       // layers starved and updated this frame (not hidden)
  double optimality_gap = std::numeric_limits<double>::quiet_NaN();
  double check_ms = 0.0;  // FrameAllocation::check_ms
  bool over() const { return active && spent > amount; }
};

// One animator's budget over a run: the allocate phase of each frame and the frame's
// BudgetReport. Frame 0 renders every layer (no budget); from frame 1 a policy that shares a
// budget allocates within budget_or_default(budget); the milliseconds per pixel of a time
// budget are those measured over the run's earlier frames (LevelRates).
class BudgetLedger {
 public:
  BudgetLedger(const ReusePolicy& policy, const FrameBudget& budget, int camera_width,
               int camera_height);
  // The allocate phase of frame `frame` (>= 0) over its measured layers.
  FrameAllocation allocate(int frame, const std::vector<LayerCandidates>& layers);
  // One layer of this frame applied at `level`: `ms` of wall time writing `pixels`;
  // `starved` as allocated (counted only for layers applied, not for hidden ones).
  void applied(Level level, double ms, std::int64_t pixels, bool starved);
  // The frame's report; the frame's updates then join the measured rates.
  BudgetReport finish();

 private:
  struct Update {
    Level level;
    double ms;
    std::int64_t pixels;
  };
  const ReusePolicy* policy_;
  FrameBudget budget_;
  LevelRates rates_;
  BudgetReport frame_;
  std::vector<Update> updates_;
  std::vector<double> past_;  // `lookahead`: the last frames' movable pixels (oldest first)
};

}  // namespace oflab
