// The per-trial CSV of a threshold study (manual/study.md): one row per presentation, late ones
// included, with everything the analysis needs, so CSVs of many observers can be merged into a
// class table. Plain C++ (the file is written through analysis/formats/atomic_file.h: whole
// or not at all).
//
//   study,observer,condition,policy,speed_deg_s,texture,viewing_distance_cm,ppi,method,
//   trial,requested_px,measured_px,distorted_first,correct,late
#pragma once

#include <iosfwd>
#include <stdexcept>
#include <string>
#include <vector>

#include "formats/atomic_file.h"
#include "study/study_session.h"

namespace oflab {

// One presentation with its condition spelled out.
struct TrialRow {
  std::string study;
  std::string observer;  // who answered (a name or code the class chooses; no commas)
  std::string condition;
  std::string policy;  // study_policy_name
  double speed_deg_s = 0.0;
  std::string texture;  // study_texture_name
  double viewing_distance_cm = 0.0;
  double ppi = 0.0;  // the screen's pixels per inch
  std::string method;
  int trial = 0;
  double requested_px = 0.0;
  double measured_px = 0.0;
  bool distorted_first = false;
  bool correct = false;
  bool late = false;
};

// Thrown for a CSV that cannot be used: "FILE: line 7: column 'measured_px': 'x' is not a
// number".
class TrialCsvError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The rows of `session`'s trials, answered by `observer` on a screen of `ppi` (> 0).
std::vector<TrialRow> trial_rows(const StudySession& session, const std::string& observer,
                                 double ppi);
std::vector<TrialRow> trial_rows(const Study& study, const std::string& method,
                                 const std::vector<StudyTrial>& trials, const std::string& observer,
                                 double ppi);

// The CSV text of `rows`, the header first; numbers with up to 17 significant digits (they
// read back exactly).
std::string trial_csv_text(const std::vector<TrialRow>& rows);

// Writes trial_csv_text(rows) to `path` whole or not at all (formats/atomic_file.h): an
// existing file is replaced only with Overwrite::kReplace. Throws FileWriteError naming it.
void write_trial_csv(const std::string& path, const std::vector<TrialRow>& rows,
                     Overwrite overwrite);

// The rows of the CSV text `text` read from `origin` (a file name, for messages): the header
// must be the one above; every field is checked (numbers finite, within the study limits,
// flags 0 or 1, text without commas). At most kMaxTrialRows rows. Throws TrialCsvError.
constexpr int kMaxTrialRows = 1000000;
std::vector<TrialRow> parse_trial_csv(const std::string& text, const std::string& origin);
// The same for the file at `path` (at most 64 MiB).
std::vector<TrialRow> read_trial_csv(const std::string& path);

}  // namespace oflab
