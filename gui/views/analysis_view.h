// View 4, "Analysis": the dissertation's analysis window, modernised. Over the last 80
// frames (or the whole run so far) of the animation model's run: the frame time, the layers
// per level (stacked, level colours), the percentage approximated, and for each cheaper
// level the error it would have left (the carried estimate plus this frame's flow over its
// neglected terms, core/engine/decision.h; drawn for frames that updated exactly one layer,
// the only ones whose books are one engine's) against its threshold, beside the measured
// true error. Painted with Qt (a few hundred line segments per frame); clicking a chart
// moves the scene model to that frame. Reads the animation model only.
#pragma once

#include "views/view_page.h"

class QCheckBox;

namespace oflab {

class AnimationModel;

class AnalysisView : public ViewPage {
  Q_OBJECT

 public:
  static constexpr int kRecentFrames = 80;

  // The model must outlive the view.
  explicit AnalysisView(AnimationModel* model, QWidget* parent = nullptr);

  QImage render_image() override;
  void set_theme(const ViewTheme& theme) override;

  bool whole_run() const;
  void set_whole_run(bool on);
  // The frame a click at widget x would jump to; -1 outside the charts.
  int frame_at(int x) const;
  // The frames charted: [first, last] (last = the current frame).
  int first_frame() const { return first_; }
  int last_frame() const { return last_; }

 protected:
  void showEvent(QShowEvent* event) override;

 private:
  class Charts;
  void refresh();
  void read_model();

  AnimationModel* model_;
  Charts* charts_;
  QCheckBox* whole_run_box_;
  ViewTheme theme_;
  int first_ = 0;
  int last_ = 0;
};

}  // namespace oflab
