// The per-trial CSV (session/study/trial_csv.h): a session's rows written and read back
// exactly, written whole or not at all (never over an existing file without replacing), and
// bad rows refused naming the file, the line and the column.
#include "study/trial_csv.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "study/study_analysis.h"

namespace oflab {
namespace {

namespace fs = std::filesystem;

std::vector<TrialRow> session_rows() {
  Study s;
  s.name = "t";
  s.trials = 6;
  s.conditions = {StudyCondition{"near"}, StudyCondition{"far", StudyPolicy::kPerspective, 45.5,
                                                         StudyTexture::kGrating, 100.0}};
  StudySession session(s, "quest+", 5);
  simulate_answers(
      session, 5, PsychometricFunction{0.7, 3.5, 0.02},
      [](int, double requested) { return requested * 1.0373; }, 0.2);
  return trial_rows(session, "ann", 109.2);
}

TEST(TrialCsv, RowsReadBackExactly) {
  const std::vector<TrialRow> rows = session_rows();
  const std::vector<TrialRow> back = parse_trial_csv(trial_csv_text(rows), "x.csv");
  ASSERT_EQ(back.size(), rows.size());
  for (size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(back[i].study, rows[i].study);
    EXPECT_EQ(back[i].observer, "ann");
    EXPECT_EQ(back[i].condition, rows[i].condition);
    EXPECT_EQ(back[i].policy, rows[i].policy);
    EXPECT_EQ(back[i].texture, rows[i].texture);
    EXPECT_EQ(back[i].speed_deg_s, rows[i].speed_deg_s);
    EXPECT_EQ(back[i].viewing_distance_cm, rows[i].viewing_distance_cm);
    EXPECT_EQ(back[i].ppi, 109.2);
    EXPECT_EQ(back[i].method, "quest+");
    EXPECT_EQ(back[i].trial, rows[i].trial);
    EXPECT_EQ(back[i].requested_px, rows[i].requested_px);
    EXPECT_EQ(back[i].measured_px, rows[i].measured_px);
    EXPECT_EQ(back[i].distorted_first, rows[i].distorted_first);
    EXPECT_EQ(back[i].correct, rows[i].correct);
    EXPECT_EQ(back[i].late, rows[i].late);
  }
  EXPECT_EQ(trial_csv_text(back), trial_csv_text(rows));
}

TEST(TrialCsv, AFileIsWrittenWholeAndNeverReplacedUnasked) {
  const fs::path dir = fs::temp_directory_path() / ("oflab-trials-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string path = (dir / "a.csv").string();
  const std::vector<TrialRow> rows = session_rows();
  write_trial_csv(path, rows, Overwrite::kRefuse);
  EXPECT_EQ(read_trial_csv(path).size(), rows.size());
  EXPECT_THROW(write_trial_csv(path, {}, Overwrite::kRefuse), FileWriteError);
  EXPECT_EQ(read_trial_csv(path).size(), rows.size());  // untouched
  write_trial_csv(path, {rows[0]}, Overwrite::kReplace);
  EXPECT_EQ(read_trial_csv(path).size(), 1u);
  size_t files = 0;
  for (const auto& entry : fs::directory_iterator(dir)) files += entry.is_regular_file();
  EXPECT_EQ(files, 1u);  // no temporary left beside it
  fs::remove_all(dir);
}

TEST(TrialCsv, BadRowsAreRefusedNamingTheLineAndTheColumn) {
  const std::string text = trial_csv_text({session_rows()[0]});
  const std::string header = text.substr(0, text.find('\n') + 1);
  const std::string row = text.substr(header.size());
  const auto error = [&](const std::string& body) {
    try {
      parse_trial_csv(body, "class/ann.csv");
    } catch (const TrialCsvError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(error(text), "");
  EXPECT_EQ(error("a,b\n"),
            "class/ann.csv: line 1: the header must be: " + header.substr(0, header.size() - 1));
  std::string bad = row;
  bad.replace(bad.find(",quest+,") + 8, 1, "x");  // the trial number
  EXPECT_EQ(error(header + row + bad),
            "class/ann.csv: line 3: column 'trial': 'x' is not a number");
  EXPECT_EQ(error(header + "a,b,c\n"), "class/ann.csv: line 2: 3 columns, not 15");
  std::string flag = row;
  flag.replace(flag.size() - 2, 1, "2");  // late
  EXPECT_EQ(error(header + flag), "class/ann.csv: line 2: column 'late': '2' must be 0 or 1");
  // Column 5 (speed_deg_s) out of the study limit.
  std::string fast = row;
  const size_t at = [&] {
    size_t p = 0;
    for (int i = 0; i < 4; ++i) p = fast.find(',', p) + 1;
    return p;
  }();
  fast.replace(at, fast.find(',', at) - at, "900");
  EXPECT_EQ(error(header + fast),
            "class/ann.csv: line 2: column 'speed_deg_s': 900 is outside 1..360 deg/s");
}

// The study of a CSV's rows: the shipped study of that name, else one made from the rows
// (their conditions in order, the error range holding every measured error); a study's
// analysis settings are its assumed slope and lapse.
TEST(TrialCsv, TheStudyOfRowsIsTheShippedOneOrMadeFromThem) {
  std::vector<TrialRow> rows = session_rows();
  const Study made = study_of_rows(rows);
  EXPECT_EQ(made.name, "t");
  ASSERT_EQ(made.conditions.size(), 2u);
  const size_t far = made.conditions[0].name == "far" ? 0 : 1;
  EXPECT_EQ(made.conditions[far].name, "far");
  EXPECT_EQ(made.conditions[0].name, rows.front().condition);  // in the order first met
  EXPECT_EQ(made.conditions[1 - far].name, "near");
  EXPECT_EQ(made.conditions[far].speed_deg_s, 45.5);
  EXPECT_EQ(made.conditions[far].texture, StudyTexture::kGrating);
  for (const TrialRow& r : rows) {
    EXPECT_LE(made.min_px, r.measured_px);
    EXPECT_GE(made.max_px, r.measured_px);
  }
  for (TrialRow& r : rows) r.study = "class";
  const Study shipped = study_of_rows(rows);
  EXPECT_EQ(shipped.title, find_or_read_study("class").title);
  Study s;
  s.assumed_slope = 5.0;
  s.assumed_lapse = 0.01;
  EXPECT_EQ(analysis_settings(s).fit.slope, 5.0);
  EXPECT_EQ(analysis_settings(s).fit.lapse, 0.01);
}

}  // namespace
}  // namespace oflab
