// The threshold study in the desktop window (manual/study.md): a window of three pages. Set
// up: the study (shipped or a file), the method, the observer's name, the screen's pixels per
// inch (typed, or measured by matching a bar to a credit card) and the seed. Trials: the two
// clips of each request (session/study/trial_clips.h TrialRunner) played one after the other
// on the paced clock at kClipFrameRate, one clip pixel to one screen pixel, then "which was
// distorted?" (buttons 1 and 2, or the keys 1 and 2). A presentation with a late frame (the
// clock passed a frame before it was drawn) is recorded late and shown again; before the first
// trial the window plays a second of frames and refuses to start when any is late, saying how
// many were. Results: the threshold and its 95 % interval per condition in pixels and minutes
// of arc (session/study/study_analysis.h), the psychometric function over the answers, and the
// per-trial CSV (written whole, an existing file replaced only when the file dialog asked);
// and the class view: many observers' CSVs on that page, each observer's rows and the class's.
#pragma once

#include <QElapsedTimer>
#include <QTimer>
#include <QWidget>
#include <memory>
#include <optional>
#include <string>

#include "models/frame_pacer.h"
#include "study/study_analysis.h"
#include "study/trial_clips.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;
class QStackedWidget;
class QTableWidget;

namespace oflab {

class StudyCanvas;
class PsychometricPlot;

// What a study run is set to; the set-up page's fields.
struct StudyChoice {
  Study study;
  std::string method;      // one of adaptive_methods()
  std::string observer;    // no commas or line breaks
  double ppi = 96.0;       // the screen's pixels per inch
  std::uint64_t seed = 1;  // of the session's draws
};

class StudyWindow : public QWidget {
  Q_OBJECT

 public:
  explicit StudyWindow(QWidget* parent = nullptr);
  ~StudyWindow() override;

  // Selects `study` on the set-up page (its method and seed become the fields' values).
  void select_study(const Study& study);
  // The set-up page's fields as a choice; "" or why they cannot start (one line).
  std::string read_choice(StudyChoice* choice) const;
  // Sets the fields other than the study.
  void set_fields(const std::string& method, const std::string& observer, double ppi,
                  std::uint64_t seed);

  // Runs the set-up page's choice to its end with `observer` answering each presentation
  // after its pictures are made and each clip's last frame is shown (no clock: a simulated
  // run is not timed), through the same answers as the buttons; then shows the results.
  // Returns "" or why it could not start.
  std::string run_simulated(SimulatedObserver& observer);

  // Starts the set-up page's choice as the Start button does: the rate check, then the
  // trials on the paced clock.
  void start();
  // The frame of the first clip of the first trial on screen, -1 before it plays and after.
  int first_clip_frame() const;
  // The set-up page's status line: why a start was refused, "" when none.
  std::string setup_status() const;

  // The running or finished session (nullptr before the first start).
  const StudySession* session() const;
  // The trials as CSV rows with the set-up page's observer and ppi.
  std::vector<TrialRow> rows() const;
  // The class view: the trials of the CSV files at `csv_paths` (session/study/trial_csv.h)
  // together on the results page, a row per observer and condition and the class's pooled row
  // (plotted when there are several observers). Returns "" or the reader's message (file,
  // line, column), the page shown staying as it was.
  std::string show_class_results(const std::vector<std::string>& csv_paths);

  // The smallest threshold fitted on the results page (pixels), 0 before results.
  double smallest_threshold_px() const { return smallest_threshold_px_; }

  // Writes rows() to `path` whole or not at all (Overwrite::kReplace only when `replace`).
  // Returns "" or the error.
  std::string write_csv(const std::string& path, bool replace) const;

 signals:
  // "Use as the reuse threshold" on the results page: the smallest threshold fitted, pixels.
  void threshold_chosen(double px);

 protected:
  void keyPressEvent(QKeyEvent* event) override;
  // Closing the window during a trial stops its clock and ends the session there: the set-up
  // page says so, and Start begins a new one.
  void hideEvent(QHideEvent* event) override;

 private:
  enum class Phase { kIdle, kRateCheck, kFirst, kGap, kSecond, kAnswer };

  QWidget* make_setup_page();
  QWidget* make_card_measure();
  QWidget* make_trial_page();
  QWidget* make_results_page();
  void open_study_file();
  void study_chosen(int index);
  void begin_rate_check();
  const std::vector<Image>& exact_clip();
  void next_trial();
  void play_phase(Phase phase);
  void tick();
  void clip_ended();
  void answer(int chosen);
  void show_results();
  void show_results_of(const Study& study, const std::vector<TrialRow>& rows,
                       const QString& heading);
  void fill_results_table(const std::vector<ThresholdResult>& fits);
  void open_class_csvs();
  void save_csv();
  void update_trial_text();

  QStackedWidget* pages_ = nullptr;
  QComboBox* study_box_ = nullptr;
  QLabel* study_text_ = nullptr;
  QComboBox* method_box_ = nullptr;
  QLineEdit* observer_edit_ = nullptr;
  QDoubleSpinBox* ppi_box_ = nullptr;
  QSpinBox* seed_box_ = nullptr;
  QLabel* setup_status_ = nullptr;
  StudyCanvas* canvas_ = nullptr;
  QLabel* trial_text_ = nullptr;
  QPushButton* first_button_ = nullptr;
  QPushButton* second_button_ = nullptr;
  QTableWidget* results_table_ = nullptr;
  PsychometricPlot* plot_ = nullptr;
  QLabel* results_text_ = nullptr;
  QPushButton* use_button_ = nullptr;
  double smallest_threshold_px_ = 0.0;

  std::vector<Study> studies_;  // the study box's entries
  StudyChoice choice_;
  std::unique_ptr<TrialRunner> runner_;
  Phase phase_ = Phase::kIdle;
  QTimer clock_;
  QElapsedTimer elapsed_;
  FramePacer pacer_;
  int frame_ = 0;      // of the clip playing
  bool late_ = false;  // a frame of this presentation was late
  int late_frames_ = 0;
};

}  // namespace oflab
