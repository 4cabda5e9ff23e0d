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

#include "models/animation_model.h"
#include "models/scene_model.h"
#include "views/frame_inspector.h"
#include "views/palette.h"

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

// What one chart draws: the records up to the current frame, the frames of its x axis and
// the x position of a frame inside its plot rectangle.
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

// A value of a frame, NaN for a frame whose plane is not drawn (a gap, not a zero).
using Series = std::function<double(const AnimationFrame&)>;
Series drawn_only(Series value) {
  return [value](const AnimationFrame& r) { return r.drawn() > 0 ? value(r) : std::nan(""); };
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

void draw_frame_box(QPainter& p, const ChartFrame& f, const QString& title, double top,
                    const QColor& text, const QString& unit) {
  const QFontMetrics fm = p.fontMetrics();
  const int margin = left_margin(fm);
  p.setPen(text.darker(150));
  p.drawRect(f.area);
  p.setPen(text);
  const int x = f.area.left() - margin;  // the chart's own margin, left of its box
  p.drawText(QRect(x, f.area.top() - fm.height() - 2, f.area.right() - x, fm.height()),
             Qt::AlignLeft | Qt::AlignVCenter, title);
  p.drawText(QRect(x, f.area.top(), margin - 6, fm.height()), Qt::AlignRight,
             QString::number(top, 'g', 3) + unit);
  p.drawText(QRect(x, f.area.bottom() - fm.height(), margin - 6, fm.height()), Qt::AlignRight,
             QStringLiteral("0"));
  draw_frame_axis(p, f, text);
}

// A polyline of value(record) over the charted frames, scaled to [0, top].
void draw_series(QPainter& p, const ChartFrame& f, double top, const QPen& pen, const Series& value) {
  QPainterPath path;
  bool started = false;
  for (int k = f.first; k <= f.end(); ++k) {
    const double v = value((*f.records)[size_t(k)]);
    if (!std::isfinite(v)) {
      started = false;
      continue;
    }
    const QPointF point(f.x(k), f.area.bottom() - std::min(v / top, 1.0) * f.area.height());
    if (started) path.lineTo(point); else path.moveTo(point);
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

double series_top(const ChartFrame& f, const Series& value, double floor) {
  double top = floor;
  for (int k = f.first; k <= f.end(); ++k) {
    const double v = value((*f.records)[size_t(k)]);
    if (std::isfinite(v)) top = std::max(top, v);
  }
  return top * 1.1;
}

// The level colours' key, right-aligned in the strip above the levels chart.
void draw_level_legend(QPainter& p, const QRect& area, const QColor& text) {
  const QFontMetrics fm = p.fontMetrics();
  const int box = fm.height() * 2 / 3, gap = fm.height() / 2;
  int x = area.right();
  for (int level = kLevelCount - 1; level >= 0; --level) {
    const QString name = QString::fromUtf8(level_name(Level(level)));
    x -= fm.horizontalAdvance(name);
    p.setPen(text);
    p.drawText(QPoint(x, area.top() - fm.descent() - 3), name);
    x -= box + 4;
    const QRect swatch(x, area.top() - 3 - (fm.height() + box) / 2, box, box);
    p.fillRect(swatch, level_qcolor(level));
    p.drawRect(swatch);
    x -= gap;
  }
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

// Level L's budget: the error it would leave against its threshold, and the measured error.
void draw_budget(QPainter& p, const ChartFrame& f, int level, double threshold,
                 const QColor& text) {
  const Series estimate = drawn_only([level](const AnimationFrame& r) {
    if (r.layer_reports.size() != 1 || r.frame == 0) return std::nan("");
    const FrameReport& books = r.layer_reports.front();
    return neglected_error(books.carried, books.flow, Level(level));
  });
  const Series measured = drawn_only([](const AnimationFrame& r) { return r.max_measured_error_px; });
  const double top = std::max(series_top(f, estimate, threshold), series_top(f, measured, 0.1));
  draw_frame_box(p, f, QObject::tr("%1: error left").arg(level_name(Level(level))),
                 top, text, QStringLiteral(" px"));
  QPen dashed(text, 1.0, Qt::DashLine);
  const double y = f.area.bottom() - std::min(threshold / top, 1.0) * f.area.height();
  p.setPen(dashed);
  p.drawLine(QPointF(f.area.left(), y), QPointF(f.area.right(), y));
  draw_series(p, f, top, QPen(level_qcolor(level), 2.0), estimate);
  draw_series(p, f, top, QPen(text, 1.0), measured);
}

void draw_current(QPainter& p, const ChartFrame& f, const QColor& text) {
  p.setPen(QPen(text, 1.0, Qt::DotLine));
  p.drawLine(QPointF(f.x(f.current), f.area.top()), QPointF(f.x(f.current), f.area.bottom()));
}

// Chart rectangles for a widget `rect` and font: a status line, three full-width rows and a
// row of four budget charts; a title strip above and a frame axis below each chart.
std::vector<QRect> chart_areas(const QRect& rect, const QFontMetrics& fm) {
  const int line = fm.height(), margin = left_margin(fm), right = 16;
  const int title = line + 4, axis = line + 8, status = line + 8;
  const int row = std::max(20, (rect.height() - status) / 4 - title - axis);
  const int width = rect.width() - margin - right;
  std::vector<QRect> result;
  const auto top_of = [&](int i) { return status + title + i * (row + title + axis); };
  for (int i = 0; i < 3; ++i) result.emplace_back(margin, top_of(i), width, row);
  const int quarter = (rect.width() - right) / 4;
  for (int i = 0; i < 4; ++i) {
    result.emplace_back(i * quarter + margin, top_of(3), quarter - margin - right / 2, row);
  }
  return result;
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
  EngineSettings settings;
  ViewTheme theme;

  void paint(QPainter& p, const QRect& rect) const;
  std::vector<QRect> areas(const QRect& rect) const {
    return chart_areas(rect, QFontMetrics(chart_font(theme)));
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
  const auto chart = [&](int i) {
    return ChartFrame{records, view_->first_, view_->last_, view_->current_, a[size_t(i)]};
  };
  const Series time = [](const AnimationFrame& r) { return r.time_ms; };
  const double time_top = series_top(chart(0), time, 1.0);
  draw_frame_box(p, chart(0), tr("frame time of the engine"), time_top, text, QStringLiteral(" ms"));
  draw_series(p, chart(0), time_top, QPen(text, 1.5), time);
  draw_levels(p, chart(1), text);
  draw_frame_box(p, chart(2), tr("approximated (not re-rendered)"), 100.0, text, QStringLiteral("%"));
  draw_series(p, chart(2), 100.0, QPen(level_qcolor(int(Level::kAffine)), 2.0),
              drawn_only([](const AnimationFrame& r) { return approximated_percent(r); }));
  for (int level = 0; level < kTermCount; ++level) {
    draw_budget(p, chart(3 + level), level, settings.thresholds[size_t(level)], text);
  }
  for (int i = 0; i < kChartCount; ++i) draw_current(p, chart(i), text);
}

AnalysisView::AnalysisView(AnimationModel* model, QWidget* parent)
    : ViewPage(parent), model_(model), theme_(view_theme(false)) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(2, 2, 2, 2);
  auto* bar = new QHBoxLayout;
  whole_run_box_ = new QCheckBox(tr("Whole loop"), this);
  whole_run_box_->setObjectName(QStringLiteral("analysis_whole_run"));
  whole_run_box_->setToolTip(
      tr("Chart every frame of the loop; otherwise the last %1 frames").arg(kRecentFrames));
  bar->addWidget(whole_run_box_);
  key_ = new QLabel(tr("Dashed: threshold. Coloured: error the level would leave. "
                       "Thin: measured error. Click a chart to jump to that frame."),
                    this);
  key_->setWordWrap(true);
  key_->setToolTip(tr("How to read the four budget charts of the bottom row"));
  bar->addWidget(key_, 1);
  layout->addLayout(bar);
  charts_ = new Charts(this);
  layout->addWidget(charts_, 1);
  connect(whole_run_box_, &QCheckBox::toggled, this, [this] { refresh(); });
  connect(model_, &AnimationModel::frame_changed, this, &AnalysisView::refresh);
  connect(model_, &AnimationModel::source_changed, this, &AnalysisView::refresh);
}

bool AnalysisView::whole_run() const { return whole_run_box_->isChecked(); }
void AnalysisView::set_whole_run(bool on) { whole_run_box_->setChecked(on); }

QRect AnalysisView::chart_area(int index) const {
  const std::vector<QRect> areas = charts_->areas(charts_->rect());
  return index >= 0 && index < kChartCount ? areas[size_t(index)] : QRect();
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

QString AnalysisView::status_text() const {
  const std::vector<AnimationFrame>* records = charts_->records;
  if (!records || records->empty()) return QString();
  const AnimationFrame& now = records->back();
  const QString reason = not_drawn_reason(now);
  if (!reason.isEmpty()) {
    return tr("Frame %1: nothing is drawn (%2); the charts leave a gap.").arg(now.frame).arg(reason);
  }
  return tr("Frame %1: %2 of %3 layers drawn, %4% approximated, largest measured error %5 px.")
      .arg(now.frame)
      .arg(now.drawn())
      .arg(now.layers)
      .arg(approximated_percent(now), 0, 'f', 0)
      .arg(now.max_measured_error_px, 0, 'f', 2);
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

double AnalysisView::smallest_text_px() const {
  return QFontInfo(chart_font(theme_)).pixelSize();
}

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
