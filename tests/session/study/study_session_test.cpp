// The trial loop (session/study/study_session.h) and the simulated observer through it and
// the analysis (session/study/study_analysis.h): determinism for a seed, late trials
// repeated and counted, and the recovery of a known threshold with the interval's coverage.
#include "study/study_session.h"

#include <gtest/gtest.h>

#include "study/study_analysis.h"

namespace oflab {
namespace {

Study two_conditions(int trials) {
  Study s;
  s.name = "t";
  s.trials = trials;
  s.conditions = {StudyCondition{"a"}, StudyCondition{"b"}};
  return s;
}

const ErrorDisplay kAsRequested = [](int, double requested) { return requested; };

TEST(StudySession, OneSeedGivesOneTrialSequence) {
  const PsychometricFunction observer{1.0, 3.5, 0.02};
  for (const char* method : {"staircase", "quest+"}) {
    StudySession a(two_conditions(20), method, 17), b(two_conditions(20), method, 17),
        c(two_conditions(20), method, 18);
    simulate_answers(a, 17, observer, kAsRequested);
    simulate_answers(b, 17, observer, kAsRequested);
    simulate_answers(c, 18, observer, kAsRequested);
    ASSERT_EQ(a.trials().size(), 40u);
    bool differs = false;
    for (size_t i = 0; i < a.trials().size(); ++i) {
      EXPECT_EQ(a.trials()[i].request.condition, b.trials()[i].request.condition);
      EXPECT_EQ(a.trials()[i].request.requested_px, b.trials()[i].request.requested_px);
      EXPECT_EQ(a.trials()[i].request.distorted_first, b.trials()[i].request.distorted_first);
      EXPECT_EQ(a.trials()[i].correct, b.trials()[i].correct);
      differs |= a.trials()[i].request.condition != c.trials()[i].request.condition;
    }
    EXPECT_TRUE(differs) << method;
  }
}

TEST(StudySession, ConditionsAreInterleavedAndEachGetsItsTrials) {
  StudySession s(two_conditions(10), "staircase", 4);
  int switches = 0, last = -1;
  int count[2] = {0, 0};
  while (!s.finished()) {
    const TrialRequest r = s.request();
    EXPECT_EQ(r.trial, count[r.condition]);
    switches += last >= 0 && r.condition != last;
    last = r.condition;
    ++count[r.condition];
    s.answer(true, r.requested_px, false);
  }
  EXPECT_EQ(count[0], 10);
  EXPECT_EQ(count[1], 10);
  EXPECT_GT(switches, 3);
  EXPECT_THROW(s.answer(true, 1.0, false), std::invalid_argument);
}

TEST(StudySession, ALateTrialIsRecordedCountedAndShownAgain) {
  StudySession s(two_conditions(5), "quest+", 2);
  const TrialRequest first = s.request();
  s.answer(false, 0.9, true);
  EXPECT_EQ(s.late_trials(), 1);
  EXPECT_EQ(s.request().condition, first.condition);
  EXPECT_EQ(s.request().requested_px, first.requested_px);
  EXPECT_EQ(s.request().trial, first.trial);
  // The late answer never reached the method: its posterior is still the prior.
  EXPECT_EQ(s.method(first.condition).estimate_px(), s.method(1 - first.condition).estimate_px());
  ASSERT_EQ(s.trials().size(), 1u);
  EXPECT_TRUE(s.trials()[0].late);
  EXPECT_THROW(s.answer(true, -1.0, false), std::invalid_argument);
  EXPECT_THROW(StudySession(two_conditions(5), "quest", 1), std::invalid_argument);
}

TEST(StudySession, LateTrialsDoNotCountTowardsTheTrialsAnalysed) {
  SimulationSettings settings;
  settings.sessions = 5, settings.replicates = 20, settings.late_fraction = 0.2;
  settings.observer = {1.0, 3.5, 0.02};
  settings.methods = {"staircase"};
  const std::vector<SimulationSummary> r = simulate_study(two_conditions(20), settings);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[0].median_trials, 20.0);
  EXPECT_GT(r[0].late_presentations + r[1].late_presentations, 5);
}

// The simulated observer through the real trial loop and analysis. A 40-trial 2AFC session
// cannot place the threshold of an observer of slope 3.5 within 10 % 95 % of the time (the
// Cramer-Rao bound is a standard deviation of about 9 % in log threshold, manual/study.md);
// the staircase does for a steep observer (slope 15, the analysis assuming it), checked here
// over 200 sessions; QUEST+, which spends trials on the slope and lapse too, reaches about
// 90 %. The 1000-session figures are `oflab-cli study simulate`'s (manual/study.md).
TEST(StudySimulation, ASteepObserversThresholdIsRecoveredWithinTenPercent) {
  Study study = two_conditions(40);
  study.conditions.pop_back();
  study.assumed_slope = 15.0;
  SimulationSettings settings;
  settings.sessions = 200, settings.replicates = 20, settings.seed = 11;
  settings.observer = {1.0, 15.0, 0.02};
  settings.methods = {"staircase", "quest+"};
  const std::vector<SimulationSummary> r = simulate_study(study, settings);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_GE(r[0].recovered_within_10pct, 0.95);
  EXPECT_GE(r[1].recovered_within_10pct, 0.85);
  for (const SimulationSummary& m : r) {
    EXPECT_LT(m.median_trials, 41) << m.method;
    EXPECT_NEAR(m.median_threshold_px, 1.0, 0.02) << m.method;
  }
}

// The 95 % interval's coverage over 300 staircase sessions (a binomial standard deviation of
// 1.3 %): within 95 +- 3 % here; the 1000-session figures of both methods are in
// manual/study.md.
TEST(StudySimulation, TheBootstrapIntervalCoversTheTrueThreshold) {
  Study study = two_conditions(40);
  study.conditions.pop_back();
  SimulationSettings settings;
  settings.sessions = 300, settings.replicates = 100, settings.seed = 21;
  settings.observer = {1.0, 3.5, 0.02};
  settings.methods = {"staircase"};
  const SimulationSummary r = simulate_study(study, settings).front();
  EXPECT_NEAR(r.ci_coverage, 0.95, 0.03);
  EXPECT_NEAR(r.median_threshold_px, 1.0, 0.03);
}

}  // namespace
}  // namespace oflab
