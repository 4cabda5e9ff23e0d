// The budget policy (core/engine/budget.h): the greedy allocation against exhaustive search
// and an independent enumeration, the documented gap, starved layers, and animators that
// never spend more than the frame budget after the first frame.
#include "engine/budget.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "engine/animator.h"
#include "engine/script.h"
#include "image/image.h"
#include "scene/scene_animator.h"
#include "scene_cases.h"

namespace oflab {
namespace {

BudgetLayer layer(std::vector<std::pair<double, double>> cost_benefit) {
  BudgetLayer l;
  for (const auto& [cost, benefit] : cost_benefit) l.push_back({Level::kAffine, cost, benefit});
  l.front().level = Level::kNone;
  return l;
}

// The optimum by counting through every combination in mixed radix: shares nothing with
// exhaustive_allocation but the data.
double enumerated_optimum(const std::vector<BudgetLayer>& layers, double budget) {
  std::vector<std::size_t> digit(layers.size(), 0);
  double best = 0.0;
  while (true) {
    double cost = 0.0, benefit = 0.0;
    for (std::size_t l = 0; l < layers.size(); ++l) {
      cost += layers[l][digit[l]].cost;
      benefit += layers[l][digit[l]].benefit;
    }
    if (cost <= budget) best = std::max(best, benefit);
    std::size_t l = 0;
    while (l < layers.size() && ++digit[l] == layers[l].size()) digit[l++] = 0;
    if (l == layers.size()) return best;
  }
}

TEST(BudgetAllocation, GreedyEqualsExhaustiveWhereGreedyIsOptimal) {
  // Ratios 2 (A's first step), 1 (B), 2/3 (A's second): greedy takes A's step and B's, 14.
  const std::vector<BudgetLayer> layers = {layer({{0, 0}, {4, 8}, {10, 12}}),
                                           layer({{0, 0}, {6, 6}})};
  const BudgetSolution g = greedy_allocation(layers, 10.0);
  const BudgetSolution e = exhaustive_allocation(layers, 10.0);
  EXPECT_DOUBLE_EQ(g.benefit, 14.0);
  EXPECT_DOUBLE_EQ(e.benefit, 14.0);
  EXPECT_EQ(g.chosen, (std::vector<int>{1, 1}));
  EXPECT_DOUBLE_EQ(optimality_gap(e.benefit, g.benefit), 0.0);
  // Free options: the best one is taken, whatever the budget.
  const std::vector<BudgetLayer> free = {layer({{0, 0}, {0, 3}, {5, 4}})};
  EXPECT_DOUBLE_EQ(greedy_allocation(free, 0.0).benefit, 3.0);
  EXPECT_DOUBLE_EQ(exhaustive_allocation(free, 0.0).benefit, 3.0);
}

TEST(BudgetAllocation, GreedySuboptimalCaseHasTheGapComputedByHand) {
  // A's step has the best ratio (7/6) and leaves 4, which affords neither B nor C; the
  // optimum is B and C (10). Gap (10 - 7) / 10.
  const std::vector<BudgetLayer> layers = {layer({{0, 0}, {6, 7}}), layer({{0, 0}, {5, 5}}),
                                           layer({{0, 0}, {5, 5}})};
  const BudgetSolution g = greedy_allocation(layers, 10.0);
  const BudgetSolution e = exhaustive_allocation(layers, 10.0);
  EXPECT_DOUBLE_EQ(g.benefit, 7.0);
  EXPECT_DOUBLE_EQ(g.cost, 6.0);
  EXPECT_DOUBLE_EQ(e.benefit, 10.0);
  EXPECT_EQ(e.chosen, (std::vector<int>{0, 1, 1}));
  EXPECT_DOUBLE_EQ(optimality_gap(e.benefit, g.benefit), 0.3);
}

TEST(BudgetAllocation, GreedyIsWithinTheDocumentedGapOnRandomSmallInstances) {
  std::mt19937 rng(15);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst = 0.0;
  for (int trial = 0; trial < 400; ++trial) {
    const int count = 1 + trial % kExhaustiveMaxLayers;
    std::vector<BudgetLayer> layers;
    for (int l = 0; l < count; ++l) {
      std::vector<std::pair<double, double>> options = {{0.0, 0.0}};
      const int more = 1 + static_cast<int>(unit(rng) * 4);
      for (int o = 0; o < more; ++o) options.push_back({100.0 * unit(rng), 10.0 * unit(rng)});
      layers.push_back(layer(options));
    }
    const double budget = 250.0 * unit(rng);
    const BudgetSolution g = greedy_allocation(layers, budget);
    const BudgetSolution e = exhaustive_allocation(layers, budget);
    ASSERT_LE(g.cost, budget + 1e-9) << trial;
    ASSERT_LE(e.cost, budget + 1e-9) << trial;
    EXPECT_NEAR(e.benefit, enumerated_optimum(layers, budget), 1e-9) << trial;
    ASSERT_LE(g.benefit, e.benefit + 1e-9) << trial;
    const double gap = optimality_gap(e.benefit, g.benefit);
    EXPECT_LE(gap, 0.5) << trial;  // the documented bound (greedy_allocation)
    worst = std::max(worst, gap);
  }
  EXPECT_LT(worst, 0.5);
}

LayerCandidates choice(Level own, std::int64_t affine_pixels, double stale_error) {
  LayerCandidates c;
  c.kind = LayerCandidates::Kind::kChoice;
  c.choice = own;
  c.feasible = kAllLevels;
  c.pixels = {0, 0, affine_pixels, 3 * affine_pixels, affine_pixels};
  c.error = {stale_error, stale_error, 0.1, 0.05};
  return c;
}

TEST(BudgetAllocation, DynamicProgrammingFindsTheExhaustiveOptimumForWholeCosts) {
  std::mt19937 rng(16);
  std::uniform_int_distribution<int> cost(0, 60), benefit(0, 20), extra(1, 4);
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<BudgetLayer> layers;
    for (int l = 0; l < 1 + trial % kExhaustiveMaxLayers; ++l) {
      std::vector<std::pair<double, double>> options = {{0.0, 0.0}};
      for (int o = extra(rng); o > 0; --o)
        options.push_back({double(cost(rng)), double(benefit(rng))});
      layers.push_back(layer(options));
    }
    const double budget = double(cost(rng) * 2);
    EXPECT_DOUBLE_EQ(optimal_benefit(layers, budget), exhaustive_allocation(layers, budget).benefit)
        << trial;
  }
  // The hand-made case where greedy is suboptimal, and costs that are not whole numbers.
  const std::vector<BudgetLayer> suboptimal = {layer({{0, 0}, {6, 7}}), layer({{0, 0}, {5, 5}}),
                                               layer({{0, 0}, {5, 5}})};
  EXPECT_DOUBLE_EQ(optimal_benefit(suboptimal, 10.0), 10.0);
  EXPECT_TRUE(std::isnan(optimal_benefit({layer({{0, 0}, {0.5, 1}})}, 10.0)));
  // More layers than exhaustive search takes: the frame's gap is still checked.
  const std::vector<LayerCandidates> many(12, choice(Level::kAffine, 1000, 3.0));
  const FrameAllocation a = allocate_frame(
      reuse_policy("budget"), {FrameBudget::Unit::kPixels, 4500.0}, LevelRates(), many);
  EXPECT_DOUBLE_EQ(a.optimality_gap, 0.0);
}

TEST(BudgetAllocation, ExhaustiveSearchRefusesTooManyCompetingLayers) {
  std::vector<BudgetLayer> layers(kExhaustiveMaxLayers + 1, layer({{0, 0}, {1, 1}}));
  EXPECT_EQ(competing_layers(layers, 10.0), kExhaustiveMaxLayers + 1);
  EXPECT_THROW(exhaustive_allocation(layers, 10.0), std::invalid_argument);
  // Options beyond the budget do not compete.
  EXPECT_EQ(competing_layers(layers, 0.5), 0);
  EXPECT_NO_THROW(exhaustive_allocation(layers, 0.5));
}

TEST(BudgetAllocation, StarvedLayersAreThoseTheRuleWouldSpendPixelsOnThatGetNone) {
  const ReusePolicy& budget = reuse_policy("budget");
  LayerCandidates fresh;
  fresh.kind = LayerCandidates::Kind::kFresh;
  fresh.pixels[static_cast<int>(Level::kRerender)] = 500;
  fresh.extent_px = 40.0;
  LayerCandidates gone;  // kNotShown: never starved
  const std::vector<LayerCandidates> layers = {choice(Level::kAffine, 1000, 3.0),
                                               choice(Level::kNone, 1000, 0.2), fresh, gone};
  const LevelRates rates;
  // Nothing affordable: A keeps its image, the fresh layer shows nothing; A and it starve.
  FrameAllocation a = allocate_frame(budget, {FrameBudget::Unit::kPixels, 0.0}, rates, layers);
  EXPECT_EQ(a.starved, (std::vector<char>{1, 0, 1, 0}));
  EXPECT_EQ(a.shown[2], 0);
  EXPECT_EQ(a.levels[0], Level::kNone);
  EXPECT_DOUBLE_EQ(a.planned, 0.0);
  // 600 pixels: the fresh layer's render (40 px of extent for 500) beats A's affine (2.9
  // for 1000, which does not fit anyway); A alone starves.
  a = allocate_frame(budget, {FrameBudget::Unit::kPixels, 600.0}, rates, layers);
  EXPECT_EQ(a.starved, (std::vector<char>{1, 0, 0, 0}));
  EXPECT_EQ(a.shown[2], 1);
  EXPECT_DOUBLE_EQ(a.planned, 500.0);
  EXPECT_DOUBLE_EQ(a.optimality_gap, 0.0);
  // Enough for both: nobody starves.
  a = allocate_frame(budget, {FrameBudget::Unit::kPixels, 1500.0}, rates, layers);
  EXPECT_EQ(a.starved, (std::vector<char>{0, 0, 0, 0}));
  // Other policies take each layer's own choice and starve nobody.
  a = allocate_frame(reuse_policy("perspective"), {FrameBudget::Unit::kPixels, 0.0}, rates, layers);
  EXPECT_EQ(a.levels[0], Level::kAffine);
  EXPECT_EQ(a.starved, (std::vector<char>{0, 0, 0, 0}));
}

TEST(BudgetAllocation, MillisecondBudgetsUseTheMeasuredRatePerLevel) {
  LevelRates rates;
  EXPECT_DOUBLE_EQ(rates.ms_per_pixel(Level::kAffine), 0.0);
  rates.record(Level::kRerender, 2.0, 1000);                    // 2 us per pixel
  EXPECT_DOUBLE_EQ(rates.ms_per_pixel(Level::kAffine), 0.002);  // not seen yet: re-render's
  rates.record(Level::kAffine, 0.5, 1000);
  rates.record(Level::kAffine, 0.5, 1000);
  rates.record(Level::kAffine, 9.0, 0);  // wrote nothing: not recorded
  EXPECT_DOUBLE_EQ(rates.ms_per_pixel(Level::kAffine), 0.0005);
  const FrameBudget ms{FrameBudget::Unit::kMilliseconds, 1.0};
  EXPECT_DOUBLE_EQ(budget_cost(ms, rates, Level::kAffine, 400), 0.2);
  EXPECT_DOUBLE_EQ(budget_cost({FrameBudget::Unit::kPixels, 1.0}, rates, Level::kAffine, 400),
                   400.0);
}

TEST(BudgetAllocation, BoxPixelsBoundTheIntegerBoxWithAMargin) {
  const ConvexPolygon p = ConvexPolygon::rectangle(0.5, 0.5, 10.2, 4.0);
  // Integer box [0, 11] x [0, 4]: 11 x 4, grown by a pixel on every side: 13 x 6.
  EXPECT_EQ(box_pixels(p), 13 * 6);
  EXPECT_EQ(box_pixels(ConvexPolygon()), 0);
}

TEST(BudgetAllocation, BadBudgetsAreRefusedWithTheirReason) {
  EXPECT_EQ(frame_budget_problem({}), "");
  EXPECT_EQ(frame_budget_problem({FrameBudget::Unit::kPixels, 0.0}), "");
  EXPECT_NE(frame_budget_problem({FrameBudget::Unit::kPixels, -1.0}), "");
  EXPECT_NE(frame_budget_problem({FrameBudget::Unit::kMilliseconds, NAN}), "");
  const FrameBudget d = budget_or_default({}, 640, 480);
  EXPECT_EQ(d.unit, FrameBudget::Unit::kPixels);
  EXPECT_DOUBLE_EQ(d.amount, 640.0 * 480.0 / 4.0);
}

// Plays a random scene of `count` polygons under the budget policy: after frame 0 no frame
// writes more pixels than the budget, and the report's own check agrees.
void expect_scene_within_budget(int count, double budget_pixels, unsigned seed) {
  std::mt19937 rng(seed);
  const Scene scene = testing::scene_with(testing::random_polygons(rng, count));
  const Camera camera = make_camera(256.0, 256, 192);
  SceneSettings settings;
  settings.engine.policy = &reuse_policy("budget");
  settings.engine.budget = {FrameBudget::Unit::kPixels, budget_pixels};
  SceneEngine animator(scene, camera, settings);
  const ViewerPose start = look_at(Vec3(0, 1, 14), Vec3(0, 0, 0), Vec3(0, 1, 0));
  const auto frames = expand_viewer_segments(
      start, {{20, Vec3(0.06, 0, -0.05), Vec3(0, 0.004, 0)}, {15, Vec3(0), Vec3(0, 0, 0.02)}});
  long starved = 0, drawn = 0;
  std::int64_t pixels = 0;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const AnimationFrame r =
        i == 0 ? animator.start(frames[0].pose)
               : animator.advance(frames[i - 1].pose, frames[i - 1].motion, frames[i].pose);
    if (i == 0) {
      EXPECT_FALSE(r.budget.active);
      continue;
    }
    ASSERT_TRUE(r.budget.active);
    EXPECT_LE(r.pixels_written, static_cast<std::int64_t>(budget_pixels)) << "frame " << i;
    EXPECT_DOUBLE_EQ(r.budget.spent, static_cast<double>(r.pixels_written)) << i;
    EXPECT_FALSE(r.budget.over()) << i;
    EXPECT_LE(r.budget.planned, budget_pixels) << i;
    EXPECT_LE(r.drawn() + r.culled() + r.hidden, r.layers);
    starved += r.budget.starved;
    drawn += r.drawn();
    pixels += r.pixels_written;
  }
  EXPECT_GT(drawn, 0);  // the polygons are in view
  if (budget_pixels >= 15000.0) {
    EXPECT_GT(pixels, 0);
  }
  if (budget_pixels == 0.0) {
    EXPECT_GT(starved, 0);
  }
}

TEST(BudgetPolicy, RandomScenesNeverExceedThePixelBudgetAfterTheFirstFrame) {
  for (unsigned seed : {1u, 2u, 3u}) {
    for (double budget : {0.0, 2000.0, 15000.0}) {
      SCOPED_TRACE("seed " + std::to_string(seed) + " budget " + std::to_string(budget));
      expect_scene_within_budget(5 + static_cast<int>(seed) * 3, budget, seed);
    }
  }
}

TEST(BudgetPolicy, ASinglePlaneIsOneLayerWithinItsBudget) {
  MotionScript script;
  script.camera = make_camera(256.0, 256, 192);
  PlanePose pose;
  pose.point = Vec3(0.0, 0.0, 4.0);
  pose.normal = Vec3(0.2, 0.1, 1.0);
  script.frames = expand_segments(pose, MotionModel::kScrew,
                                  {{30, Vec3(0.02, 0.0, -0.03), Vec3(0.0, 0.02, 0.01)}});
  for (double budget : {0.0, 5000.0, 1e6}) {
    EngineSettings settings;
    settings.policy = &reuse_policy("budget");
    settings.budget = {FrameBudget::Unit::kPixels, budget};
    const auto animator = make_plane_animator(script, testing::checker_image(64, 64), settings);
    long updated = 0;
    for (int i = 0; i < animator->frame_count(); ++i) {
      const AnimationFrame f = i == 0 ? animator->start() : animator->advance();
      if (i == 0) continue;
      EXPECT_LE(f.pixels_written, static_cast<std::int64_t>(budget)) << budget << " " << i;
      EXPECT_FALSE(f.budget.over());
      updated += f.pixels_written > 0 ? 1 : 0;
    }
    if (budget == 0.0) {
      EXPECT_EQ(updated, 0);
    }
    if (budget == 1e6) {
      EXPECT_GT(updated, 0);  // an unstarved plane is updated
    }
  }
}

}  // namespace
}  // namespace oflab
