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
#include "views/palette.h"

namespace oflab {
namespace {

constexpr int kLeftMargin = 64;
constexpr int kRightMargin = 16;

QColor qcolor(const RgbF& c) { return QColor::fromRgbF(c[0], c[1], c[2]); }
QColor level_qcolor(int level) {
  const Rgb8 c = level_colour(static_cast<Level>(level));
  return QColor(c.r, c.g, c.b);
}

// What one chart draws: the records in the window and the x position of a frame.
struct ChartFrame {
  const std::vector<AnimationFrame>* records;
  int first = 0, last = 0;
  QRect area;
  double x(double frame) const {
    const int n = last - first + 1;
    return area.left() + (frame - first + 0.5) * area.width() / std::max(1, n);
  }
  double bar_width() const { return std::max(1.0, double(area.width()) / (last - first + 1)); }
};

void draw_frame_box(QPainter& p, const ChartFrame& f, const QString& title, double top,
                    const QColor& text, const QString& unit) {
  p.setPen(text.darker(150));
  p.drawRect(f.area);
  p.setPen(text);
  const int x = f.area.left() - kLeftMargin;  // the chart's own margin, left of its box
  p.drawText(QRect(x, f.area.top() - 18, f.area.right() - x, 16), Qt::AlignLeft | Qt::AlignVCenter,
             QStringLiteral("  ") + title);
  p.drawText(QRect(x, f.area.top(), kLeftMargin - 6, 16), Qt::AlignRight,
             QString::number(top, 'g', 3) + unit);
  p.drawText(QRect(x, f.area.bottom() - 14, kLeftMargin - 6, 16), Qt::AlignRight,
             QStringLiteral("0"));
}

// A polyline of value(record) over the window, scaled to [0, top].
void draw_series(QPainter& p, const ChartFrame& f, double top, const QPen& pen,
                 const std::function<double(const AnimationFrame&)>& value) {
  QPainterPath path;
  bool started = false;
  for (int k = f.first; k <= f.last; ++k) {
    const double v = value((*f.records)[size_t(k)]);
    if (!std::isfinite(v)) {
      started = false;
      continue;
    }
    const QPointF point(f.x(k), f.area.bottom() - std::min(v / top, 1.0) * f.area.height());
    if (started) path.lineTo(point); else path.moveTo(point);
    started = true;
  }
  p.setPen(pen);
  p.setBrush(Qt::NoBrush);
  p.drawPath(path);
}

double series_top(const ChartFrame& f, const std::function<double(const AnimationFrame&)>& value,
                  double floor) {
  double top = floor;
  for (int k = f.first; k <= f.last; ++k) {
    const double v = value((*f.records)[size_t(k)]);
    if (std::isfinite(v)) top = std::max(top, v);
  }
  return top * 1.1;
}

void draw_levels(QPainter& p, const ChartFrame& f, const QColor& text) {
  int top = 1;
  for (int k = f.first; k <= f.last; ++k) top = std::max(top, (*f.records)[size_t(k)].drawn());
  draw_frame_box(p, f, QObject::tr("layers per level (stacked)"), top, text, QString());
  const double unit = double(f.area.height()) / top;
  for (int k = f.first; k <= f.last; ++k) {
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
  const auto estimate = [level](const AnimationFrame& r) {
    if (r.layer_reports.size() != 1 || r.frame == 0) return std::nan("");
    const FrameReport& books = r.layer_reports.front();
    return neglected_error(books.carried, books.flow, Level(level));
  };
  const auto measured = [](const AnimationFrame& r) {
    return r.drawn() > 0 ? r.max_measured_error_px : std::nan("");
  };
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

void draw_current(QPainter& p, const ChartFrame& f, int frame, const QColor& text) {
  p.setPen(QPen(text, 1.0, Qt::DotLine));
  p.drawLine(QPointF(f.x(frame), f.area.top()), QPointF(f.x(frame), f.area.bottom()));
}

}  // namespace

// The painted charts; the view owns it and tells it what to draw.
class AnalysisView::Charts : public QWidget {
 public:
  explicit Charts(AnalysisView* view) : QWidget(view), view_(view) {
    setObjectName(QStringLiteral("analysis_charts"));
    setAttribute(Qt::WA_OpaquePaintEvent);
    setMinimumSize(400, 300);
  }
  const std::vector<AnimationFrame>* records = nullptr;
  EngineSettings settings;
  ViewTheme theme;

  void paint(QPainter& p, const QRect& rect) const;
  // Chart rectangles: 0 time, 1 levels, 2 percent, 3..6 the four budgets.
  std::vector<QRect> areas(const QRect& rect) const;

 protected:
  void paintEvent(QPaintEvent*) override {
    QPainter p(this);
    paint(p, rect());
  }
  void mousePressEvent(QMouseEvent* event) override {
    const int frame = view_->frame_at(event->pos().x());
    if (frame >= 0) view_->model_->scene_model()->set_frame(frame);
  }

 private:
  AnalysisView* view_;
};

std::vector<QRect> AnalysisView::Charts::areas(const QRect& rect) const {
  // Three full-width rows and a row of four budget charts, 22 px of title above each.
  const int row = (rect.height() - 4 * 26) / 4;
  const int width = rect.width() - kLeftMargin - kRightMargin;
  std::vector<QRect> result;
  for (int i = 0; i < 3; ++i) result.emplace_back(kLeftMargin, 24 + i * (row + 26), width, row);
  const int quarter = (rect.width() - 4 * kLeftMargin) / 4;
  for (int i = 0; i < 4; ++i) {
    result.emplace_back(kLeftMargin + i * (quarter + kLeftMargin), 24 + 3 * (row + 26),
                        quarter - kRightMargin / 2, row);
  }
  return result;
}

void AnalysisView::Charts::paint(QPainter& p, const QRect& rect) const {
  const QColor text = qcolor(theme.text);
  p.fillRect(rect, qcolor(theme.background));
  QFont font = p.font();
  font.setPixelSize(theme.presentation ? 16 : 12);
  p.setFont(font);
  if (!records || records->empty()) {
    p.setPen(text);
    p.drawText(rect, Qt::AlignCenter, tr("Nothing to analyse: the animation cannot play."));
    return;
  }
  p.setRenderHint(QPainter::Antialiasing, true);
  const std::vector<QRect> a = areas(rect);
  const auto chart = [&](int i) { return ChartFrame{records, view_->first_, view_->last_, a[size_t(i)]}; };
  const auto time = [](const AnimationFrame& r) { return r.time_ms; };
  const double time_top = series_top(chart(0), time, 1.0);
  draw_frame_box(p, chart(0), tr("frame time of the engine"), time_top, text, QStringLiteral(" ms"));
  draw_series(p, chart(0), time_top, QPen(text, 1.5), time);
  draw_levels(p, chart(1), text);
  draw_frame_box(p, chart(2), tr("approximated (not re-rendered)"), 100.0, text, QStringLiteral("%"));
  draw_series(p, chart(2), 100.0, QPen(level_qcolor(int(Level::kAffine)), 2.0),
              [](const AnimationFrame& r) { return approximated_percent(r); });
  for (int level = 0; level < kTermCount; ++level) {
    draw_budget(p, chart(3 + level), level, settings.thresholds[size_t(level)], text);
  }
  for (int i = 0; i < 7; ++i) draw_current(p, chart(i), view_->last_, text);
}

AnalysisView::AnalysisView(AnimationModel* model, QWidget* parent)
    : ViewPage(parent), model_(model), theme_(view_theme(false)) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(2, 2, 2, 2);
  auto* bar = new QHBoxLayout;
  whole_run_box_ = new QCheckBox(tr("Whole run (else the last %1 frames)").arg(kRecentFrames), this);
  bar->addWidget(whole_run_box_);
  auto* key = new QLabel(tr("Dashed: threshold. Coloured: error the level would leave. "
                            "Thin: measured error. Click a chart to jump to that frame."),
                         this);
  key->setWordWrap(true);
  bar->addWidget(key, 1);
  layout->addLayout(bar);
  charts_ = new Charts(this);
  layout->addWidget(charts_, 1);
  connect(whole_run_box_, &QCheckBox::toggled, this, [this] { refresh(); });
  connect(model_, &AnimationModel::frame_changed, this, &AnalysisView::refresh);
  connect(model_, &AnimationModel::source_changed, this, &AnalysisView::refresh);
}

bool AnalysisView::whole_run() const { return whole_run_box_->isChecked(); }
void AnalysisView::set_whole_run(bool on) { whole_run_box_->setChecked(on); }

int AnalysisView::frame_at(int x) const {
  if (x < kLeftMargin || x > charts_->width() - kRightMargin || last_ < first_) return -1;
  const double span = charts_->width() - kLeftMargin - kRightMargin;
  const int n = last_ - first_ + 1;
  return std::clamp(first_ + int((x - kLeftMargin) * n / span), first_, last_);
}

void AnalysisView::read_model() {
  const std::vector<AnimationFrame>& history = model_->history();
  charts_->records = history.empty() ? nullptr : &history;
  charts_->settings = model_->settings();
  charts_->theme = theme_;
  last_ = history.empty() ? 0 : history.back().frame;
  first_ = whole_run() ? 0 : std::max(0, last_ - kRecentFrames + 1);
}

void AnalysisView::refresh() {
  if (!isVisible()) return;
  read_model();
  charts_->update();
}

QImage AnalysisView::render_image() {
  read_model();
  QImage image(charts_->size().expandedTo(QSize(800, 500)), QImage::Format_RGB32);
  QPainter painter(&image);
  charts_->paint(painter, image.rect());
  return image;
}

void AnalysisView::set_theme(const ViewTheme& theme) {
  theme_ = theme;
  refresh();
}

void AnalysisView::showEvent(QShowEvent* event) {
  ViewPage::showEvent(event);
  refresh();
}

}  // namespace oflab
