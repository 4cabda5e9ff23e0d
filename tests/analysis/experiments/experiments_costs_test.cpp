// The cost sweep's readings (analysis/experiments/experiments_costs.h) on hand-made sweep
// results: the break-even interpolation, the per-policy break-even table and the printed
// rule's table beside the corrected one. No run is played, so nothing here is timed.
#include "experiments/experiments_costs.h"

#include <gtest/gtest.h>

#include <cmath>

#include "experiments/experiments_runs.h"
#include "experiments/published_results.h"

namespace oflab {
namespace {

// A sweep point at re-render cost `cost` with time saved `saved` and largest error `error`.
CostPoint point(double cost, double saved, double error = 0.5) {
  CostPoint p;
  p.content.kind = cost <= 1.0 ? ContentKind::kTexture : ContentKind::kImpostor;
  p.content.quality = 1;
  p.render_cost = cost;
  p.summary.time_saved = saved;
  p.summary.max_measured_error_px = error;
  return p;
}

CostScript script(const std::string& name, const std::string& policy,
                  std::vector<CostPoint> points) {
  return {name, policy, std::move(points)};
}

TEST(CostSweep, BreakEvenInterpolatesWhereTimeSavedCrossesZero) {
  // From -0.2 at cost 1 to 0.6 at cost 25: zero a quarter of the way, at 1 + 0.25 * 24 = 7.
  EXPECT_NEAR(break_even_cost(script("a", "p", {point(1, -0.2), point(25, 0.6)})), 7.0, 1e-12);
  // The first crossing counts: -0.5 at 1, -0.1 at 10, 0.3 at 30 -> 10 + 0.25 * 20 = 15.
  EXPECT_NEAR(break_even_cost(script("a", "p", {point(1, -0.5), point(10, -0.1), point(30, 0.3)})),
              15.0, 1e-12);
  EXPECT_EQ(break_even_cost(script("a", "p", {point(1, 0.1), point(25, 0.6)})), 0.0);
  EXPECT_TRUE(std::isnan(break_even_cost(script("a", "p", {point(1, -0.3), point(25, -0.1)}))));
  EXPECT_TRUE(std::isnan(break_even_cost(script("a", "p", {}))));
}

TEST(CostSweep, FirstPointCostingFindsTheFirstDearEnoughContent) {
  const CostScript s =
      script("a", "p", {point(1, 0), point(9.9, 0), point(15.5, 0), point(110, 0)});
  EXPECT_EQ(first_point_costing(s, 10.0), 2);
  EXPECT_EQ(first_point_costing(s, 1.0), 0);
  EXPECT_EQ(first_point_costing(s, 200.0), -1);
}

CostSweepResult two_policy_result() {
  CostSweepResult r;
  r.spec.policies = {kCorrectedPolicy, kPrintedPolicy};
  r.scripts = {script("zoom", kCorrectedPolicy, {point(1, -0.1), point(15.5, 0.7, 1.0)}),
               script("street/walk", kCorrectedPolicy, {point(1, 0.2), point(15.5, 0.5)}),
               script("zoom", kPrintedPolicy, {point(1, 0.05), point(15.5, 0.9, 3.25)}),
               script("street/walk", kPrintedPolicy, {point(1, -0.4), point(15.5, -0.2)})};
  return r;
}

TEST(CostSweep, BreakEvenTableHasAColumnPerPolicy) {
  const ReportTable t = break_even_table(two_policy_result());
  ASSERT_EQ(t.header, (std::vector<std::string>{"script", kCorrectedPolicy, kPrintedPolicy}));
  ASSERT_EQ(t.rows.size(), 2u);
  // zoom, corrected: -0.1 at 1 to 0.7 at 15.5: 1 + 14.5 / 8 = 2.8125.
  EXPECT_EQ(t.rows[0], (std::vector<std::string>{"zoom", "2.8", "pays already"}));
  EXPECT_EQ(t.rows[1], (std::vector<std::string>{"street/walk", "pays already", "never"}));
}

TEST(CostSweep, PrintedChoiceTableSetsThePrintedRuleBesideTheCorrectedOne) {
  const ReportTable t = printed_choice_table(two_policy_result());
  const PublishedScriptResult* zoom = published_experiment1_row("zoom");
  ASSERT_NE(zoom, nullptr);
  ASSERT_EQ(t.rows.size(), 1u) << "only Experiment 1 scripts with a published row";
  const std::vector<std::string>& row = t.rows[0];
  ASSERT_EQ(row.size(), t.header.size());
  EXPECT_EQ(row[0], "zoom");
  EXPECT_EQ(row[1], percent(zoom->time_saved_percent / 100.0));
  EXPECT_EQ(row[2], "impostor 1");  // the first point of at least ten warps
  EXPECT_EQ(row[3], "70.0%");
  EXPECT_EQ(row[4], "1.00");
  EXPECT_EQ(row[5], "90.0%");
  EXPECT_EQ(row[6], "3.25");
}

TEST(CostSweep, SpecsSweepTheCorrectedAndThePrintedRule) {
  for (bool quick : {true, false}) {
    const CostSweepSpec spec = cost_sweep_spec(quick);
    const auto has = [&](const std::string& name) {
      return std::find(spec.policies.begin(), spec.policies.end(), name) != spec.policies.end();
    };
    EXPECT_TRUE(has(kCorrectedPolicy)) << quick;
    EXPECT_TRUE(has(kPrintedPolicy)) << quick;
    for (const std::string& p : spec.policies) EXPECT_NE(find_reuse_policy(p), nullptr) << p;
  }
  const CostSweepSpec full = cost_sweep_spec(false);
  EXPECT_GE(full.policies.size(), 4u);
}

}  // namespace
}  // namespace oflab
