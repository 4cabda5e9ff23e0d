// The psychometric function, its maximum-likelihood fit and the visual angle
// (session/study/psychometric.h) against independent computations.
#include "study/psychometric.h"

#include <gtest/gtest.h>

#include <cmath>

namespace oflab {
namespace {

TEST(Psychometric, TheThresholdIsSeenSeventyFivePercentOfTheTime) {
  for (double slope : {1.0, 3.5, 10.0}) {
    for (double lapse : {0.0, 0.02, 0.1}) {
      const PsychometricFunction f{0.8, slope, lapse};
      EXPECT_NEAR(f.correct(0.8), 0.75, 1e-12);
      EXPECT_NEAR(f.correct(0.0), 0.5, 1e-12);         // guessing
      EXPECT_NEAR(f.correct(1e3), 1.0 - lapse, 1e-9);  // seen, but for lapses
      EXPECT_LT(f.correct(0.7), f.correct(0.9));
    }
  }
}

// The fit against a dense search of the log-likelihood written out term by term.
TEST(Psychometric, TheFitFindsTheMaximumOfTheLikelihood) {
  StudyRandom random(3);
  const PsychometricFunction truth{1.2, 3.5, 0.02};
  std::vector<TrialOutcome> trials;
  for (int i = 0; i < 60; ++i) {
    const double x = 0.3 * std::pow(2.0, random.uniform() * 4.0);
    trials.push_back({x, random.chance(truth.correct(x))});
  }
  const FitSettings settings{0.01, 100.0, 3.5, 0.02};
  const ThresholdFit fit = fit_threshold(trials, settings);
  double best_t = 0.0, best = -1e300;
  for (int i = 0; i <= 200000; ++i) {
    const double t = 0.01 * std::pow(1e4, i / 200000.0);
    double ll = 0.0;
    for (const TrialOutcome& trial : trials) {
      const double k = -std::log(1.0 - 0.25 / (1.0 - 0.5 - 0.02));
      const double p = 0.5 + 0.48 * (1.0 - std::exp(-k * std::pow(trial.error_px / t, 3.5)));
      ll += std::log(trial.correct ? p : 1.0 - p);
    }
    if (ll > best) best = ll, best_t = t;
  }
  EXPECT_NEAR(fit.threshold_px / best_t, 1.0, 1e-4);
  EXPECT_NEAR(fit.log_likelihood, best, 1e-6);
  EXPECT_FALSE(fit.at_bound);
}

TEST(Psychometric, AllCorrectAnswersPutTheFitAtItsLowerBound) {
  std::vector<TrialOutcome> trials(20, TrialOutcome{1.0, true});
  const ThresholdFit fit = fit_threshold(trials, FitSettings{0.01, 100.0, 3.5, 0.02});
  EXPECT_TRUE(fit.at_bound);
  EXPECT_LT(fit.threshold_px, 0.02);
}

TEST(Psychometric, TheBootstrapIntervalHoldsTheFitAndNarrowsWithMoreTrials) {
  const PsychometricFunction truth{1.0, 3.5, 0.02};
  const auto interval = [&](int n) {
    StudyRandom random(8);
    std::vector<TrialOutcome> trials;
    for (int i = 0; i < n; ++i) {
      const double x = 0.6 + 0.8 * double(i % 5) / 4.0;
      trials.push_back({x, random.chance(truth.correct(x))});
    }
    const FitSettings settings{0.01, 100.0, 3.5, 0.02};
    const double fitted = fit_threshold(trials, settings).threshold_px;
    const ThresholdInterval ci = bootstrap_interval(trials, fitted, settings, 200, 0.95, random);
    EXPECT_LT(ci.low_px, fitted);
    EXPECT_GT(ci.high_px, fitted);
    return std::log(ci.high_px / ci.low_px);
  };
  const double narrow = interval(400), wide = interval(25);
  EXPECT_LT(narrow, wide / 2.5);  // 16 times the trials: about a quarter of the width
}

TEST(Psychometric, ArcminutesFollowFromPixelsPerInchAndDistance) {
  // 1 px at 96 ppi is 0.026458 cm; at 60 cm that subtends 0.026458 / 60 rad (small angle).
  EXPECT_NEAR(arcmin_of_pixels(1.0, 96.0, 60.0), 2.54 / 96.0 / 60.0 * 180.0 / M_PI * 60.0, 1e-6);
  EXPECT_NEAR(arcmin_of_pixels(2.0, 96.0, 120.0), arcmin_of_pixels(1.0, 96.0, 60.0), 1e-6);
  // A large size: 2 atan(s / 2d), a 30 cm object at 30 cm subtends 2 atan(0.5) = 53.13 deg.
  EXPECT_NEAR(arcmin_of_pixels(30.0 / 2.54 * 100.0, 100.0, 30.0),
              2.0 * std::atan(0.5) * 180.0 / M_PI * 60.0, 1e-6);
}

}  // namespace
}  // namespace oflab
