// View 4, "Analysis": the dissertation's analysis window, modernised. Over the last 80
// frames (or the whole loop) of the animation model's run: the frame time and the
// percentage approximated (side by side), the layers per level (stacked, in the level
// colours, with their legend), and, the largest charts, for each cheaper level the error
// it would have left (the carried estimate plus this
// frame's flow over its neglected terms, core/engine/decision.h; drawn for frames that
// updated exactly one layer, the only ones whose books are one engine's) against its
// threshold, beside the measured true error. Every chart has a frame axis with ticks; a
// status line names the current frame, or says why its plane is not drawn (a frame whose
// plane is not visible leaves a gap in the charts, never zeros).
//
// Clicking a chart moves the scene model to the frame under the pointer: each chart maps x
// through its own rectangle (comparing, the four charts share one x range, so one frame
// has one x in all of them). The x axis moves only when the current frame leaves it
// (playing on past its end, or looping back), never because of a click, so the history
// stays still under the pointer. Painted with Qt; reads the animation model only.
//
// While the animation view compares policies (its comparison layout,
// session/player/policy_comparison.h), the charts overlay the compared policies' histories
// instead, one line per policy in its colour (views/palette.h policy_colour) with a key:
// the largest measured error, the frame time and the work in the cost model; then one band
// per policy with its levels per frame, and beside the bands each policy's share of
// layer-frames per level over the charted frames. So a class sees where each one pays.
#pragma once

#include <QRect>
#include <functional>
#include <vector>

#include "adapters/painted_text.h"
#include "views/view_page.h"

class QCheckBox;
class QLabel;

namespace oflab {

class AnimationModel;
class WindowModel;
class PolicyComparison;

class AnalysisView : public ViewPage {
  Q_OBJECT

 public:
  static constexpr int kRecentFrames = 80;
  // Charts: 0 frame time, 1 layers per level, 2 percent approximated, 3..6 the budgets of
  // levels none, translate, affine and perspective (the largest four, two by two).
  static constexpr int kChartCount = 7;
  // Comparing: 0 measured error, 1 frame time, 2 work, 3 levels per frame (one band per
  // policy).
  static constexpr int kComparisonChartCount = 4;

  // Charts the window model's animation model; while the window model's panel display is
  // the comparison, the compared policies instead. The model must outlive the view.
  explicit AnalysisView(WindowModel* window, QWidget* parent = nullptr);

  QImage render_image() override;
  QString scene_panel_note() const override;
  void set_theme(const ViewTheme& theme) override;
  double smallest_text_px() const override;

  // True when the charts overlay compared policies (a comparison is given and plays).
  bool comparing() const;
  // Charts laid out now: kComparisonChartCount when comparing, else kChartCount.
  int chart_count() const;

  bool whole_run() const;
  void set_whole_run(bool on);
  // The frame a click at `point` (charts widget pixels) jumps to: the frame under x in the
  // chart whose plot rectangle holds the point; -1 outside every chart.
  int frame_at(const QPoint& point) const;
  // Plot rectangle of chart `index` (0 .. chart_count() - 1) in charts widget pixels, as last
  // laid out for the widget's size and the theme's font; empty for another index.
  QRect chart_area(int index) const;
  // The x axis: frames [first, last]. The run is charted up to current_frame() <= last.
  int first_frame() const { return first_; }
  int last_frame() const { return last_; }
  int current_frame() const { return current_; }
  // Frames that get a labelled tick on a chart `width_px` wide, for labels of `label_px`
  // pixel font: multiples of 1, 2 or 5 x 10^k, far enough apart for their labels.
  static std::vector<int> frame_ticks(int first, int last, int width_px, int label_px);
  // How often level `level`'s budget chart (0 none .. 3 perspective) crosses its dashed
  // threshold upwards over the charted frames: frames whose error the level would leave
  // exceeds thresholds[level] while the last charted frame before it (gaps skipped) was
  // within it. -1 when comparing, with nothing charted or for another level.
  int threshold_crossings(int level) const;
  // Every text the charts paint now at the size render_image paints them, with its box in
  // those pixels (titles, keys, axis labels, the status line), and what is wrong with them
  // (adapters/painted_text.h text_problems): elided, off the charts or overlapping; empty
  // when every text is legible.
  std::vector<PaintedText> painted_texts();
  std::vector<QString> text_problems();
  // The status line: the current frame's level and error, or why its plane is not drawn;
  // comparing, each policy's measured error at the current frame.
  QString status_text() const;

 protected:
  void showEvent(QShowEvent* event) override;

 private:
  class Charts;
  void refresh();
  void read_model();
  QSize image_size() const;  // the charts' size, at least 800 x 500
  void follow_current_frame(int current, int loop_frames);
  QString comparison_status() const;

  WindowModel* window_;
  AnimationModel* model_;
  Charts* charts_;
  QCheckBox* whole_run_box_;
  QLabel* key_;
  ViewTheme theme_;
  int first_ = 0;
  int last_ = 0;
  int current_ = 0;
};

}  // namespace oflab
