#include "study/trial_csv.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "formats/json_fields.h"

namespace oflab {
namespace {

constexpr const char* kHeader =
    "study,observer,condition,policy,speed_deg_s,texture,viewing_distance_cm,ppi,method,trial,"
    "requested_px,measured_px,distorted_first,correct,late";
constexpr int kColumns = 15;

std::string number_text(double v) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, ',')) fields.push_back(field);
  if (!line.empty() && line.back() == ',') fields.push_back("");
  return fields;
}

// Where a field sits, for messages.
struct CsvPlace {
  const std::string& origin;
  int line;
  [[noreturn]] void fail(const std::string& column, const std::string& message) const {
    throw TrialCsvError(origin + ": line " + std::to_string(line) + ": column '" + column +
                        "': " + message);
  }
  double number(const std::string& column, const std::string& text, const Limit& limit) const {
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0') fail(column, "'" + text + "' is not a number");
    if (!limit.allows(v)) fail(column, limit.problem(v));
    return v;
  }
  bool flag(const std::string& column, const std::string& text) const {
    if (text != "0" && text != "1") fail(column, "'" + text + "' must be 0 or 1");
    return text == "1";
  }
  std::string name(const std::string& column, const std::string& text) const {
    if (text.empty()) fail(column, "is empty");
    return text;
  }
};

inline constexpr Limit kShownPx{"shown error", "px", 0.0, 1000.0};
inline constexpr Limit kPpi{"pixels per inch", "ppi", 10.0, 2000.0};
inline constexpr Limit kTrialNumber{"trial", "", 0.0, 1000000.0, true};

TrialRow parse_row(const std::vector<std::string>& f, const CsvPlace& at) {
  TrialRow r;
  r.study = at.name("study", f[0]);
  r.observer = at.name("observer", f[1]);
  r.condition = at.name("condition", f[2]);
  r.policy = at.name("policy", f[3]);
  r.speed_deg_s = at.number("speed_deg_s", f[4], study_limits::kSpeed);
  r.texture = at.name("texture", f[5]);
  r.viewing_distance_cm = at.number("viewing_distance_cm", f[6], study_limits::kViewingDistance);
  r.ppi = at.number("ppi", f[7], kPpi);
  r.method = at.name("method", f[8]);
  r.trial = int(at.number("trial", f[9], kTrialNumber));
  r.requested_px = at.number("requested_px", f[10], kShownPx);
  r.measured_px = at.number("measured_px", f[11], kShownPx);
  r.distorted_first = at.flag("distorted_first", f[12]);
  r.correct = at.flag("correct", f[13]);
  r.late = at.flag("late", f[14]);
  return r;
}

}  // namespace

std::vector<TrialRow> trial_rows(const Study& study, const std::string& method,
                                 const std::vector<StudyTrial>& trials, const std::string& observer,
                                 double ppi) {
  std::vector<TrialRow> rows;
  for (const StudyTrial& t : trials) {
    const StudyCondition& c = study.conditions[size_t(t.request.condition)];
    rows.push_back({study.name, observer, c.name, study_policy_name(c.policy), c.speed_deg_s,
                    study_texture_name(c.texture), c.viewing_distance_cm, ppi, method,
                    t.request.trial, t.request.requested_px, t.measured_px,
                    t.request.distorted_first, t.correct, t.late});
  }
  return rows;
}

std::vector<TrialRow> trial_rows(const StudySession& session, const std::string& observer,
                                 double ppi) {
  return trial_rows(session.study(), session.method_name(), session.trials(), observer, ppi);
}

std::string trial_csv_text(const std::vector<TrialRow>& rows) {
  std::string text = std::string(kHeader) + "\n";
  for (const TrialRow& r : rows) {
    text += r.study + "," + r.observer + "," + r.condition + "," + r.policy + "," +
            number_text(r.speed_deg_s) + "," + r.texture + "," +
            number_text(r.viewing_distance_cm) + "," + number_text(r.ppi) + "," + r.method + "," +
            std::to_string(r.trial) + "," + number_text(r.requested_px) + "," +
            number_text(r.measured_px) + "," + (r.distorted_first ? "1" : "0") + "," +
            (r.correct ? "1" : "0") + "," + (r.late ? "1" : "0") + "\n";
  }
  return text;
}

void write_trial_csv(const std::string& path, const std::vector<TrialRow>& rows,
                     Overwrite overwrite) {
  write_file_atomically(path, trial_csv_text(rows), overwrite);
}

std::vector<TrialRow> parse_trial_csv(const std::string& text, const std::string& origin) {
  std::istringstream in(text);
  std::string line;
  if (!std::getline(in, line) || line != kHeader) {
    throw TrialCsvError(origin + ": line 1: the header must be: " + kHeader);
  }
  std::vector<TrialRow> rows;
  for (int number = 2; std::getline(in, line); ++number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    const CsvPlace at{origin, number};
    if (int(rows.size()) >= kMaxTrialRows) {
      throw TrialCsvError(origin + ": line " + std::to_string(number) + ": more than " +
                          std::to_string(kMaxTrialRows) + " rows, the limit for trial files");
    }
    const std::vector<std::string> fields = split(line);
    if (int(fields.size()) != kColumns) {
      throw TrialCsvError(origin + ": line " + std::to_string(number) + ": " +
                          std::to_string(fields.size()) + " columns, not " +
                          std::to_string(kColumns));
    }
    rows.push_back(parse_row(fields, at));
  }
  return rows;
}

std::vector<TrialRow> read_trial_csv(const std::string& path) {
  return parse_trial_csv(json_fields::read_file_text<TrialCsvError>(path), path);
}

}  // namespace oflab
