// The results of threshold studies (manual/study.md): per observer, condition and method the
// threshold (the error seen 75 % of the time, from the maximum-likelihood fit of
// study/psychometric.h to the answered trials) with its 95 % parametric bootstrap interval, in
// pixels and minutes of arc; a class table adds, per condition and method, the fit of every
// observer's trials pooled. And the simulated observer's sessions that test the whole
// experiment (simulate_study). Plain C++.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "study/psychometric.h"
#include "study/study_session.h"
#include "study/trial_csv.h"

namespace oflab {

struct AnalysisSettings {
  // The fit's search range [0.01, 100] px and assumed slope and lapse (the study's defaults).
  FitSettings fit{0.01, 100.0, 3.5, 0.02};
  int replicates = 400;    // bootstrap refits (>= 20)
  double level = 0.95;     // of the interval
  std::uint64_t seed = 1;  // of the bootstrap's draws
};

// The settings that fit `study`'s trials: its assumed slope and lapse, the other defaults.
AnalysisSettings analysis_settings(const Study& study);

// The study the rows of a CSV come from, for their plot and fit: the shipped study or study
// file called rows[0].study when there is one (find_or_read_study), else a study of that name
// with the rows' conditions (in the order first met), the default error range widened to
// hold every measured error, and the default assumed slope and lapse. Precondition: rows not
// empty.
Study study_of_rows(const std::vector<TrialRow>& rows);

struct ThresholdResult {
  std::string study, observer, condition, method;  // observer "" for a class row
  int trials = 0;                                  // answered (not late) trials fitted
  int late = 0;                                    // late presentations, not fitted
  double proportion_correct = 0.0;
  double threshold_px = 0.0, low_px = 0.0, high_px = 0.0;
  bool at_bound = false;  // the fit hit an end of its range: more or other trials are needed
  // Minutes of arc, when every row shares one ppi and viewing distance.
  std::optional<double> threshold_arcmin, low_arcmin, high_arcmin;
};

// `r` as the JSON of `oflab-cli study analyse --json` and the page: {study, observer (null for
// a class row), condition, method, trials, late, proportion_correct, threshold_px, ci95_px
// [low, high], at_bound, threshold_arcmin, ci95_arcmin [low, high] (null when not known)}.
nlohmann::ordered_json threshold_result_json(const ThresholdResult& r);

// The threshold of `rows` (one group: late rows are counted, not fitted; at least one answered
// row), labelled from its first row. The bootstrap draws from a generator seeded by
// settings.seed.
ThresholdResult analyse_group(const std::vector<TrialRow>& rows, const AnalysisSettings& settings);

// One row per (study, observer, condition, method) in the order first met; then, when the rows
// come from more than one observer, a class row per (study, condition, method) pooling them.
std::vector<ThresholdResult> analyse_rows(const std::vector<TrialRow>& rows,
                                          const AnalysisSettings& settings);

struct SimulationSettings {
  int sessions = 100;
  std::uint64_t seed = 1;  // session k uses the k-th output of SplitMix64(seed)
  PsychometricFunction observer;
  std::vector<std::string> methods;  // of adaptive_methods()
  int replicates = 200;              // bootstrap refits per condition and session
  double late_fraction = 0.0;        // presentations flagged late
  ErrorDisplay display;              // requested -> shown error; empty: shown = requested
};

// Per condition and method, over the simulated sessions.
struct SimulationSummary {
  std::string condition, method;
  int sessions = 0;
  double recovered_within_10pct = 0.0;     // fraction with |fit / true - 1| <= 0.1
  double ci_coverage = 0.0;                // fraction whose 95 % interval holds the true threshold
  double median_trials = 0.0;              // answered trials per condition and session
  double median_threshold_px = 0.0;        // of the fits
  double median_method_estimate_px = 0.0;  // of the method's own estimates
  int late_presentations = 0;              // over all sessions
};

// Runs settings.sessions sessions of `study` for each method with the simulated observer and
// analyses each condition as analyse_group does (the study's assumed slope and lapse).
std::vector<SimulationSummary> simulate_study(const Study& study,
                                              const SimulationSettings& settings);

}  // namespace oflab
