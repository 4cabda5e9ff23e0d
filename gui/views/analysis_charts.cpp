#include "views/analysis_charts.h"

#include <QObject>
#include <QPainter>
#include <QPainterPath>
#include <cmath>
#include <functional>
#include <limits>

#include "display/palette.h"
#include "models/animation_model.h"
#include "player/run_player.h"

namespace oflab {
namespace {

QColor level_qcolor(int level) {
  const Rgb8 c = level_colour(static_cast<Level>(level));
  return QColor(c.r, c.g, c.b);
}

// Width of the label column left of each chart: room for its widest top value.
int left_margin(const QFontMetrics& fm) {
  return fm.horizontalAdvance(QStringLiteral("8.88e+03 ms")) + 10;
}

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
      frame_axis_ticks(f.first, f.last, f.area.width(), p.font().pixelSize());
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
  p.drawText(
      QRect(x, f.area.top() - f.title_lines * (fm.height() + 2), f.area.right() - x, fm.height()),
      Qt::AlignLeft | Qt::AlignVCenter, title);
}

// A value chart's frame: box, title, its top and bottom values in the margin (a log scale's
// decades between them as dotted lines), the frame axis.
void draw_frame_box(QPainter& p, const ChartFrame& f, const QString& title, const ValueScale& scale,
                    const QColor& text, const QString& unit) {
  const QFontMetrics fm = p.fontMetrics();
  const int margin = left_margin(fm);
  const int x = f.area.left() - margin;
  draw_box_and_title(p, f, title, text);
  p.drawText(QRect(x, f.area.top(), margin - 6, fm.height()), Qt::AlignRight,
             QString::number(scale.top, 'g', 3) + unit);
  // A linear chart too short for both values keeps its top one: its bottom is zero.
  if (scale.log || f.area.height() >= 2 * fm.height()) {
    p.drawText(QRect(x, f.area.bottom() - fm.height(), margin - 6, fm.height()), Qt::AlignRight,
               scale.log ? QString::number(scale.bottom, 'g', 3) + unit : QStringLiteral("0"));
  }
  if (scale.log) {
    p.save();
    p.setPen(QPen(text.darker(150), 1.0, Qt::DotLine));
    for (double decade = scale.bottom * 10; decade < scale.top; decade *= 10) {
      const double y = f.area.bottom() - scale.fraction(decade) * f.area.height();
      p.drawLine(QPointF(f.area.left(), y), QPointF(f.area.right(), y));
    }
    p.restore();
  }
  draw_frame_axis(p, f, text);
}

void draw_frame_box(QPainter& p, const ChartFrame& f, const QString& title, double top,
                    const QColor& text, const QString& unit) {
  draw_frame_box(p, f, title, ValueScale{top}, text, unit);
}

// A polyline of value(frame) over the charted frames, on `scale`.
void draw_series(QPainter& p, const ChartFrame& f, const ValueScale& scale, const QPen& pen,
                 const FrameValue& value) {
  QPainterPath path;
  bool started = false;
  for (int k = f.first; k <= f.current; ++k) {
    const double v = value(k);
    if (!std::isfinite(v)) {
      started = false;
      continue;
    }
    const QPointF point(f.x(k), f.area.bottom() - scale.fraction(v) * f.area.height());
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

void draw_series(QPainter& p, const ChartFrame& f, double top, const QPen& pen,
                 const FrameValue& value) {
  draw_series(p, f, ValueScale{top}, pen, value);
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
int legend_width(const QFontMetrics& fm, const std::vector<LegendEntry>& entries) {
  const int box = fm.height() * 2 / 3, gap = fm.height() / 2;
  int width = 0;
  for (const LegendEntry& entry : entries) width += fm.horizontalAdvance(entry.first) + box + 4;
  return width + gap * std::max(0, int(entries.size()) - 1);
}

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
std::vector<LegendEntry> level_legend() {
  std::vector<LegendEntry> entries;
  for (int level = 0; level < kLevelCount; ++level) {
    entries.emplace_back(QString::fromUtf8(level_name(Level(level))), level_qcolor(level));
  }
  return entries;
}

void draw_level_legend(QPainter& p, const QRect& area, const QColor& text) {
  draw_legend(p, area, level_legend(), text);
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

// Level L's budget: the error the level would leave at each frame (level_budget_at,
// session/player/run_player.h).
Series level_budget(int level) {
  return [level](const AnimationFrame& r) { return level_budget_at(r, level); };
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
  // Dotted, so it never reads as the level's own line ("none" is a dark grey).
  draw_series(p, f, top, QPen(text, 2.0, Qt::DotLine, Qt::RoundCap), measured_at);
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
  bool may_log = false;  // series_scale may pick a log scale
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

// The chart's scale: linear to compared_top, or, for a chart that may take a log scale,
// series_scale of each policy's largest value over the charted frames.
ValueScale compared_scale(const ChartFrame& f, const std::vector<FrameValue>& values,
                          const ComparedChart& chart) {
  const double top = compared_top(f, values, chart);
  if (!chart.may_log) return ValueScale{top};
  std::vector<double> largest;
  for (const FrameValue& value : values) {
    double most = std::nan("");
    for (int k = f.first; k <= f.current; ++k) {
      if (std::isfinite(value(k))) most = std::isfinite(most) ? std::max(most, value(k)) : value(k);
    }
    largest.push_back(most);
  }
  return series_scale(largest, chart.floor);
}

// The chart's lines, in panel order, each narrower than the one before, so a line that
// another covers (two policies doing the same) still shows as its border; with the key.
void draw_compared(QPainter& p, const ChartFrame& f, const std::vector<ComparedRun>& runs,
                   const ComparedChart& chart, const QColor& text) {
  std::vector<FrameValue> values;
  for (const ComparedRun& run : runs) values.push_back(of_run(run, chart.field, chart.drawn_only));
  const ValueScale top = compared_scale(f, values, chart);
  draw_frame_box(p, f, top.log ? chart.title + QObject::tr(" (log scale)") : chart.title, top, text,
                 chart.unit);
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

// The column of the level shares right of the level bands `bands` in a widget `rect`.
QRect share_panel(const QRect& rect, const QRect& bands) {
  const int left = bands.right() + 12;
  return QRect(left, bands.top(), rect.width() - 16 - left, bands.height());
}

}  // namespace

QFont chart_font(const ViewTheme& theme) {
  QFont font;
  font.setPixelSize(theme.label_size);
  return font;
}

std::vector<int> frame_axis_ticks(int first, int last, int width_px, int label_px) {
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
std::vector<QRect> chart_areas(const QRect& rect, const QFontMetrics& fm, bool comparing,
                               int title_lines) {
  const int line = fm.height(), margin = left_margin(fm), right = 16;
  const int title = title_lines * (line + 2) + 2, axis = line + 8, status = line + 8;
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

void paint_engine_charts(QPainter& p, const std::vector<ChartFrame>& charts,
                         const EngineSettings& settings, const QColor& text) {
  const auto chart = [&](int i) { return charts[size_t(i)]; };
  const FrameValue time = of_records(chart(0), [](const AnimationFrame& r) { return r.time_ms; });
  const double time_top = series_top(chart(0), time, 1.0);
  draw_frame_box(p, chart(0), QObject::tr("frame time of the engine"), time_top, text,
                 QStringLiteral(" ms"));
  draw_series(p, chart(0), time_top, QPen(text, 1.5), time);
  draw_levels(p, chart(1), text);
  draw_frame_box(p, chart(2), QObject::tr("approximated (not re-rendered)"), 100.0, text,
                 QStringLiteral("%"));
  draw_series(p, chart(2), 100.0, QPen(level_qcolor(int(Level::kAffine)), 2.0),
              of_records(chart(2), drawn_only([](const AnimationFrame& r) {
                           return approximated_percent(r);
                         })));
  for (int level = 0; level < kTermCount; ++level) {
    draw_budget(p, chart(3 + level), level, settings.thresholds[size_t(level)], text);
  }
}

namespace {

// The comparison's three line charts, in chart order.
std::vector<ComparedChart> compared_charts() {
  return {
      {QObject::tr("largest measured error, per policy"), QStringLiteral(" px"),
       [](const ComparedFrame& f) { return f.max_measured_error_px; }, true, 0.1, 1.0, true},
      // Wall times: a frame the machine was busy elsewhere would flatten every other frame.
      {QObject::tr("frame time, per policy (the slowest 2% of frames clipped at the top)"),
       QStringLiteral(" ms"), [](const ComparedFrame& f) { return f.time_ms; }, false, 0.1, 0.98},
      {QObject::tr("work in the cost model (perspective-warp pixels), per policy"), QString(),
       [](const ComparedFrame& f) { return f.model_work; }, false, 1.0, 1.0},
  };
}

QString level_bands_title() { return QObject::tr("levels per frame, one band per policy"); }

}  // namespace

void paint_comparison_charts(QPainter& p, const QRect& rect, const std::vector<ChartFrame>& charts,
                             const std::vector<ComparedRun>& runs, const QColor& text) {
  const std::vector<ComparedChart> lines = compared_charts();
  for (size_t i = 0; i < lines.size(); ++i) draw_compared(p, charts[i], runs, lines[i], text);
  draw_level_bands(p, charts[3], runs, text);
  draw_level_shares(p, share_panel(rect, charts[3].area), charts[3], runs, text);
}

int comparison_title_lines(const QRect& rect, const QFontMetrics& fm,
                           const std::vector<ComparedRun>& runs) {
  const int width = chart_areas(rect, fm, true).front().width();
  // The widest title, and a log scale's note, beside the widest key.
  int title = fm.horizontalAdvance(level_bands_title());
  for (const ComparedChart& chart : compared_charts()) {
    title = std::max(title, fm.horizontalAdvance(chart.title + QObject::tr(" (log scale)")));
  }
  const int key = std::max(legend_width(fm, policy_legend(runs)), legend_width(fm, level_legend()));
  // The title starts in the chart's margin, left of its box.
  return title + fm.height() + key <= width + left_margin(fm) ? 1 : 2;
}

double ValueScale::fraction(double v) const {
  if (!std::isfinite(v)) return v;
  if (!log) return std::clamp(v / top, 0.0, 1.0);
  if (v <= bottom) return 0.0;
  return std::clamp(std::log(v / bottom) / std::log(top / bottom), 0.0, 1.0);
}

ValueScale series_scale(const std::vector<double>& largest, double floor) {
  double most = floor, least = std::numeric_limits<double>::infinity();
  for (double v : largest) {
    if (!(v > 0)) continue;  // NaN or nothing above zero
    most = std::max(most, v);
    least = std::min(least, v);
  }
  if (std::isfinite(least) && most > kLogScaleRatio * least && most > kLogScaleBottom) {
    return ValueScale{1.1 * most, kLogScaleBottom, true};
  }
  return ValueScale{1.1 * most};
}

void draw_current(QPainter& p, const ChartFrame& f, const QColor& text) {
  p.setPen(QPen(text, 1.0, Qt::DotLine));
  p.drawLine(QPointF(f.x(f.current), f.area.top()), QPointF(f.x(f.current), f.area.bottom()));
}

}  // namespace oflab
