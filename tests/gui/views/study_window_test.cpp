// The threshold study's window (gui/views/study_window.h): a simulated observer answering in
// it, through the buttons' answers, gives the trials of the headless simulation (oflab-cli
// study session) for the same study, method and seed; its results page fits what the analysis
// fits and becomes the main window's reuse threshold at a button; its CSV is written whole and
// never over a file without leave.
#include "views/study_window.h"

#include <gtest/gtest.h>

#include <QPushButton>
#include <QTableWidget>
#include <QTemporaryDir>
#include <fstream>
#include <sstream>

#include "app/main_window.h"
#include "models/window_model.h"

namespace oflab::test {
namespace {

Study short_study() {
  Study s;
  s.name = "short";
  s.title = "A short study";
  s.method = "staircase";
  s.trials = 5;
  s.seed = 5;
  s.conditions = {{"near", StudyPolicy::kPerspective, 30.0, StudyTexture::kGrating, 50.0}};
  return s;
}

TEST(StudyWindow, ASimulatedObserverInTheWindowAnswersAsTheHeadlessSimulation) {
  const Study study = short_study();
  MainWindow main;
  StudyWindow& window = *main.open_study_window();
  window.select_study(study);
  window.set_fields("staircase", "ann", 110.0, 5);
  const PsychometricFunction observer{0.8, study.assumed_slope, study.assumed_lapse};
  SimulatedObserver answers(5, observer);
  ASSERT_EQ(window.run_simulated(answers), "");

  StudySession headless(study, "staircase", 5);
  simulate_answers(headless, 5, observer, engine_error_display(study));
  EXPECT_EQ(trial_csv_text(window.rows()), trial_csv_text(trial_rows(headless, "ann", 110.0)));
  ASSERT_GE(window.rows().size(), 5u);

  // The results page: one row per condition with the analysis's threshold.
  const auto* table = window.findChild<QTableWidget*>();
  ASSERT_NE(table, nullptr);
  ASSERT_EQ(table->rowCount(), 1);
  const ThresholdResult fit = analyse_rows(window.rows(), AnalysisSettings{}).at(0);
  EXPECT_EQ(table->item(0, 0)->text(), "ann");
  EXPECT_TRUE(table->item(0, 3)->text().startsWith(QString::number(fit.threshold_px, 'f', 2)))
      << table->item(0, 3)->text().toStdString();

  // Its threshold becomes the main window's reuse threshold.
  EXPECT_EQ(window.smallest_threshold_px(), fit.threshold_px);
  for (QPushButton* b : window.findChildren<QPushButton*>()) {
    if (b->text().startsWith("Use ")) b->click();
  }
  for (double t : main.model()->state().settings.thresholds) EXPECT_EQ(t, fit.threshold_px);

  QTemporaryDir dir;
  const std::string path = dir.filePath("ann.csv").toStdString();
  EXPECT_EQ(window.write_csv(path, false), "");
  EXPECT_NE(window.write_csv(path, false), "");  // refused: the file exists
  std::stringstream written;
  written << std::ifstream(path).rdbuf();
  EXPECT_EQ(written.str(), trial_csv_text(window.rows()));
}

// Two observers' CSVs in the class view: a row per observer and the class's pooled row, the
// class's threshold the one offered; a broken CSV is refused naming the file and the line.
TEST(StudyWindow, TheClassViewMergesObserversAndRefusesABrokenFile) {
  const Study study = short_study();
  QTemporaryDir dir;
  std::vector<std::string> paths;
  for (const auto& [name, threshold] : {std::pair<std::string, double>{"ann", 0.6}, {"bob", 2.0}}) {
    StudySession run(study, "staircase", threshold > 1 ? 8 : 9);
    simulate_answers(run, 3, PsychometricFunction{threshold, 3.5, 0.02},
                     engine_error_display(study));
    paths.push_back(dir.filePath(QString::fromStdString(name + ".csv")).toStdString());
    write_trial_csv(paths.back(), trial_rows(run, name, 96.0), Overwrite::kRefuse);
  }
  StudyWindow window;
  ASSERT_EQ(window.show_class_results(paths), "");
  const auto* table = window.findChild<QTableWidget*>();
  ASSERT_EQ(table->rowCount(), 3);  // ann, bob, the class
  EXPECT_EQ(table->item(2, 0)->text(), "(class)");
  std::vector<TrialRow> rows = read_trial_csv(paths[0]);
  const std::vector<TrialRow> more = read_trial_csv(paths[1]);
  rows.insert(rows.end(), more.begin(), more.end());
  const ThresholdResult pooled = analyse_rows(rows, AnalysisSettings{}).at(2);
  EXPECT_EQ(pooled.observer, "");
  EXPECT_EQ(window.smallest_threshold_px(), pooled.threshold_px);

  const std::string broken = dir.filePath("broken.csv").toStdString();
  std::ofstream(broken) << "study,observer\nx,y\n";
  const std::string problem = window.show_class_results({paths[0], broken});
  EXPECT_NE(problem.find("broken.csv"), std::string::npos) << problem;
  EXPECT_EQ(table->rowCount(), 3);  // the class view stays
}

TEST(StudyWindow, ANameWithACommaCannotStart) {
  StudyWindow window;
  window.select_study(short_study());
  window.set_fields("staircase", "ann, bob", 96.0, 1);
  StudyChoice choice;
  EXPECT_NE(window.read_choice(&choice), "");
  SimulatedObserver answers(1, PsychometricFunction{});
  EXPECT_NE(window.run_simulated(answers), "");
  EXPECT_EQ(window.session(), nullptr);
}

}  // namespace
}  // namespace oflab::test
