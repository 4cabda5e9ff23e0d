// View 4, "Analysis": the dissertation's analysis window, modernised. Over the last 80
// frames (or the whole run so far) of the animation view's engine: the frame time, the
// polygons per level (stacked, level colours), the percentage approximated, and for each
// cheaper level the error it would have left (the carried estimate plus this frame's flow
// over its neglected terms, core/engine/decision.h) against its threshold, beside the measured
// true error. Painted with Qt (a few hundred line segments per frame); clicking a chart
// moves the scene model to that frame.
#pragma once

#include "views/view_page.h"

class QCheckBox;

namespace oflab {

class AnimationView;
class SceneModel;
struct FrameRecord;

class AnalysisView : public ViewPage {
  Q_OBJECT

 public:
  static constexpr int kRecentFrames = 80;

  // Both must outlive the view.
  AnalysisView(SceneModel* model, AnimationView* animation, QWidget* parent = nullptr);

  QString view_name() const override { return QStringLiteral("analysis"); }
  QString view_title() const override { return tr("Analysis"); }
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

  SceneModel* model_;
  AnimationView* animation_;
  Charts* charts_;
  QCheckBox* whole_run_box_;
  ViewTheme theme_;
  int first_ = 0;
  int last_ = 0;
};

}  // namespace oflab
