// The budget policy's allocation (see core/engine/budget.h and manual/policies.md).
#include "engine/budget.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "engine/lookahead.h"
#include "engine/wall_clock.h"

namespace oflab {
namespace {

// One step from one option of a layer to a dearer one on its hull.
struct Increment {
  int layer = 0;
  int from = 0;  // option indices into the layer's options
  int to = 0;
  double cost = 0.0;
  double benefit = 0.0;
};

// The options of `layer` within `budget` that a greedy allocation climbs through: sorted by
// cost, each dearer one bringing more benefit, on the upper convex hull of (cost, benefit).
// Indices into `layer`; the first is the best free option.
std::vector<int> hull_options(const BudgetLayer& layer, double budget) {
  std::vector<int> order;
  for (int i = 0; i < static_cast<int>(layer.size()); ++i) {
    if (layer[i].cost <= budget) order.push_back(i);
  }
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    if (layer[a].cost != layer[b].cost) return layer[a].cost < layer[b].cost;
    return layer[a].benefit > layer[b].benefit;
  });
  std::vector<int> hull;
  for (int i : order) {
    if (!hull.empty() && layer[i].benefit <= layer[hull.back()].benefit) continue;  // dominated
    while (hull.size() >= 2) {
      const BudgetOption& a = layer[hull[hull.size() - 2]];
      const BudgetOption& b = layer[hull.back()];
      // b lies on or below the segment from a to i: a mix of a and i beats it.
      const double cross = (b.cost - a.cost) * (layer[i].benefit - a.benefit) -
                           (b.benefit - a.benefit) * (layer[i].cost - a.cost);
      if (cross < 0.0) break;
      hull.pop_back();
    }
    hull.push_back(i);
  }
  return hull;
}

BudgetSolution totals(const std::vector<BudgetLayer>& layers, std::vector<int> chosen) {
  BudgetSolution s;
  s.chosen = std::move(chosen);
  for (std::size_t l = 0; l < layers.size(); ++l) {
    s.cost += layers[l][s.chosen[l]].cost;
    s.benefit += layers[l][s.chosen[l]].benefit;
  }
  return s;
}

// The greedy climb along every layer's hull, increments in decreasing benefit per cost.
BudgetSolution greedy_climb(const std::vector<BudgetLayer>& layers, double budget,
                            std::vector<int>& base) {
  std::vector<Increment> steps;
  for (int l = 0; l < static_cast<int>(layers.size()); ++l) {
    const std::vector<int> hull = hull_options(layers[l], budget);
    base[l] = hull.empty() ? 0 : hull.front();
    for (std::size_t k = 1; k < hull.size(); ++k) {
      const BudgetOption& a = layers[l][hull[k - 1]];
      const BudgetOption& b = layers[l][hull[k]];
      steps.push_back({l, hull[k - 1], hull[k], b.cost - a.cost, b.benefit - a.benefit});
    }
  }
  // Free increments (cost 0 cannot happen after the hull) first, then by ratio.
  std::stable_sort(steps.begin(), steps.end(), [](const Increment& a, const Increment& b) {
    return a.benefit * b.cost > b.benefit * a.cost;
  });
  std::vector<int> chosen = base;
  double left = budget;
  for (const Increment& s : steps) {
    // An increment builds on the one before it on the same hull: once one is skipped, the
    // layer's later increments are out of reach.
    if (chosen[s.layer] != s.from || s.cost > left) continue;
    chosen[s.layer] = s.to;
    left -= s.cost;
  }
  return totals(layers, chosen);
}

}  // namespace

std::string frame_budget_problem(const FrameBudget& budget) {
  if (budget.unit == FrameBudget::Unit::kNone) return "";
  if (!std::isfinite(budget.amount)) return "the budget must be a finite number";
  if (budget.amount < 0.0) return "the budget must not be negative";
  return "";
}

FrameBudget budget_or_default(const FrameBudget& budget, int camera_width, int camera_height) {
  if (budget.unit != FrameBudget::Unit::kNone) return budget;
  return {FrameBudget::Unit::kPixels, 0.25 * double(camera_width) * double(camera_height)};
}

std::int64_t box_pixels(const ConvexPolygon& polygon) {
  if (polygon.empty()) return 0;
  const BoundingBox b = polygon.bounds();
  const double w = std::ceil(b.x_max) - std::floor(b.x_min) + 2.0;
  const double h = std::ceil(b.y_max) - std::floor(b.y_min) + 2.0;
  return static_cast<std::int64_t>(w) * static_cast<std::int64_t>(h);
}

void LevelRates::record(Level level, double ms, std::int64_t pixels) {
  if (pixels <= 0 || !std::isfinite(ms)) return;
  ms_[static_cast<int>(level)] += ms;
  pixels_[static_cast<int>(level)] += static_cast<double>(pixels);
}

double LevelRates::ms_per_pixel(Level level) const {
  int l = static_cast<int>(level);
  if (pixels_[l] <= 0.0) l = static_cast<int>(Level::kRerender);
  return pixels_[l] > 0.0 ? ms_[l] / pixels_[l] : 0.0;
}

BudgetSolution greedy_allocation(const std::vector<BudgetLayer>& layers, double budget) {
  std::vector<int> base(layers.size(), 0);
  BudgetSolution climbed = greedy_climb(layers, budget, base);
  // The best single option alone, every other layer at its best free option.
  const BudgetSolution floor = totals(layers, base);
  BudgetSolution single = floor;
  for (std::size_t l = 0; l < layers.size(); ++l) {
    for (std::size_t o = 0; o < layers[l].size(); ++o) {
      const BudgetOption& opt = layers[l][o];
      const double gain = opt.benefit - layers[l][base[l]].benefit;
      if (opt.cost <= budget && floor.benefit + gain > single.benefit) {
        std::vector<int> chosen = base;
        chosen[l] = static_cast<int>(o);
        single = totals(layers, chosen);
      }
    }
  }
  return single.benefit > climbed.benefit ? single : climbed;
}

int competing_layers(const std::vector<BudgetLayer>& layers, double budget) {
  int competing = 0;
  for (const BudgetLayer& layer : layers) {
    int within = 0;
    for (const BudgetOption& o : layer) within += o.cost <= budget ? 1 : 0;
    competing += within > 1 ? 1 : 0;
  }
  return competing;
}

BudgetSolution exhaustive_allocation(const std::vector<BudgetLayer>& layers, double budget) {
  if (competing_layers(layers, budget) > kExhaustiveMaxLayers) {
    throw std::invalid_argument("exhaustive allocation: more than " +
                                std::to_string(kExhaustiveMaxLayers) + " layers offer a choice");
  }
  std::vector<int> chosen(layers.size(), 0), best = chosen;
  double best_benefit = -1.0;
  std::function<void(std::size_t, double, double)> visit = [&](std::size_t l, double cost,
                                                               double benefit) {
    if (l == layers.size()) {
      if (benefit > best_benefit) {
        best_benefit = benefit;
        best = chosen;
      }
      return;
    }
    for (std::size_t o = 0; o < layers[l].size(); ++o) {
      const BudgetOption& opt = layers[l][o];
      if (cost + opt.cost > budget) continue;
      chosen[l] = static_cast<int>(o);
      visit(l + 1, cost + opt.cost, benefit + opt.benefit);
    }
  };
  visit(0, 0.0, 0.0);
  return totals(layers, best);
}

double optimal_benefit(const std::vector<BudgetLayer>& layers, double budget) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  double dearest = 0.0, best_each = 0.0;
  for (const BudgetLayer& layer : layers) {
    double cost = 0.0, benefit = -std::numeric_limits<double>::infinity();
    for (const BudgetOption& o : layer) {
      if (o.cost != std::floor(o.cost)) return nan;
      if (o.cost <= budget && o.benefit > benefit) {
        benefit = o.benefit;
        cost = o.cost;
      }
    }
    dearest += cost;
    best_each += benefit;
  }
  if (dearest <= budget) return best_each;  // every layer's best option fits at once
  const double cells = double(layers.size()) * (std::floor(budget) + 1.0);
  if (!(cells <= kMaxOptimalTableCells)) return nan;
  // best[c]: the largest benefit of the layers so far within a whole budget c.
  const std::size_t width = static_cast<std::size_t>(budget) + 1;
  std::vector<double> best(width, 0.0), next(width);
  for (const BudgetLayer& layer : layers) {
    std::fill(next.begin(), next.end(), -std::numeric_limits<double>::infinity());
    for (const BudgetOption& o : layer) {
      if (o.cost > budget) continue;
      const std::size_t k = static_cast<std::size_t>(o.cost);
      for (std::size_t c = k; c < width; ++c) next[c] = std::max(next[c], best[c - k] + o.benefit);
    }
    best.swap(next);
  }
  return best.back();
}

double optimality_gap(double best_benefit, double greedy_benefit) {
  return best_benefit > 0.0 ? (best_benefit - greedy_benefit) / best_benefit : 0.0;
}

double budget_cost(const FrameBudget& budget, const LevelRates& rates, Level level,
                   std::int64_t pixels) {
  const double p = static_cast<double>(pixels);
  return budget.unit == FrameBudget::Unit::kMilliseconds ? p * rates.ms_per_pixel(level) : p;
}

namespace {

// A layer's options for the allocator (kNotShown: the single free option of nothing).
BudgetLayer budget_layer(const LayerCandidates& c, const FrameBudget& budget,
                         const LevelRates& rates) {
  const auto cost = [&](Level l) {
    return budget_cost(budget, rates, l, c.pixels[static_cast<int>(l)]);
  };
  if (c.kind == LayerCandidates::Kind::kNotShown) return {{Level::kRerender, 0.0, 0.0, false}};
  if (c.kind == LayerCandidates::Kind::kFresh) {
    return {{Level::kRerender, 0.0, 0.0, false},
            {Level::kRerender, cost(Level::kRerender), c.extent_px, true}};
  }
  BudgetLayer layer;
  const double stale = c.error[static_cast<int>(Level::kNone)];
  for (int l = 0; l < kLevelCount; ++l) {
    const Level level = static_cast<Level>(l);
    if (!c.feasible[l] && level != Level::kNone && level != Level::kRerender) continue;
    const double left = level == Level::kRerender ? 0.0 : c.error[l];
    // none costs nothing whatever its rate; a level writing nothing neither.
    layer.push_back({level, level == Level::kNone ? 0.0 : cost(level), stale - left, true});
  }
  return layer;
}

bool wants_pixels(const LayerCandidates& c) {
  if (c.kind == LayerCandidates::Kind::kFresh) return true;
  return c.kind == LayerCandidates::Kind::kChoice && c.pixels[static_cast<int>(c.choice)] > 0;
}

}  // namespace

FrameAllocation allocate_frame(const ReusePolicy& policy, const FrameBudget& budget,
                               const LevelRates& rates, const std::vector<LayerCandidates>& layers,
                               const std::vector<double>& past_pixels) {
  FrameAllocation a;
  a.levels.resize(layers.size());
  a.shown.assign(layers.size(), 1);
  a.starved.assign(layers.size(), 0);
  for (std::size_t i = 0; i < layers.size(); ++i) a.levels[i] = layers[i].choice;
  if (policy.spreads_updates) {
    spread_updates(layers, past_pixels, a);
    return a;
  }
  if (!policy.shares_budget || budget.unit == FrameBudget::Unit::kNone) return a;
  std::vector<BudgetLayer> options;
  for (const LayerCandidates& c : layers) options.push_back(budget_layer(c, budget, rates));
  const BudgetSolution greedy = greedy_allocation(options, budget.amount);
  for (std::size_t i = 0; i < layers.size(); ++i) {
    const BudgetOption& o = options[i][greedy.chosen[i]];
    a.levels[i] = o.level;
    a.shown[i] = o.shown ? 1 : 0;
    const bool got_pixels = o.shown && layers[i].pixels[static_cast<int>(o.level)] > 0;
    a.starved[i] = wants_pixels(layers[i]) && !got_pixels ? 1 : 0;
  }
  a.planned = greedy.cost;
  const auto t0 = WallClock::now();
  double best = budget.unit == FrameBudget::Unit::kPixels
                    ? optimal_benefit(options, budget.amount)
                    : std::numeric_limits<double>::quiet_NaN();
  if (std::isnan(best) && competing_layers(options, budget.amount) <= kExhaustiveMaxLayers) {
    best = exhaustive_allocation(options, budget.amount).benefit;
  }
  if (!std::isnan(best)) a.optimality_gap = optimality_gap(best, greedy.benefit);
  a.check_ms = ms_since(t0);
  return a;
}

BudgetLedger::BudgetLedger(const ReusePolicy& policy, const FrameBudget& budget, int camera_width,
                           int camera_height)
    : policy_(&policy), budget_(budget_or_default(budget, camera_width, camera_height)) {}

FrameAllocation BudgetLedger::allocate(int frame, const std::vector<LayerCandidates>& layers) {
  frame_ = BudgetReport{};
  updates_.clear();
  const bool active = policy_->shares_budget && frame > 0;
  const FrameAllocation a =
      allocate_frame(*policy_, active ? budget_ : FrameBudget{}, rates_, layers, past_);
  if (policy_->spreads_updates && frame > 0) {
    past_.push_back(a.movable);
    if (past_.size() > kLookaheadHorizon) past_.erase(past_.begin());
  }
  if (active) {
    frame_.active = true;
    frame_.amount = budget_.amount;
    frame_.planned = a.planned;
    frame_.optimality_gap = a.optimality_gap;
    frame_.check_ms = a.check_ms;
  }
  return a;
}

void BudgetLedger::applied(Level level, double ms, std::int64_t pixels, bool starved) {
  updates_.push_back({level, ms, pixels});
  if (frame_.active) frame_.spent += budget_cost(budget_, rates_, level, pixels);
  frame_.starved += frame_.active && starved ? 1 : 0;
}

BudgetReport BudgetLedger::finish() {
  for (const Update& u : updates_) rates_.record(u.level, u.ms, u.pixels);
  updates_.clear();
  return frame_;
}

}  // namespace oflab
