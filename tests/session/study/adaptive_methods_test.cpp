// The adaptive methods (session/study/adaptive_methods.h): the staircase's 3-down-1-up rule
// step by step, and QUEST+'s posterior and expected entropies against a brute-force
// computation on a tiny grid (Bayes' rule and Shannon's entropy written out directly).
#include "study/adaptive_methods.h"

#include <gtest/gtest.h>

#include <cmath>

#include "study/psychometric.h"

namespace oflab {
namespace {

double log10_of(double x) { return std::log10(x); }

TEST(Staircase, OneDownUntilTheFirstReversalThenThreeDownOneUp) {
  MethodSettings s;
  s.min_px = 0.01, s.max_px = 100.0, s.start_px = 1.0;
  Staircase stairs(s);
  EXPECT_DOUBLE_EQ(stairs.next_error_px(), 1.0);
  stairs.record(1.0, 1.0, true);  // before the first reversal: one correct lowers
  EXPECT_NEAR(log10_of(stairs.next_error_px()), -0.1, 1e-12);
  const double down = stairs.next_error_px();
  stairs.record(down, down, false);  // one wrong: up 0.1, the first reversal
  EXPECT_NEAR(log10_of(stairs.next_error_px()), 0.0, 1e-12);
  ASSERT_EQ(stairs.reversals().size(), 1u);
  EXPECT_DOUBLE_EQ(stairs.reversals()[0], down);
  stairs.record(1.0, 1.0, true);
  stairs.record(1.0, 1.0, true);
  EXPECT_NEAR(log10_of(stairs.next_error_px()), 0.0, 1e-12);  // two correct: no change yet
  stairs.record(1.0, 1.0, true);                              // three: down, the second reversal
  ASSERT_EQ(stairs.reversals().size(), 2u);
  // From the second reversal on the step is 0.05, the move at that reversal included.
  EXPECT_NEAR(log10_of(stairs.next_error_px()), -0.05, 1e-12);
  const double level = stairs.next_error_px();
  stairs.record(level, level, true);
  stairs.record(level, level, false);  // a wrong answer breaks the run and raises
  EXPECT_NEAR(log10_of(stairs.next_error_px()), 0.0, 1e-12);
  for (int i = 0; i < 2; ++i) stairs.record(1.0, 1.0, true);
  EXPECT_NEAR(log10_of(stairs.next_error_px()), 0.0, 1e-12);  // the run starts again
}

TEST(Staircase, StaysWithinTheRangeAndEstimatesFromTheLaterReversals) {
  MethodSettings s;
  s.min_px = 0.5, s.max_px = 2.0, s.start_px = 1.9;
  Staircase stairs(s);
  for (int i = 0; i < 5; ++i) stairs.record(stairs.next_error_px(), 0.0, false);
  EXPECT_DOUBLE_EQ(stairs.next_error_px(), 2.0);
  for (int i = 0; i < 30; ++i) stairs.record(stairs.next_error_px(), 0.0, true);
  EXPECT_DOUBLE_EQ(stairs.next_error_px(), 0.5);
  // One reversal, at the top (up to down): the estimate is its level.
  ASSERT_EQ(stairs.reversals().size(), 1u);
  EXPECT_DOUBLE_EQ(stairs.estimate_px(), 2.0);
}

// The posterior after answers, by Bayes' rule on the grid, written independently.
std::vector<double> brute_posterior(const QuestPlus& q,
                                    const std::vector<std::pair<double, bool>>& answers) {
  std::vector<double> post;
  double sum = 0.0;
  for (const QuestPlus::Parameters& p : q.parameters()) {
    double like = 1.0;
    for (const auto& [x, correct] : answers) {
      const double pc = PsychometricFunction{p.threshold_px, p.slope, p.lapse}.correct(x);
      like *= correct ? pc : 1.0 - pc;
    }
    post.push_back(like);
    sum += like;
  }
  for (double& v : post) v /= sum;
  return post;
}

double entropy(const std::vector<double>& p) {
  double h = 0.0;
  for (double v : p) h -= v > 0.0 ? v * std::log(v) : 0.0;
  return h;
}

// The expected entropy after a trial at x: each outcome's probability times the entropy of
// the posterior it leads to.
double brute_expected_entropy(const std::vector<double>& post, const QuestPlus& q, double x) {
  double h = 0.0;
  for (bool correct : {true, false}) {
    std::vector<double> next;
    double z = 0.0;
    for (size_t i = 0; i < post.size(); ++i) {
      const QuestPlus::Parameters& p = q.parameters()[i];
      const double pc = PsychometricFunction{p.threshold_px, p.slope, p.lapse}.correct(x);
      next.push_back(post[i] * (correct ? pc : 1.0 - pc));
      z += next.back();
    }
    for (double& v : next) v /= z;
    h += z * entropy(next);
  }
  return h;
}

TEST(QuestPlus, PosteriorAndExpectedEntropiesMatchABruteForceComputation) {
  MethodSettings s;
  s.min_px = 0.25, s.max_px = 4.0;
  QuestPlusGrid grid;
  grid.thresholds = 3, grid.stimuli = 4, grid.slopes = {2.0, 4.0}, grid.lapses = {0.0, 0.05};
  QuestPlus q(s, grid);
  ASSERT_EQ(q.parameters().size(), 12u);
  std::vector<std::pair<double, bool>> answers;
  for (const auto& [x, correct] : std::vector<std::pair<double, bool>>{
           {q.next_error_px(), true}, {1.3, false}, {0.7, true}, {2.2, true}}) {
    q.record(x, x, correct);
    answers.push_back({x, correct});
    const std::vector<double> expected = brute_posterior(q, answers);
    // QUEST+ keeps every probability within [1e-9, 1 - 1e-9] (a lapse-free function's 0
    // and 1): hence the tolerance.
    for (size_t i = 0; i < expected.size(); ++i) EXPECT_NEAR(q.posterior()[i], expected[i], 1e-7);
    int best = 0;
    for (int k = 0; k < 4; ++k) {
      const double h = brute_expected_entropy(expected, q, q.stimuli()[size_t(k)]);
      EXPECT_NEAR(q.expected_entropy(k), h, 1e-7);
      if (h < brute_expected_entropy(expected, q, q.stimuli()[size_t(best)])) best = k;
    }
    EXPECT_DOUBLE_EQ(q.next_error_px(), q.stimuli()[size_t(best)]);
  }
  // The estimate is the posterior mean of log t.
  double mean = 0.0;
  const std::vector<double> post = brute_posterior(q, answers);
  for (size_t i = 0; i < post.size(); ++i)
    mean += post[i] * std::log(q.parameters()[i].threshold_px);
  EXPECT_NEAR(q.estimate_px(), std::exp(mean), 1e-7);
}

TEST(AdaptiveMethods, TheRegistryNamesBothMethodsAndMakesThem) {
  EXPECT_EQ(adaptive_method_names(), "staircase, quest+");
  for (const AdaptiveMethodKind& kind : adaptive_methods()) {
    const auto method = kind.make(MethodSettings());
    EXPECT_GE(method->next_error_px(), 0.1) << kind.name;
    EXPECT_LE(method->next_error_px(), 10.0) << kind.name;
  }
  EXPECT_EQ(find_adaptive_method("quest"), nullptr);
}

}  // namespace
}  // namespace oflab
