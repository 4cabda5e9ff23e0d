#include "views/analysis_view.h"

#include <QCheckBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMouseEvent>
#include <QPainter>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "models/animation_model.h"
#include "models/scene_model.h"
#include "models/window_model.h"
#include "player/policy_comparison.h"
#include "player/run_player.h"
#include "views/analysis_charts.h"
#include "views/frame_inspector.h"

namespace oflab {
namespace {

QColor qcolor(const RgbF& c) { return QColor::fromRgbF(c[0], c[1], c[2]); }

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
  // 2 when a comparison chart's title and key do not fit one line, else 1.
  int title_lines(const QRect& rect) const {
    return compared ? comparison_title_lines(rect, QFontMetrics(chart_font(theme)), *compared) : 1;
  }
  std::vector<QRect> areas(const QRect& rect) const {
    return chart_areas(rect, QFontMetrics(chart_font(theme)), compared != nullptr,
                       title_lines(rect));
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
  std::vector<ChartFrame> charts;
  for (const QRect& area : areas(rect)) {
    charts.push_back(
        ChartFrame{records, view_->first_, view_->last_, view_->current_, area, title_lines(rect)});
  }
  if (compared) {
    paint_comparison_charts(p, rect, charts, *compared, text);
  } else {
    paint_engine_charts(p, charts, settings, text);
  }
  for (const ChartFrame& chart : charts) draw_current(p, chart, text);
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
  return frame_axis_ticks(first, last, width_px, label_px);
}

int AnalysisView::threshold_crossings(int level) const {
  const std::vector<AnimationFrame>* records = charts_->records;
  if (comparing() || !records || level < 0 || level >= kTermCount) return -1;
  const double threshold = charts_->settings.thresholds[size_t(level)];
  int crossings = 0;
  bool below = false, seen = false;  // the last charted value, gaps skipped
  for (int k = first_; k <= std::min(current_, int(records->size()) - 1); ++k) {
    const double v = level_budget_at((*records)[size_t(k)], level);
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
                         "Dotted: measured error. Click a chart to jump to that frame."));
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

QSize AnalysisView::image_size() const { return charts_->size().expandedTo(QSize(800, 500)); }

std::vector<PaintedText> AnalysisView::painted_texts() {
  read_model();
  const QSize size = image_size();
  return record_painted_text(size, [&](QPainter& p) { charts_->paint(p, QRect(QPoint(), size)); });
}

std::vector<QString> AnalysisView::text_problems() {
  return oflab::text_problems(painted_texts(), image_size());
}

QImage AnalysisView::render_image() {
  read_model();
  QImage image(image_size(), QImage::Format_RGB32);
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
