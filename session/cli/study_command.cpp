#include "cli/study_command.h"

#include <iomanip>
#include <nlohmann/json.hpp>
#include <ostream>

#include "cli/cli_args.h"
#include "study/adaptive_methods.h"
#include "study/engine_display.h"
#include "study/study_analysis.h"
#include "study/study_file.h"
#include "study/trial_csv.h"

namespace oflab {
namespace {

using nlohmann::ordered_json;

constexpr const char* kUsage =
    "oflab-cli study list | simulate --study NAME|FILE --observer-threshold PX "
    "[--observer-slope S] [--observer-lapse L] [--sessions N] [--seed S] [--method M|all] "
    "[--replicates B] [--late-fraction F] [--shown engine|requested] [--json] | session --study "
    "NAME|FILE "
    "--observer-threshold PX --csv FILE [--observer NAME] [--method M] [--seed S] [--ppi P] "
    "[--force] | analyse CSV... [--replicates B] [--seed S] [--slope S] [--lapse L] [--json] | "
    "ladder --study NAME|FILE [--json]";

inline constexpr Limit kSessions{"sessions", "", 1.0, 100000.0, true};
inline constexpr Limit kReplicates{"bootstrap replicates", "", 20.0, 100000.0, true};
inline constexpr Limit kObserverLapse{"observer lapse", "", 0.0, 0.2};
inline constexpr Limit kLateFraction{"late fraction", "", 0.0, 0.9};

CommandArgs options_after(const CommandArgs& args, size_t first) {
  return CommandArgs(args.begin() + long(std::min(first, args.size())), args.end());
}

Study study_argument(const CliArgs& a) {
  try {
    return find_or_read_study(a.values("--study").front());
  } catch (const StudyError& e) {
    throw UsageError(e.what());
  }
}

PsychometricFunction observer_argument(const CliArgs& a, const Study& study) {
  PsychometricFunction f;
  f.threshold_px = a.number_in("--observer-threshold", study_limits::kErrorPx);
  f.slope = a.has("--observer-slope") ? a.number_in("--observer-slope", study_limits::kSlope)
                                      : study.assumed_slope;
  f.lapse = a.has("--observer-lapse") ? a.number_in("--observer-lapse", kObserverLapse)
                                      : study.assumed_lapse;
  if (f.threshold_px < study.min_px || f.threshold_px > study.max_px) {
    throw UsageError("--observer-threshold: " + std::to_string(f.threshold_px) +
                     " px is outside the study's error range");
  }
  return f;
}

std::uint64_t seed_argument(const CliArgs& a, std::uint64_t fallback) {
  return a.has("--seed") ? std::uint64_t(a.number_in("--seed", study_limits::kSeed)) : fallback;
}

std::vector<std::string> methods_argument(const CliArgs& a, const std::string& fallback) {
  const std::string name = a.text_or("--method", fallback);
  std::vector<std::string> methods;
  for (const AdaptiveMethodKind& kind : adaptive_methods()) {
    if (name == "all" || name == kind.name) methods.push_back(kind.name);
  }
  if (methods.empty()) {
    throw UsageError("--method: '" + name + "' is not one of " + adaptive_method_names() + ", all");
  }
  return methods;
}

int list(std::ostream& out) {
  for (const std::string& name : shipped_study_names()) {
    const Study s = find_or_read_study(name);
    out << std::left << std::setw(24) << s.name << " " << std::setw(10) << s.method << " trials "
        << std::setw(4) << s.trials << " conditions " << std::setw(3) << s.conditions.size() << " "
        << s.title << "\n";
  }
  return 0;
}

// The settings of `simulate` from its options; `shown` receives how errors are shown.
SimulationSettings simulation_settings(const CliArgs& a, const Study& study, std::string* shown) {
  *shown = a.text_or("--shown", "engine");
  if (*shown != "engine" && *shown != "requested") {
    throw UsageError("--shown: '" + *shown + "' is not one of engine, requested");
  }
  SimulationSettings s;
  s.observer = observer_argument(a, study);
  s.sessions = a.has("--sessions") ? a.integer_in("--sessions", kSessions) : 100;
  s.seed = seed_argument(a, study.seed);
  s.methods = methods_argument(a, "all");
  s.replicates = a.has("--replicates") ? a.integer_in("--replicates", kReplicates) : 200;
  s.late_fraction = a.has("--late-fraction") ? a.number_in("--late-fraction", kLateFraction) : 0.0;
  if (*shown == "engine") s.display = engine_error_display(study);
  return s;
}

ordered_json simulation_json(const Study& study, const SimulationSettings& s,
                             const std::string& shown,
                             const std::vector<SimulationSummary>& results) {
  ordered_json j = {{"study", study.name},
                    {"sessions", s.sessions},
                    {"seed", s.seed},
                    {"observer",
                     {{"threshold_px", s.observer.threshold_px},
                      {"slope", s.observer.slope},
                      {"lapse", s.observer.lapse}}},
                    {"shown_error", shown == "engine" ? "measured by the engine" : "as requested"},
                    {"bootstrap_replicates", s.replicates},
                    {"results", ordered_json::array()}};
  for (const SimulationSummary& r : results) {
    j["results"].push_back({{"condition", r.condition},
                            {"method", r.method},
                            {"recovered_within_10pct", r.recovered_within_10pct},
                            {"ci_coverage", r.ci_coverage},
                            {"median_trials", r.median_trials},
                            {"median_threshold_px", r.median_threshold_px},
                            {"median_method_estimate_px", r.median_method_estimate_px},
                            {"late_presentations", r.late_presentations}});
  }
  return j;
}

int simulate(const CommandArgs& args, std::ostream& out) {
  const CliArgs a(options_after(args, 1), {{"--study", 1},
                                           {"--observer-threshold", 1},
                                           {"--observer-slope", 1},
                                           {"--observer-lapse", 1},
                                           {"--sessions", 1},
                                           {"--seed", 1},
                                           {"--method", 1},
                                           {"--replicates", 1},
                                           {"--late-fraction", 1},
                                           {"--shown", 1},
                                           {"--json", 0}});
  const Study study = study_argument(a);
  std::string shown;
  const SimulationSettings s = simulation_settings(a, study, &shown);
  const std::vector<SimulationSummary> results = simulate_study(study, s);
  if (a.has("--json")) {
    out << simulation_json(study, s, shown, results).dump(2) << "\n";
    return 0;
  }
  out << "study " << study.name << ": " << s.sessions << " simulated sessions, observer threshold "
      << s.observer.threshold_px << " px (slope " << s.observer.slope << ", lapse "
      << s.observer.lapse << "), errors shown "
      << (shown == "engine" ? "by the engine" : "as requested") << "\n";
  for (const SimulationSummary& r : results) {
    out << std::left << std::setw(22) << r.condition << " " << std::setw(10) << r.method
        << " within 10 %: " << std::setw(6) << r.recovered_within_10pct
        << " CI coverage: " << std::setw(6) << r.ci_coverage
        << " median trials: " << r.median_trials << "\n";
  }
  return 0;
}

int session(const CommandArgs& args, std::ostream& out) {
  const CliArgs a(options_after(args, 1), {{"--study", 1},
                                           {"--observer-threshold", 1},
                                           {"--observer-slope", 1},
                                           {"--observer-lapse", 1},
                                           {"--csv", 1},
                                           {"--observer", 1},
                                           {"--method", 1},
                                           {"--seed", 1},
                                           {"--ppi", 1},
                                           {"--force", 0}});
  const Study study = study_argument(a);
  const PsychometricFunction observer = observer_argument(a, study);
  const std::string csv = a.values("--csv").front();
  const Overwrite overwrite = check_out_file("--csv", csv, a.has("--force"));
  const std::string name = a.text_or("--observer", "simulated");
  if (name.empty() || name.find_first_of(",\n\r") != std::string::npos) {
    throw UsageError("--observer: a name without commas or line breaks");
  }
  const std::string method = methods_argument(a, study.method).front();
  const std::uint64_t seed = seed_argument(a, study.seed);
  const double ppi = a.has("--ppi") ? a.number_in("--ppi", study_limits::kPpi) : 96.0;
  StudySession run(study, method, seed);
  simulate_answers(run, seed, observer, engine_error_display(study));
  write_trial_csv(csv, trial_rows(run, name, ppi), overwrite);
  out << "wrote " << csv << ": " << run.trials().size() << " trials of " << study.name << " ("
      << method << ", seed " << seed << ")\n";
  return 0;
}

int analyse(const CommandArgs& args, std::ostream& out) {
  size_t files = 1;
  while (files < args.size() && args[files].rfind("--", 0) != 0) ++files;
  if (files == 1) throw UsageError("study analyse: give one or more per-trial CSV files");
  const CliArgs a(
      options_after(args, files),
      {{"--replicates", 1}, {"--seed", 1}, {"--slope", 1}, {"--lapse", 1}, {"--json", 0}});
  AnalysisSettings settings;
  if (a.has("--replicates")) settings.replicates = a.integer_in("--replicates", kReplicates);
  settings.seed = seed_argument(a, 1);
  if (a.has("--slope")) settings.fit.slope = a.number_in("--slope", study_limits::kSlope);
  if (a.has("--lapse")) settings.fit.lapse = a.number_in("--lapse", study_limits::kLapse);
  std::vector<TrialRow> rows;
  try {
    for (size_t i = 1; i < files; ++i) {
      const std::vector<TrialRow> more = read_trial_csv(args[i]);
      rows.insert(rows.end(), more.begin(), more.end());
    }
  } catch (const TrialCsvError& e) {
    throw UsageError(e.what());
  }
  const std::vector<ThresholdResult> results = analyse_rows(rows, settings);
  if (a.has("--json")) {
    ordered_json j = {{"files", files - 1},
                      {"rows", rows.size()},
                      {"fit",
                       {{"slope", settings.fit.slope},
                        {"lapse", settings.fit.lapse},
                        {"bootstrap", "parametric"},
                        {"replicates", settings.replicates}}},
                      {"results", ordered_json::array()}};
    for (const ThresholdResult& r : results) j["results"].push_back(threshold_result_json(r));
    out << j.dump(2) << "\n";
    return 0;
  }
  for (const ThresholdResult& r : results) {
    out << std::left << std::setw(14) << (r.observer.empty() ? "(class)" : r.observer) << " "
        << std::setw(22) << r.condition << " " << std::setw(10) << r.method << " trials "
        << std::setw(4) << r.trials << " threshold " << r.threshold_px << " px [" << r.low_px
        << ", " << r.high_px << "]";
    if (r.threshold_arcmin) out << " = " << *r.threshold_arcmin << " arcmin";
    out << (r.at_bound ? " (at the fit's bound)" : "") << "\n";
  }
  return 0;
}

// Each condition's ladder: the thresholds and the errors the engine measured at them.
int ladder(const CommandArgs& args, std::ostream& out) {
  const CliArgs a(options_after(args, 1), {{"--study", 1}, {"--json", 0}});
  const Study study = study_argument(a);
  ordered_json j = {{"study", study.name}, {"conditions", ordered_json::array()}};
  for (const StudyCondition& c : study.conditions) {
    const ErrorLadder l = play_error_ladder(c, study.min_px, study.max_px, kLadderSteps);
    j["conditions"].push_back(
        {{"condition", c.name}, {"threshold_px", l.thresholds_px}, {"measured_px", l.measured_px}});
    if (a.has("--json")) continue;
    out << c.name << " (" << study_policy_name(c.policy) << ", " << c.speed_deg_s << " deg/s)\n";
    for (size_t i = 0; i < l.thresholds_px.size(); ++i) {
      out << "  threshold " << std::setw(10) << l.thresholds_px[i] << " px  measured "
          << l.measured_px[i] << " px\n";
    }
  }
  if (a.has("--json")) out << j.dump(2) << "\n";
  return 0;
}

}  // namespace

Command study_command() {
  return {"study", "threshold studies headless: simulated observers, per-trial CSVs, analysis",
          kUsage, run_study_command};
}

int run_study_command(const CommandArgs& args, std::ostream& out, std::ostream& /*err*/) {
  if (args.empty()) throw UsageError(std::string("give an action: ") + kUsage);
  const std::string& action = args[0];
  if (action == "list") {
    CliArgs(options_after(args, 1), {});
    return list(out);
  }
  if (action == "simulate") return simulate(args, out);
  if (action == "session") return session(args, out);
  if (action == "analyse") return analyse(args, out);
  if (action == "ladder") return ladder(args, out);
  throw UsageError("unknown action '" + action + "' (list, simulate, session, analyse, ladder)");
}

}  // namespace oflab
