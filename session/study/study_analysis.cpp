#include "study/study_analysis.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace oflab {
namespace {

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Arcminutes for the result when every row shares a screen and distance.
void add_arcmin(const std::vector<TrialRow>& rows, ThresholdResult& r) {
  for (const TrialRow& row : rows) {
    if (row.ppi != rows[0].ppi || row.viewing_distance_cm != rows[0].viewing_distance_cm) return;
  }
  const double ppi = rows[0].ppi, cm = rows[0].viewing_distance_cm;
  r.threshold_arcmin = arcmin_of_pixels(r.threshold_px, ppi, cm);
  r.low_arcmin = arcmin_of_pixels(r.low_px, ppi, cm);
  r.high_arcmin = arcmin_of_pixels(r.high_px, ppi, cm);
}

}  // namespace

ThresholdResult analyse_group(const std::vector<TrialRow>& rows, const AnalysisSettings& settings) {
  ThresholdResult r;
  r.study = rows.front().study, r.observer = rows.front().observer;
  r.condition = rows.front().condition, r.method = rows.front().method;
  std::vector<TrialOutcome> outcomes;
  int correct = 0;
  for (const TrialRow& row : rows) {
    if (row.late) {
      ++r.late;
      continue;
    }
    outcomes.push_back({row.measured_px, row.correct});
    correct += row.correct;
  }
  r.trials = int(outcomes.size());
  r.proportion_correct = r.trials ? double(correct) / r.trials : 0.0;
  if (outcomes.empty()) return r;
  const ThresholdFit fit = fit_threshold(outcomes, settings.fit);
  StudyRandom random(settings.seed);
  const ThresholdInterval ci = bootstrap_interval(outcomes, fit.threshold_px, settings.fit,
                                                  settings.replicates, settings.level, random);
  r.threshold_px = fit.threshold_px, r.at_bound = fit.at_bound;
  r.low_px = ci.low_px, r.high_px = ci.high_px;
  add_arcmin(rows, r);
  return r;
}

std::vector<ThresholdResult> analyse_rows(const std::vector<TrialRow>& rows,
                                          const AnalysisSettings& settings) {
  using Key = std::tuple<std::string, std::string, std::string, std::string>;
  std::vector<Key> order, class_order;
  std::map<Key, std::vector<TrialRow>> groups, pooled;
  std::map<std::string, int> observers;
  for (const TrialRow& row : rows) {
    const Key key{row.study, row.observer, row.condition, row.method};
    const Key class_key{row.study, "", row.condition, row.method};
    if (!groups.count(key)) order.push_back(key);
    if (!pooled.count(class_key)) class_order.push_back(class_key);
    groups[key].push_back(row);
    pooled[class_key].push_back(row);
    observers[row.observer] = 1;
  }
  std::vector<ThresholdResult> results;
  for (const Key& key : order) results.push_back(analyse_group(groups[key], settings));
  if (observers.size() < 2) return results;
  for (const Key& key : class_order) {
    ThresholdResult r = analyse_group(pooled[key], settings);
    r.observer = "";
    results.push_back(r);
  }
  return results;
}

std::vector<SimulationSummary> simulate_study(const Study& study,
                                              const SimulationSettings& settings) {
  const ErrorDisplay shown_as_requested = [](int, double requested) { return requested; };
  const ErrorDisplay& display = settings.display ? settings.display : shown_as_requested;
  AnalysisSettings analysis;
  analysis.fit.slope = study.assumed_slope, analysis.fit.lapse = study.assumed_lapse;
  analysis.replicates = settings.replicates;
  const double truth = settings.observer.threshold_px;
  std::vector<SimulationSummary> summaries;
  for (const std::string& method : settings.methods) {
    const size_t first = summaries.size();
    std::vector<std::vector<double>> trials(study.conditions.size()), fits(trials.size()),
        own(trials.size());
    for (size_t c = 0; c < study.conditions.size(); ++c) {
      summaries.push_back({study.conditions[c].name, method});
    }
    SplitMix64 seeds(settings.seed);
    for (int s = 0; s < settings.sessions; ++s) {
      const std::uint64_t seed = seeds.next();
      StudySession session(study, method, seed);
      simulate_answers(session, seed, settings.observer, display, settings.late_fraction);
      const std::vector<TrialRow> rows = trial_rows(session, "simulated", 96.0);
      for (size_t c = 0; c < study.conditions.size(); ++c) {
        std::vector<TrialRow> group;
        for (const TrialRow& row : rows) {
          if (row.condition == study.conditions[c].name) group.push_back(row);
        }
        analysis.seed = seed + c;
        const ThresholdResult r = analyse_group(group, analysis);
        SimulationSummary& sum = summaries[first + c];
        sum.recovered_within_10pct += std::abs(r.threshold_px / truth - 1.0) <= 0.1;
        sum.ci_coverage += r.low_px <= truth && truth <= r.high_px;
        sum.late_presentations += r.late;
        trials[c].push_back(r.trials);
        fits[c].push_back(r.threshold_px);
        own[c].push_back(session.method(int(c)).estimate_px());
      }
    }
    for (size_t c = 0; c < study.conditions.size(); ++c) {
      SimulationSummary& sum = summaries[first + c];
      sum.sessions = settings.sessions;
      sum.recovered_within_10pct /= settings.sessions;
      sum.ci_coverage /= settings.sessions;
      sum.median_trials = median(trials[c]);
      sum.median_threshold_px = median(fits[c]);
      sum.median_method_estimate_px = median(own[c]);
    }
  }
  return summaries;
}

AnalysisSettings analysis_settings(const Study& study) {
  AnalysisSettings settings;
  settings.fit.slope = study.assumed_slope;
  settings.fit.lapse = study.assumed_lapse;
  return settings;
}

Study study_of_rows(const std::vector<TrialRow>& rows) {
  try {
    return find_or_read_study(rows.front().study);
  } catch (const StudyError&) {  // not shipped, no such file here: made from the rows
  }
  Study study;
  study.name = study.title = rows.front().study;
  study.conditions.clear();
  for (const TrialRow& r : rows) {
    study.min_px = std::min(study.min_px, r.measured_px > 0.0 ? r.measured_px : study.min_px);
    study.max_px = std::max(study.max_px, r.measured_px);
    const bool known = std::any_of(study.conditions.begin(), study.conditions.end(),
                                   [&](const StudyCondition& c) { return c.name == r.condition; });
    if (!known) {
      StudyCondition c;
      c.name = r.condition;
      c.speed_deg_s = r.speed_deg_s;
      c.viewing_distance_cm = r.viewing_distance_cm;
      c.policy = r.policy == "affine" ? StudyPolicy::kAffine : StudyPolicy::kPerspective;
      c.texture = r.texture == "grating" ? StudyTexture::kGrating : StudyTexture::kButterfly;
      study.conditions.push_back(c);
    }
  }
  return study;
}

nlohmann::ordered_json threshold_result_json(const ThresholdResult& r) {
  using nlohmann::ordered_json;
  const auto optional = [](const std::optional<double>& v) {
    return v ? ordered_json(*v) : ordered_json(nullptr);
  };
  return {{"study", r.study},
          {"observer", r.observer.empty() ? ordered_json(nullptr) : ordered_json(r.observer)},
          {"condition", r.condition},
          {"method", r.method},
          {"trials", r.trials},
          {"late", r.late},
          {"proportion_correct", r.proportion_correct},
          {"threshold_px", r.threshold_px},
          {"ci95_px", {r.low_px, r.high_px}},
          {"at_bound", r.at_bound},
          {"threshold_arcmin", optional(r.threshold_arcmin)},
          {"ci95_arcmin", {optional(r.low_arcmin), optional(r.high_arcmin)}}};
}

}  // namespace oflab
