// The main window's side of the threshold study (views/study_window.h): the Study menu's
// window, opened and closed by a state's study.open (a lesson's step), and the thresholds it
// measured, which a state may ask for (study.use_threshold) and "Use X px" sets.
#include <algorithm>

#include "app/main_window.h"
#include "models/window_model.h"
#include "views/study_window.h"

namespace oflab {

StudyWindow* MainWindow::open_study_window() {
  if (!study_window_) {
    study_window_ = new StudyWindow(this);
    connect(study_window_, &StudyWindow::threshold_chosen, this, [this](double px) {
      WindowState state = model_->state();
      state.settings.thresholds = {px, px, px, px};
      QString error;
      if (!model_->apply(state, &error)) show_message(error);
    });
    study_window_->resize(std::max(900, width() * 3 / 4), std::max(720, height() * 3 / 4));
  }
  study_window_->show();
  study_window_->raise();
  study_window_->activateWindow();
  return study_window_;
}

void MainWindow::show_model_study() {
  const std::string name = static_cast<const WindowModel*>(model_)->values().study_open;
  if (name == study_applied_) return;
  study_applied_ = name;
  if (name.empty()) {
    if (study_window_) study_window_->hide();
    return;
  }
  StudyWindow* study = open_study_window();
  study->select_study(find_or_read_study(name));  // a shipped name: window_state_problem
  study->show_setup();
}

WindowState MainWindow::with_study_threshold(WindowState state) const {
  const double px = study_window_ ? study_window_->smallest_threshold_px() : 0.0;
  if (state.study_use_threshold && px > 0.0) state.settings.thresholds = {px, px, px, px};
  return state;
}

}  // namespace oflab
