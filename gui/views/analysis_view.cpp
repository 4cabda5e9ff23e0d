#include "views/analysis_view.h"

#include <QCheckBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <functional>

#include "display/palette.h"
#include "models/animation_model.h"
#include "models/scene_model.h"
#include "models/window_model.h"
#include "player/policy_comparison.h"
#include "views/frame_inspector.h"

namespace oflab {
namespace {

QColor qcolor(const RgbF& c) { return QColor::fromRgbF(c[0], c[1], c[2]); }
QColor level_qcolor(int level) {
  const Rgb8 c = level_colour(static_cast<Level>(level));
  return QColor(c.r, c.g, c.b);
}

QFont chart_font(const ViewTheme& theme) {
  QFont font;
  font.setPixelSize(theme.label_size);
  return font;
}

// Width of the label column left of each chart: room for its widest top value.
int left_margin(const QFontMetrics& fm) {
  return fm.horizontalAdvance(QStringLiteral("8.88e+03 ms")) + 10;
}

// What one chart draws: the frames of its x axis up to the current frame, the model's
// records (records[k] is frame k) and the x position of a frame inside its plot rectangle.
struct ChartFrame {
  const std::vector<AnimationFrame>* records;
  int first = 0, last = 0, current = 0;
  QRect area;
  double x(double frame) const {
    const int n = last - first + 1;
    return area.left() + (frame - first + 0.5) * area.width() / std::max(1, n);
  }
  double bar_width() const { return std::max(1.0, double(area.width()) / (last - first + 1)); }
  int end() const { return std::min(current, int(records->size()) - 1); }
};

// A value of a record, NaN for a frame whose plane is not drawn (a gap, not a zero).
using Series = std::function<double(const AnimationFrame&)>;
Series drawn_only(Series value) {
  return [value](const AnimationFrame& r) { return r.drawn() > 0 ? value(r) : std::nan(""); };
}

// The value charted at frame k, NaN where there is none (a gap, not a zero).
using FrameValue = std::function<double(int)>;

// `value` of the model's records, NaN past the last one.
FrameValue of_records(const ChartFrame& f, Series value) {
  const std::vector<AnimationFrame>* records = f.records;
  return [records, value](int k) {
    return k < int(records->size()) ? value((*records)[size_t(k)]) : std::nan("");
  };
}

// `field` of a compared run's history, NaN for a frame not kept or (when `drawn_only`)
// whose plane is not drawn.
FrameValue of_run(const ComparedRun& run, double (*field)(const ComparedFrame&), bool drawn_only) {
  return [&run, field, drawn_only](int k) {
    const ComparedFrame* c = run.at(k);
    return c && (!drawn_only || c->drawn() > 0) ? field(*c) : std::nan("");
  };
}

// The frame axis under a chart: a tick at every labelled frame and its number.
void draw_frame_axis(QPainter& p, const ChartFrame& f, const QColor& text) {
  const QFontMetrics fm = p.fontMetrics();
  const std::vector<int> ticks =
      AnalysisView::frame_ticks(f.first, f.last, f.area.width(), p.font().pixelSize());
  p.setPen(text);
  for (int frame : ticks) {
    const double x = f.x(frame);
    p.drawLine(QPointF(x, f.area.bottom()), QPointF(x, f.area.bottom() + 5));
    const QString label = QString::number(frame);
    const int w = fm.horizontalAdvance(label);
    // Centred on its tick, but never left of the chart (the margin holds the word "frame").
    const double left = std::max(x - w / 2.0 - 2, double(f.area.left()));
    p.drawText(QRectF(left, f.area.bottom() + 5, w + 4, fm.height()), Qt::AlignCenter, label);
  }
  const int margin = left_margin(fm);
  p.drawText(QRect(f.area.left() - margin, f.area.bottom() + 5, margin - 6, fm.height()),
             Qt::AlignRight | Qt::AlignVCenter, QObject::tr("frame"));
}

// A chart's box and its title in the strip above it.
void draw_box_and_title(QPainter& p, const ChartFrame& f, const QString& title,
                        const QColor& text) {
  const QFontMetrics fm = p.fontMetrics();
  const int x = f.area.left() - left_margin(fm);  // the chart's own margin, left of its box
  p.setPen(text.darker(150));
  p.drawRect(f.area);
  p.setPen(text);
  p.drawText(QRect(x, f.area.top() - fm.height() - 2, f.area.right() - x, fm.height()),
             Qt::AlignLeft | Qt::AlignVCenter, title);
}

// A value chart's frame: box, title, its top value and 0 in the margin, the frame axis.
void draw_frame_box(QPainter& p, const ChartFrame& f, const QString& title, double top,
                    const QColor& text, const QString& unit) {
  const QFontMetrics fm = p.fontMetrics();
  const int margin = left_margin(fm);
  const int x = f.area.left() - margin;
  draw_box_and_title(p, f, title, text);
  p.drawText(QRect(x, f.area.top(), margin - 6, fm.height()), Qt::AlignRight,
             QString::number(top, 'g', 3) + unit);
  p.drawText(QRect(x, f.area.bottom() - fm.height(), margin - 6, fm.height()), Qt::AlignRight,
             QStringLiteral("0"));
  draw_frame_axis(p, f, text);
}

// A polyline of value(frame) over the charted frames, scaled to [0, top].
void draw_series(QPainter& p, const ChartFrame& f, double top, const QPen& pen,
                 const FrameValue& value) {
  QPainterPath path;
  bool started = false;
  for (int k = f.first; k <= f.current; ++k) {
    const double v = value(k);
    if (!std::isfinite(v)) {
      started = false;
      continue;
    }
    const QPointF point(f.x(k), f.area.bottom() - std::min(v / top, 1.0) * f.area.height());
    if (started)
      path.lineTo(point);
    else
      path.moveTo(point);
    started = true;
  }
  // Without antialiasing: stroking antialiased polylines took three quarters of a frame
  // in software (14 ms of CPU per frame at 1920 x 1080 against 3 ms without).
  p.save();
  p.setRenderHint(QPainter::Antialiasing, false);
  p.setPen(pen);
  p.setBrush(Qt::NoBrush);
  p.drawPath(path);
  p.restore();
}

// 1.1 times the largest finite value over the charted frames, and at least 1.1 * floor.
double series_top(const ChartFrame& f, const FrameValue& value, double floor) {
  double top = floor;
  for (int k = f.first; k <= f.current; ++k) {
    const double v = value(k);
    if (std::isfinite(v)) top = std::max(top, v);
  }
  return top * 1.1;
}

// A key of coloured swatches and names, right-aligned in the strip above `area`.
using LegendEntry = std::pair<QString, QColor>;
void draw_legend(QPainter& p, const QRect& area, const std::vector<LegendEntry>& entries,
                 const QColor& text) {
  const QFontMetrics fm = p.fontMetrics();
  const int box = fm.height() * 2 / 3, gap = fm.height() / 2;
  int x = area.right();
  for (auto entry = entries.rbegin(); entry != entries.rend(); ++entry) {
    x -= fm.horizontalAdvance(entry->first);
    p.setPen(text);
    p.drawText(QPoint(x, area.top() - fm.descent() - 3), entry->first);
    x -= box + 4;
    const QRect swatch(x, area.top() - 3 - (fm.height() + box) / 2, box, box);
    p.fillRect(swatch, entry->second);
    p.drawRect(swatch);
    x -= gap;
  }
}

// The level colours' key.
void draw_level_legend(QPainter& p, const QRect& area, const QColor& text) {
  std::vector<LegendEntry> entries;
  for (int level = 0; level < kLevelCount; ++level) {
    entries.emplace_back(QString::fromUtf8(level_name(Level(level))), level_qcolor(level));
  }
  draw_legend(p, area, entries, text);
}

void draw_levels(QPainter& p, const ChartFrame& f, const QColor& text) {
  int top = 1;
  for (int k = f.first; k <= f.end(); ++k) top = std::max(top, (*f.records)[size_t(k)].drawn());
  draw_frame_box(p, f, QObject::tr("layers per level (stacked)"), top, text, QString());
  draw_level_legend(p, f.area, text);
  const double unit = double(f.area.height()) / top;
  for (int k = f.first; k <= f.end(); ++k) {
    double y = f.area.bottom();
    for (int level = 0; level < kLevelCount; ++level) {
      const int n = (*f.records)[size_t(k)].levels[size_t(level)];
      if (n == 0) continue;
      const QRectF bar(f.x(k) - f.bar_width() / 2, y - n * unit, f.bar_width(), n * unit);
      p.fillRect(bar, level_qcolor(level));
      y -= n * unit;
    }
  }
}

// Level L's budget: the error the level would leave at each frame (the carried books plus
// this frame's flow over the terms it neglects, core/engine/decision.h neglected_error, the
// quantity choose_level tests against thresholds[L]); NaN for frame 0 and for frames that
// did not update exactly one layer or drew nothing.
Series level_budget(int level) {
  return drawn_only([level](const AnimationFrame& r) {
    if (r.layer_reports.size() != 1 || r.frame == 0) return std::nan("");
    const FrameReport& books = r.layer_reports.front();
    return neglected_error(books.carried, books.flow, Level(level));
  });
}

// Level L's budget chart: the error it would leave against its threshold, and the measured
// error.
void draw_budget(QPainter& p, const ChartFrame& f, int level, double threshold,
                 const QColor& text) {
  const Series measured =
      drawn_only([](const AnimationFrame& r) { return r.max_measured_error_px; });
  const FrameValue estimated = of_records(f, level_budget(level));
  const FrameValue measured_at = of_records(f, measured);
  const double top = std::max(series_top(f, estimated, threshold), series_top(f, measured_at, 0.1));
  draw_frame_box(p, f, QObject::tr("%1: error left").arg(level_name(Level(level))), top, text,
                 QStringLiteral(" px"));
  QPen dashed(text, 1.0, Qt::DashLine);
  const double y = f.area.bottom() - std::min(threshold / top, 1.0) * f.area.height();
  p.setPen(dashed);
  p.drawLine(QPointF(f.area.left(), y), QPointF(f.area.right(), y));
  draw_series(p, f, top, QPen(level_qcolor(level), 2.0), estimated);
  draw_series(p, f, top, QPen(text, 1.0), measured_at);
}

// ---- The comparison: one series per compared policy ----

QColor policy_qcolor(int index) {
  const Rgb8 c = policy_colour(index);
  return QColor(c.r, c.g, c.b);
}

std::vector<LegendEntry> policy_legend(const std::vector<ComparedRun>& runs) {
  std::vector<LegendEntry> entries;
  for (size_t i = 0; i < runs.size(); ++i) {
    entries.emplace_back(QString::fromUtf8(runs[i].policy->name), policy_qcolor(int(i)));
  }
  return entries;
}

// A chart of one line per compared policy: its title and unit, the field of the history it
// draws, whether frames whose plane is not drawn are gaps, and its scale: the `quantile` of
// the values charted (1: the largest; less clips the rarest spikes at the top), at least
// `floor`.
struct ComparedChart {
  QString title, unit;
  double (*field)(const ComparedFrame&);
  bool drawn_only = true;
  double floor = 1.0;
  double quantile = 1.0;
};

// 1.1 times the chart's quantile of every policy's values over the charted frames.
double compared_top(const ChartFrame& f, const std::vector<FrameValue>& values,
                    const ComparedChart& chart) {
  std::vector<double> all;
  for (const FrameValue& value : values) {
    for (int k = f.first; k <= f.current; ++k) {
      if (std::isfinite(value(k))) all.push_back(value(k));
    }
  }
  double top = chart.floor;
  if (!all.empty()) {
    const size_t at = size_t(chart.quantile * double(all.size() - 1));
    std::nth_element(all.begin(), all.begin() + long(at), all.end());
    top = std::max(top, all[at]);
  }
  return 1.1 * top;
}

// The chart's lines, in panel order, each narrower than the one before, so a line that
// another covers (two policies doing the same) still shows as its border; with the key.
void draw_compared(QPainter& p, const ChartFrame& f, const std::vector<ComparedRun>& runs,
                   const ComparedChart& chart, const QColor& text) {
  std::vector<FrameValue> values;
  for (const ComparedRun& run : runs) values.push_back(of_run(run, chart.field, chart.drawn_only));
  const double top = compared_top(f, values, chart);
  draw_frame_box(p, f, chart.title, top, text, chart.unit);
  draw_legend(p, f.area, policy_legend(runs), text);
  for (size_t i = 0; i < runs.size(); ++i) {
    const double width = 2.0 + double(runs.size() - 1 - i);
    draw_series(p, f, top, QPen(policy_qcolor(int(i)), width), values[i]);
  }
}

// One band per compared policy, in panel order, marked by a strip of the policy's colour in
// the margin: at every frame the policy's drawn layers per level, stacked to the band's
// height (each level's share of that frame).
void draw_level_bands(QPainter& p, const ChartFrame& f, const std::vector<ComparedRun>& runs,
                      const QColor& text) {
  draw_box_and_title(p, f, QObject::tr("levels per frame, one band per policy"), text);
  draw_level_legend(p, f.area, text);
  draw_frame_axis(p, f, text);
  const double band = double(f.area.height()) / double(runs.size());
  for (size_t i = 0; i < runs.size(); ++i) {
    const double top = f.area.top() + double(i) * band;
    p.fillRect(QRectF(f.area.left() - 10, top + 1, 6, band - 2), policy_qcolor(int(i)));
    if (i > 0) {
      p.setPen(text.darker(150));
      p.drawLine(QPointF(f.area.left(), top), QPointF(f.area.right(), top));
    }
    for (int k = f.first; k <= f.current; ++k) {
      const ComparedFrame* c = runs[i].at(k);
      if (!c || c->drawn() == 0) continue;
      const double unit = (band - 2) / c->drawn();
      double y = top + band - 1;
      for (int level = 0; level < kLevelCount; ++level) {
        const int n = c->levels[size_t(level)];
        if (n == 0) continue;
        p.fillRect(QRectF(f.x(k) - f.bar_width() / 2, y - n * unit, f.bar_width(), n * unit),
                   level_qcolor(level));
        y -= n * unit;
      }
    }
  }
}

// Beside the bands, each policy's share of layer-frames per level over the charted frames:
// its swatch and name, then one bar stacked in the level colours with the percentages that
// fit inside their part.
void draw_level_shares(QPainter& p, const QRect& panel, const ChartFrame& f,
                       const std::vector<ComparedRun>& runs, const QColor& text) {
  const QFontMetrics fm = p.fontMetrics();
  p.setPen(text);
  p.drawText(QRect(panel.left(), panel.top() - fm.height() - 2, panel.width(), fm.height()),
             Qt::AlignLeft | Qt::AlignVCenter,
             QObject::tr("share, frames %1-%2").arg(f.first).arg(f.current));
  const double band = double(panel.height()) / double(runs.size());
  for (size_t i = 0; i < runs.size(); ++i) {
    const int top = panel.top() + int(double(i) * band);
    const int box = fm.height() * 2 / 3;
    p.fillRect(QRect(panel.left(), top + (fm.height() - box) / 2, box, box), policy_qcolor(int(i)));
    p.setPen(text);
    p.drawText(QRect(panel.left() + box + 4, top, panel.width() - box - 4, fm.height()),
               Qt::AlignLeft | Qt::AlignVCenter, QString::fromUtf8(runs[i].policy->name));
    const auto totals = runs[i].level_totals(f.first, f.current);
    double all = 0;
    for (std::int64_t n : totals) all += double(n);
    if (all <= 0) continue;
    const QRectF bar(panel.left(), top + fm.height() + 2, panel.width(),
                     std::max(4.0, band - fm.height() - 6));
    double x = bar.left();
    for (int level = 0; level < kLevelCount; ++level) {
      const double share = double(totals[size_t(level)]) / all;
      const QRectF part(x, bar.top(), share * bar.width(), bar.height());
      p.fillRect(part, level_qcolor(level));
      const QString label = QString::number(std::lround(100 * share)) + QStringLiteral("%");
      if (fm.horizontalAdvance(label) + 4 < part.width() && fm.height() <= part.height()) {
        p.setPen(level_qcolor(level).lightnessF() < 0.45 ? Qt::white : Qt::black);
        p.drawText(part, Qt::AlignCenter, label);
      }
      x += part.width();
    }
  }
}

void draw_current(QPainter& p, const ChartFrame& f, const QColor& text) {
  p.setPen(QPen(text, 1.0, Qt::DotLine));
  p.drawLine(QPointF(f.x(f.current), f.area.top()), QPointF(f.x(f.current), f.area.bottom()));
}

// Chart rectangles for a widget `rect` and font, below a status line, with a title strip
// above and a frame axis below each chart.
// The engine's charts: a first row of the frame time and the percent approximated side by
// side, the levels across the whole width, then the four budget charts two by two, each
// kBudgetRows times as tall as a chart of the first two rows: the saw-tooth of each
// level's budget is what the view is for.
// Comparing: four rows of one width, the last the level bands with the column of the level
// shares at their right (share_panel); the line charts above end where the bands end, so
// all four share one frame axis (one x for each frame).
constexpr double kBudgetRows = 2.6;
std::vector<QRect> chart_areas(const QRect& rect, const QFontMetrics& fm, bool comparing) {
  const int line = fm.height(), margin = left_margin(fm), right = 16;
  const int title = line + 4, axis = line + 8, status = line + 8;
  const int width = rect.width() - margin - right;
  if (comparing) {
    std::vector<QRect> result;
    const int row = std::max(20, (rect.height() - status) / 4 - title - axis);
    const int shares = std::clamp(rect.width() / 5, 160, 420);
    for (int i = 0; i < 4; ++i) {
      result.emplace_back(margin, status + title + i * (row + title + axis),
                          width - shares - margin / 2, row);
    }
    return result;
  }
  const int free = rect.height() - status - 4 * (title + axis);
  const int small = std::max(20, int(free / (2.0 + 2.0 * kBudgetRows)));
  const int big = std::max(20, int(small * kBudgetRows));
  const int half = (rect.width() - right) / 2;
  const auto in_column = [&](int column, int top, int height) {
    return QRect(column * half + margin, top, half - margin - right / 2, height);
  };
  const int row_1 = status + title, row_2 = row_1 + small + axis + title;
  const int row_3 = row_2 + small + axis + title, row_4 = row_3 + big + axis + title;
  return {in_column(0, row_1, small), QRect(margin, row_2, width, small),
          in_column(1, row_1, small), in_column(0, row_3, big),
          in_column(1, row_3, big),   in_column(0, row_4, big),
          in_column(1, row_4, big)};
}

// The column of the level shares right of the level bands `bands` in a widget `rect`.
QRect share_panel(const QRect& rect, const QRect& bands) {
  const int left = bands.right() + 12;
  return QRect(left, bands.top(), rect.width() - 16 - left, bands.height());
}

}  // namespace

// The painted charts; the view owns it and tells it what to draw.
class AnalysisView::Charts : public QWidget {
 public:
  explicit Charts(AnalysisView* view) : QWidget(view), view_(view) {
    setObjectName(QStringLiteral("analysis_charts"));
    setAttribute(Qt::WA_OpaquePaintEvent);
    setMinimumSize(400, 300);
    setToolTip(tr("Click a chart to jump to the frame under the pointer"));
  }
  const std::vector<AnimationFrame>* records = nullptr;
  // The compared runs whose histories are overlaid; null when no comparison is charted.
  const std::vector<ComparedRun>* compared = nullptr;
  EngineSettings settings;
  ViewTheme theme;

  void paint(QPainter& p, const QRect& rect) const;
  std::vector<QRect> areas(const QRect& rect) const {
    return chart_areas(rect, QFontMetrics(chart_font(theme)), compared != nullptr);
  }

 protected:
  void paintEvent(QPaintEvent*) override {
    QPainter p(this);
    paint(p, rect());
  }
  void mousePressEvent(QMouseEvent* event) override {
    const int frame = view_->frame_at(event->pos());
    if (frame >= 0) view_->model_->scene_model()->set_frame(frame);
  }

 private:
  void paint_status(QPainter& p, const QRect& rect) const;
  void paint_engine(QPainter& p, const std::vector<QRect>& areas) const;
  void paint_comparison(QPainter& p, const QRect& rect, const std::vector<QRect>& areas) const;
  AnalysisView* view_;
};

void AnalysisView::Charts::paint_status(QPainter& p, const QRect& rect) const {
  const QFontMetrics fm = p.fontMetrics();
  const AnimationFrame& now = records->back();
  const bool hidden = !not_drawn_reason(now).isEmpty();
  p.setPen(hidden ? QColor(213, 94, 0) : qcolor(theme.text));  // Okabe-Ito vermillion
  p.drawText(QRect(8, 2, rect.width() - 16, fm.height() + 4), Qt::AlignLeft | Qt::AlignVCenter,
             view_->status_text());
}

void AnalysisView::Charts::paint(QPainter& p, const QRect& rect) const {
  const QColor text = qcolor(theme.text);
  p.fillRect(rect, qcolor(theme.background));
  p.setFont(chart_font(theme));
  if (!records || records->empty()) {
    p.setPen(text);
    p.drawText(rect, Qt::AlignCenter, tr("Nothing to analyse: the animation cannot play."));
    return;
  }
  p.setRenderHint(QPainter::Antialiasing, true);
  paint_status(p, rect);
  const std::vector<QRect> a = areas(rect);
  if (compared) {
    paint_comparison(p, rect, a);
  } else {
    paint_engine(p, a);
  }
  for (const QRect& area : a) {
    draw_current(p, ChartFrame{records, view_->first_, view_->last_, view_->current_, area}, text);
  }
}

// The model's engine: frame time, levels, percent approximated and the four budgets.
void AnalysisView::Charts::paint_engine(QPainter& p, const std::vector<QRect>& a) const {
  const QColor text = qcolor(theme.text);
  const auto chart = [&](int i) {
    return ChartFrame{records, view_->first_, view_->last_, view_->current_, a[size_t(i)]};
  };
  const FrameValue time = of_records(chart(0), [](const AnimationFrame& r) { return r.time_ms; });
  const double time_top = series_top(chart(0), time, 1.0);
  draw_frame_box(p, chart(0), tr("frame time of the engine"), time_top, text,
                 QStringLiteral(" ms"));
  draw_series(p, chart(0), time_top, QPen(text, 1.5), time);
  draw_levels(p, chart(1), text);
  draw_frame_box(p, chart(2), tr("approximated (not re-rendered)"), 100.0, text,
                 QStringLiteral("%"));
  draw_series(p, chart(2), 100.0, QPen(level_qcolor(int(Level::kAffine)), 2.0),
              of_records(chart(2), drawn_only([](const AnimationFrame& r) {
                           return approximated_percent(r);
                         })));
  for (int level = 0; level < kTermCount; ++level) {
    draw_budget(p, chart(3 + level), level, settings.thresholds[size_t(level)], text);
  }
}

// The compared policies' histories: measured error, frame time and work, one line per
// policy, then their levels per frame and level shares.
void AnalysisView::Charts::paint_comparison(QPainter& p, const QRect& rect,
                                            const std::vector<QRect>& a) const {
  const QColor text = qcolor(theme.text);
  const auto chart = [&](int i) {
    return ChartFrame{records, view_->first_, view_->last_, view_->current_, a[size_t(i)]};
  };
  const std::vector<ComparedRun>& runs = *compared;
  draw_compared(p, chart(0), runs,
                {tr("largest measured error, per policy"), QStringLiteral(" px"),
                 [](const ComparedFrame& f) { return f.max_measured_error_px; }, true, 0.1, 1.0},
                text);
  // Wall times: a frame the machine was busy elsewhere would flatten every other frame.
  draw_compared(
      p, chart(1), runs,
      {tr("frame time, per policy (the slowest 2% of frames clipped at the top)"),
       QStringLiteral(" ms"), [](const ComparedFrame& f) { return f.time_ms; }, false, 0.1, 0.98},
      text);
  draw_compared(p, chart(2), runs,
                {tr("work in the cost model (perspective-warp pixels), per policy"), QString(),
                 [](const ComparedFrame& f) { return f.model_work; }, false, 1.0, 1.0},
                text);
  draw_level_bands(p, chart(3), runs, text);
  draw_level_shares(p, share_panel(rect, a[3]), chart(3), runs, text);
}

AnalysisView::AnalysisView(WindowModel* window, QWidget* parent)
    : ViewPage(parent), window_(window), model_(window->animation()), theme_(view_theme(false)) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(2, 2, 2, 2);
  auto* bar = new QHBoxLayout;
  whole_run_box_ = new QCheckBox(tr("Whole loop"), this);
  whole_run_box_->setObjectName(QStringLiteral("analysis_whole_run"));
  whole_run_box_->setToolTip(
      tr("Chart every frame of the loop; otherwise the last %1 frames").arg(kRecentFrames));
  bar->addWidget(whole_run_box_);
  key_ = new QLabel(this);
  key_->setWordWrap(true);
  bar->addWidget(key_, 1);
  layout->addLayout(bar);
  charts_ = new Charts(this);
  layout->addWidget(charts_, 1);
  connect(whole_run_box_, &QCheckBox::toggled, this, [this] { refresh(); });
  connect(model_, &AnimationModel::frame_changed, this, &AnalysisView::refresh);
  connect(model_, &AnimationModel::source_changed, this, &AnalysisView::refresh);
  connect(window_, &WindowModel::panels_changed, this, &AnalysisView::refresh);
}

bool AnalysisView::comparing() const { return charts_->compared != nullptr; }

int AnalysisView::chart_count() const { return comparing() ? kComparisonChartCount : kChartCount; }

bool AnalysisView::whole_run() const { return whole_run_box_->isChecked(); }
void AnalysisView::set_whole_run(bool on) { whole_run_box_->setChecked(on); }

QRect AnalysisView::chart_area(int index) const {
  const std::vector<QRect> areas = charts_->areas(charts_->rect());
  return index >= 0 && index < int(areas.size()) ? areas[size_t(index)] : QRect();
}

int AnalysisView::frame_at(const QPoint& point) const {
  if (last_ < first_) return -1;
  for (const QRect& area : charts_->areas(charts_->rect())) {
    if (!area.contains(point)) continue;
    const int n = last_ - first_ + 1;
    const int frame = first_ + int((point.x() - area.left()) * double(n) / area.width());
    return std::clamp(frame, first_, last_);
  }
  return -1;
}

std::vector<int> AnalysisView::frame_ticks(int first, int last, int width_px, int label_px) {
  std::vector<int> ticks;
  if (last < first || width_px <= 0) return ticks;
  const double px_per_frame = double(width_px) / (last - first + 1);
  const double room = 3.0 * label_px;  // a label of up to 4 digits and a gap
  int step = 1;
  for (int decade = 1; step * px_per_frame < room; decade *= 10) {
    for (int m : {1, 2, 5}) {
      step = m * decade;
      if (step * px_per_frame >= room) break;
    }
  }
  for (int frame = (first + step - 1) / step * step; frame <= last; frame += step) {
    ticks.push_back(frame);
  }
  return ticks;
}

int AnalysisView::threshold_crossings(int level) const {
  const std::vector<AnimationFrame>* records = charts_->records;
  if (comparing() || !records || level < 0 || level >= kTermCount) return -1;
  const double threshold = charts_->settings.thresholds[size_t(level)];
  const Series budget = level_budget(level);
  int crossings = 0;
  bool below = false, seen = false;  // the last charted value, gaps skipped
  for (int k = first_; k <= std::min(current_, int(records->size()) - 1); ++k) {
    const double v = budget((*records)[size_t(k)]);
    if (!std::isfinite(v)) continue;
    crossings += seen && below && v > threshold;
    below = v <= threshold;
    seen = true;
  }
  return crossings;
}

QString AnalysisView::status_text() const {
  const std::vector<AnimationFrame>* records = charts_->records;
  if (!records || records->empty()) return QString();
  const AnimationFrame& now = records->back();
  if (comparing()) return comparison_status();
  const QString reason = not_drawn_reason(now);
  if (!reason.isEmpty()) {
    return tr("Frame %1: nothing is drawn (%2); the charts leave a gap.")
        .arg(now.frame)
        .arg(reason);
  }
  return tr("Frame %1: %2 of %3 layers drawn, %4% approximated, largest measured error %5 px.")
      .arg(now.frame)
      .arg(now.drawn())
      .arg(now.layers)
      .arg(approximated_percent(now), 0, 'f', 0)
      .arg(now.max_measured_error_px, 0, 'f', 2);
}

QString AnalysisView::comparison_status() const {
  QStringList errors;
  for (const ComparedRun& run : *charts_->compared) {
    const ComparedFrame* now = run.at(current_);
    const QString name = QString::fromUtf8(run.policy->name);
    if (!now) {
      errors << tr("%1 not played").arg(name);
    } else if (now->drawn() == 0) {
      errors << tr("%1 nothing drawn").arg(name);
    } else {
      errors << tr("%1 %2 px").arg(name).arg(now->max_measured_error_px, 0, 'f', 2);
    }
  }
  return tr("Frame %1, largest measured error: %2.")
      .arg(current_)
      .arg(errors.join(QStringLiteral(", ")));
}

void AnalysisView::follow_current_frame(int current, int loop_frames) {
  current_ = current;
  const int span = whole_run() ? std::max(1, loop_frames) : std::min(kRecentFrames, loop_frames);
  // The axis stays where it is while the current frame is on it; otherwise it moves so the
  // current frame is its last (playing on), or starts at 0 (looping back, a restart).
  if (last_ - first_ + 1 != span || current_ > last_) {
    last_ = std::max(current_, span - 1);
    first_ = last_ - span + 1;
  } else if (current_ < first_) {
    first_ = 0;
    last_ = span - 1;
  }
}

void AnalysisView::read_model() {
  const std::vector<AnimationFrame>& history = model_->history();
  charts_->records = history.empty() ? nullptr : &history;
  PolicyComparison* comparison =
      window_->panel_display() == PanelDisplay::kComparison ? &window_->comparison() : nullptr;
  const std::vector<ComparedRun>* runs = comparison ? &comparison->runs() : nullptr;
  charts_->compared = runs && !runs->empty() && charts_->records ? runs : nullptr;
  key_->setText(comparing()
                    ? tr("One line per compared policy, coloured as in the key above each chart. "
                         "Bottom: each policy's levels per frame, and its share over the charted "
                         "frames. Click a chart to jump to that frame.")
                    : tr("Dashed: threshold. Coloured: error the level would leave. "
                         "Thin: measured error. Click a chart to jump to that frame."));
  key_->setToolTip(comparing() ? tr("How to read the comparison's charts")
                               : tr("How to read the four budget charts of the bottom two rows"));
  charts_->settings = model_->settings();
  charts_->theme = theme_;
  const int loop = model_->animator() ? model_->animator()->frame_count() : 1;
  follow_current_frame(history.empty() ? 0 : history.back().frame, loop);
}

void AnalysisView::refresh() {
  if (!isVisible()) return;
  read_model();
  charts_->update();
}

QString AnalysisView::scene_panel_note() const { return oflab::scene_panel_note(*model_); }

QImage AnalysisView::render_image() {
  read_model();
  QImage image(charts_->size().expandedTo(QSize(800, 500)), QImage::Format_RGB32);
  QPainter painter(&image);
  charts_->paint(painter, image.rect());
  return image;
}

double AnalysisView::smallest_text_px() const { return QFontInfo(chart_font(theme_)).pixelSize(); }

void AnalysisView::set_theme(const ViewTheme& theme) {
  theme_ = theme;
  charts_->theme = theme;
  refresh();
}

void AnalysisView::showEvent(QShowEvent* event) {
  ViewPage::showEvent(event);
  refresh();
}

}  // namespace oflab
