#include "web_study.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "study/study_analysis.h"

namespace oflab {
namespace {

using nlohmann::ordered_json;

ordered_json study_summary(const Study& s) {
  ordered_json conditions = ordered_json::array();
  for (const StudyCondition& c : s.conditions) conditions.push_back(c.name);
  return {{"name", s.name},
          {"title", s.title},
          {"description", s.description},
          {"method", s.method},
          {"trials", s.trials},
          {"min_px", s.min_px},
          {"max_px", s.max_px},
          {"assumed_slope", s.assumed_slope},
          {"assumed_lapse", s.assumed_lapse},
          {"conditions", conditions}};
}

// A study file's text read as the file `name` would be: written to the module's file system
// and read there, so its messages name the file as the desktop's do.
Study read_study_text(const std::string& name, const std::string& text) {
  const std::string path = "/tmp/" + name;
  {
    std::ofstream out(path, std::ios::binary);
    out << text;
  }
  try {
    Study study = read_study_file(path);
    std::remove(path.c_str());
    return study;
  } catch (...) {
    std::remove(path.c_str());
    throw;
  }
}

std::string without_folder(const std::string& message) {
  return message.rfind("/tmp/", 0) == 0 ? message.substr(5) : message;
}

}  // namespace

std::string WebStudy::shipped_json() {
  ordered_json out = ordered_json::array();
  for (const std::string& name : shipped_study_names()) {
    out.push_back(study_summary(find_or_read_study(name)));
  }
  return out.dump();
}

std::string WebStudy::open(const std::string& name, const std::string& file_text,
                           const std::string& method, double seed) {
  try {
    const Study study =
        file_text.empty() ? find_or_read_study(name) : read_study_text(name, file_text);
    const std::uint64_t s = seed < 0.0 ? study.seed : std::uint64_t(seed);
    auto runner = std::make_unique<TrialRunner>(study, method.empty() ? study.method : method, s);
    runner_ = std::move(runner);
    seed_ = s;
    shown_ = std::make_unique<Study>(study);
  } catch (const std::exception& e) {
    return without_folder(e.what());
  }
  return "";
}

std::string WebStudy::request_json() const {
  if (finished()) return "{}";
  const StudySession& s = runner_->session();
  const int answered = s.answered_trials();
  return ordered_json{{"condition", s.study().conditions[size_t(s.request().condition)].name},
                      {"answered", answered},
                      {"total", s.study().trials * int(s.study().conditions.size())},
                      {"late", s.late_trials()}}
      .dump();
}

int WebStudy::clip_length() const { return int(std::lround(kClipSeconds * kClipFrameRate)); }

const std::vector<Pixel>& WebStudy::clip_frame(int clip, int frame) {
  static const std::vector<Pixel> kNone;
  if (finished() || frame < 0 || frame >= clip_length()) return kNone;
  const TrialClips& clips = runner_->clips();
  const std::vector<Image>& frames = clip == 1 ? clips.first : clips.second;
  return frames.at(size_t(frame)).pixels();
}

std::string WebStudy::answer(int chosen, bool late) {
  if (finished()) return "the study has finished";
  try {
    runner_->answer(chosen, late);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

std::string WebStudy::simulate(double threshold_px) {
  if (!runner_) return "no study is open";
  const Study& study = runner_->session().study();
  if (!(threshold_px >= study.min_px && threshold_px <= study.max_px)) {
    return "the simulated observer's threshold must be within the study's error range";
  }
  SimulatedObserver observer(
      seed_, PsychometricFunction{threshold_px, study.assumed_slope, study.assumed_lapse});
  run_simulated(*runner_, observer);
  return "";
}

std::string WebStudy::csv(const std::string& observer, double ppi) const {
  return runner_ ? trial_csv_text(trial_rows(runner_->session(), observer, ppi)) : "";
}

std::string WebStudy::results_json(const std::string& observer, double ppi) const {
  ordered_json out = ordered_json::array();
  if (!runner_) return out.dump();
  const std::vector<TrialRow> rows = trial_rows(runner_->session(), observer, ppi);
  if (std::none_of(rows.begin(), rows.end(), [](const TrialRow& r) { return !r.late; })) {
    return out.dump();  // nothing answered yet: nothing to fit
  }
  const AnalysisSettings settings = analysis_settings(runner_->session().study());
  for (const ThresholdResult& result : analyse_rows(rows, settings)) {
    out.push_back(threshold_result_json(result));
  }
  return out.dump();
}

std::string WebStudy::class_results_json(const std::string& files_json) {
  std::vector<TrialRow> rows;
  try {
    for (const auto& file : nlohmann::json::parse(files_json)) {
      const std::vector<TrialRow> more =
          parse_trial_csv(file.at("text").get<std::string>(), file.at("name").get<std::string>());
      rows.insert(rows.end(), more.begin(), more.end());
    }
  } catch (const std::exception& e) {
    return ordered_json{{"problem", e.what()}}.dump();
  }
  if (rows.empty()) return ordered_json{{"problem", "the files hold no trials"}}.dump();
  const Study study = study_of_rows(rows);
  ordered_json results = ordered_json::array();
  if (std::any_of(rows.begin(), rows.end(), [](const TrialRow& r) { return !r.late; })) {
    for (const ThresholdResult& r : analyse_rows(rows, analysis_settings(study))) {
      results.push_back(threshold_result_json(r));
    }
  }
  shown_ = std::make_unique<Study>(study);
  return ordered_json{{"study", study_summary(study)}, {"results", results}}.dump();
}

std::vector<double> WebStudy::curve(double threshold_px, int n) const {
  std::vector<double> p;
  if (!shown_ || !(threshold_px > 0.0)) return p;
  const Study& s = *shown_;
  const PsychometricFunction f{threshold_px, s.assumed_slope, s.assumed_lapse};
  n = std::clamp(n, 2, 1000);
  for (int i = 0; i < n; ++i) {
    p.push_back(f.correct(s.min_px * std::pow(s.max_px / s.min_px, double(i) / (n - 1))));
  }
  return p;
}

std::string WebStudy::study_json() const {
  return runner_ ? study_summary(runner_->session().study()).dump() : "{}";
}

}  // namespace oflab
