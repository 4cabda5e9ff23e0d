// The analysis view's charts (gui/views/analysis_view.h), painted with Qt: where each chart
// goes in the charts widget, the frame axis they share, and the two sets of charts drawn on
// them. The engine's: its frame time, its layers per level (stacked, in the level colours,
// with their key), the percent approximated and, for each cheaper level, the error it would
// leave (level_budget_at, session/player/run_player.h) against its dashed threshold beside the
// measured error. The comparison's: one line per compared policy (largest measured error, frame
// time, work in the cost model) in the policy's colour with a key, then one band of levels per
// policy and each policy's share of layer-frames per level. A frame whose plane is not drawn leaves
// a gap in a line, never a zero.
//
// Units: charts widget pixels (top-left origin, y down); errors in pixels, times in
// milliseconds. Frames are indices of the animation model's records.
#pragma once

#include <QColor>
#include <QFont>
#include <QFontMetrics>
#include <QRect>
#include <algorithm>
#include <vector>

#include "adapters/view_theme.h"
#include "engine/animator.h"
#include "engine/engine.h"
#include "player/policy_comparison.h"

class QPainter;

namespace oflab {

// What one chart draws: the frames of its x axis, [first, last], charted up to `current`;
// the model's records (records[k] is frame k; not empty); its plot rectangle `area`; and
// the x position of a frame inside it (the centre of the frame's bar).
struct ChartFrame {
  const std::vector<AnimationFrame>* records;
  int first = 0, last = 0, current = 0;
  QRect area;
  // Lines of the title strip above `area`: 1 (the title left, the key right) or 2 (the
  // title above the key, when the two do not fit one line).
  int title_lines = 1;
  double x(double frame) const {
    const int n = last - first + 1;
    return area.left() + (frame - first + 0.5) * area.width() / std::max(1, n);
  }
  double bar_width() const { return std::max(1.0, double(area.width()) / (last - first + 1)); }
  int end() const { return std::min(current, int(records->size()) - 1); }
};

// The font of every chart's texts: the theme's label size.
QFont chart_font(const ViewTheme& theme);

// Frames in [first, last] that get a labelled tick on a chart `width_px` wide, for labels of
// `label_px` pixel font: multiples of 1, 2 or 5 x 10^k, far enough apart for their labels;
// empty when last < first or width_px <= 0.
std::vector<int> frame_axis_ticks(int first, int last, int width_px, int label_px);

// The plot rectangles of the charts in a widget `rect` whose texts `fm` measures, below the
// status line, each with a title strip above (`title_lines` lines high) and a frame axis
// below: the engine's seven (0 frame time, 1 layers per level, 2 percent approximated, 3..6
// the budgets of levels none .. perspective, each 2.6 times as tall as a chart of the first
// two rows), or, `comparing`, four rows of one width (the last the level bands, with the
// column of the level shares at their right), so all four share one frame axis.
std::vector<QRect> chart_areas(const QRect& rect, const QFontMetrics& fm, bool comparing,
                               int title_lines = 1);

// The title strip's lines of the comparison's charts in a widget `rect` whose texts `fm`
// measures, for `runs`: 1 when every chart's title and key fit one line of its width with a
// gap of a text height between them, else 2 (the title above its key).
int comparison_title_lines(const QRect& rect, const QFontMetrics& fm,
                           const std::vector<ComparedRun>& runs);

// The value axis of a line chart: linear from 0 to `top`, or logarithmic from `bottom` (> 0)
// to `top`. fraction(v) is v's height in the chart (0 at the bottom, 1 at the top), clamped
// to [0, 1]; NaN stays NaN.
struct ValueScale {
  double top = 1.0;
  double bottom = 0.0;
  bool log = false;
  double fraction(double v) const;
};

// The scale of a chart whose series reach the largest values `largest` (one per series,
// NaN or <= 0 for a series with nothing above zero), at least `floor`: logarithmic from
// kLogScaleBottom px when the largest series reaches more than kLogScaleRatio times the
// smallest positive one (so a policy many pixels off does not flatten one within a pixel),
// else linear; the top 1.1 times the largest value.
constexpr double kLogScaleRatio = 10.0;
constexpr double kLogScaleBottom = 0.01;
ValueScale series_scale(const std::vector<double>& largest, double floor);

// The engine's charts on `charts` (the seven areas of chart_areas, not comparing; one x
// axis), the budgets against `settings`' thresholds, texts and lines in `text`.
void paint_engine_charts(QPainter& p, const std::vector<ChartFrame>& charts,
                         const EngineSettings& settings, const QColor& text);

// The comparison's charts on `charts` (the four areas of chart_areas, comparing) for `runs`
// (not empty, in panel order): measured error, frame time and work, one line per policy,
// then their levels per frame, and their level shares in the column right of the bands in
// the widget `rect`.
void paint_comparison_charts(QPainter& p, const QRect& rect, const std::vector<ChartFrame>& charts,
                             const std::vector<ComparedRun>& runs, const QColor& text);

// The dotted line at the current frame of chart `f`.
void draw_current(QPainter& p, const ChartFrame& f, const QColor& text);

}  // namespace oflab
