#include "views/slices_view.h"

#include <QFontMetricsF>
#include <QHBoxLayout>
#include <QPainter>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <functional>

#include "adapters/exact_frames.h"
#include "adapters/frame_images.h"
#include "formats/scene_file.h"
#include "formats/viewer_script_file.h"
#include "models/scene_model.h"
#include "models/window_model.h"
#include "views/slider_spin.h"

namespace oflab {
namespace {

QColor qcolor(const RgbF& c, int alpha = 255) {
  return QColor::fromRgbF(c[0], c[1], c[2], alpha / 255.0);
}

// The diagram's text: the theme's caption size.
QFont diagram_font(const ViewTheme& theme) {
  QFont font;
  font.setPixelSize(theme.font_size);
  return font;
}

// Lateral extent of the diagram, world units either side of the axis.
constexpr double kHalfWidth = 12.0;

const QColor kBandA(90, 170, 120, 60), kBandB(90, 120, 170, 60);
const QColor kAsymptote(213, 94, 0);  // Okabe-Ito vermillion
const QColor kPlane(230, 159, 0);     // Okabe-Ito orange

// The depth axis under the diagram: a tick and label at each depth_ticks value, the eye's
// 0 at the left, and the axis title at the right.
void draw_depth_axis(QPainter& p, const std::function<double(double)>& x_of, double left,
                     double right, double bottom, double max_depth, const QColor& text) {
  const QFontMetricsF fm(p.font());
  p.setPen(QPen(text, 1));
  p.drawLine(QPointF(left, bottom), QPointF(right, bottom));
  double last_right = -1e9;
  for (double z : depth_ticks(max_depth)) {
    const double x = x_of(z);
    p.drawLine(QPointF(x, bottom), QPointF(x, bottom + 5));
    const QString label = QString::number(z);
    const double w = fm.horizontalAdvance(label);
    if (x - w / 2 < last_right + 6) continue;  // too close to the previous label
    p.drawText(QPointF(x - w / 2, bottom + 5 + fm.ascent()), label);
    last_right = x + w / 2;
  }
  p.drawText(QRectF(left, bottom + 6 + fm.height(), right - left, fm.height()), Qt::AlignRight,
             QStringLiteral("depth Z, world units (square-root scale)"));
}

// The legend from `area`'s top left: a swatch of each mark and its meaning, in as many
// rows as the width needs. Returns the y below its last row.
double draw_diagram_legend(QPainter& p, const QRectF& area, const ViewTheme& theme) {
  const QFontMetricsF fm(p.font());
  const double h = fm.height(), swatch = 1.6 * h;
  double x = area.left(), y = area.top();
  auto entry = [&](const QString& name, const std::function<void(const QRectF&)>& mark) {
    const double width = swatch + 4 + fm.horizontalAdvance(name);
    if (x > area.left() && x + width > area.right()) x = area.left(), y += 1.2 * h;
    const QRectF box(x, y + 0.15 * h, swatch, 0.7 * h);
    mark(box);
    p.setPen(qcolor(theme.text));
    p.drawText(QPointF(box.right() + 4, y + fm.ascent()), name);
    x += width + h;
  };
  entry(QStringLiteral("slices"), [&](const QRectF& b) {
    p.fillRect(QRectF(b.left(), b.top(), b.width() / 2, b.height()), kBandA);
    p.fillRect(QRectF(b.center().x(), b.top(), b.width() / 2, b.height()), kBandB);
  });
  entry(QStringLiteral("slice boundary"), [&](const QRectF& b) {
    p.setPen(QPen(qcolor(theme.outline), 1));
    p.drawLine(QPointF(b.center().x(), b.top()), QPointF(b.center().x(), b.bottom()));
  });
  entry(QStringLiteral("asymptote k|V|/epsilon"), [&](const QRectF& b) {
    p.setPen(QPen(kAsymptote, 2, Qt::DashLine));
    p.drawLine(QPointF(b.center().x(), b.top()), QPointF(b.center().x(), b.bottom()));
  });
  entry(QStringLiteral("scene plane (seen from above)"), [&](const QRectF& b) {
    p.setPen(QPen(kPlane, 4));
    p.drawLine(QPointF(b.center().x(), b.top()), QPointF(b.center().x(), b.bottom()));
  });
  return y + 1.2 * h;
}

// A camera frame (premultiplied, painted over the background) scaled to fit under its title
// in an image of `area`; an empty frame shows the title alone.
QPixmap titled_picture(const Image& frame, const QString& title, const QSize& area,
                       const ViewTheme& theme) {
  QImage image(area, QImage::Format_RGB32);
  image.fill(qcolor(theme.background));
  QPainter p(&image);
  QFont font = diagram_font(theme);
  font.setBold(true);
  p.setFont(font);
  p.setPen(qcolor(theme.text));
  const double title_h = 1.6 * theme.font_size;
  p.drawText(QRectF(0, 0, area.width(), title_h), Qt::AlignCenter, title);
  if (!frame.empty()) {
    const QSize fitted = QSize(frame.width(), frame.height())
                             .scaled(area - QSize(0, int(title_h)), Qt::KeepAspectRatio);
    const QRectF target(0.5 * (area.width() - fitted.width()), title_h, fitted.width(),
                        fitted.height());
    p.setRenderHint(QPainter::SmoothPixmapTransform, true);
    p.drawImage(target, image_view(frame));
    p.setPen(QPen(qcolor(theme.muted), 1));
    p.drawRect(target);
  }
  p.end();
  return QPixmap::fromImage(std::move(image));  // moved: no copy of the pixels
}

}  // namespace

std::vector<double> depth_ticks(double max_depth) {
  std::vector<double> ticks;
  for (double decade = 1.0; decade <= max_depth; decade *= 10.0) {
    for (double step : {1.0, 2.0, 5.0}) {
      if (step * decade <= max_depth) ticks.push_back(step * decade);
    }
  }
  return ticks;
}

QImage slice_diagram(int width, int height, const std::vector<Slice>& slices, double asymptote,
                     const std::vector<DiagramPlane>& planes, double max_depth,
                     const ViewTheme& theme) {
  QImage image(width, height, QImage::Format_RGB32);
  image.fill(qcolor(theme.background));
  QPainter p(&image);
  p.setRenderHint(QPainter::Antialiasing);
  p.setFont(diagram_font(theme));
  const double line = QFontMetricsF(p.font()).height();
  const double left = 40, right = width - 20, bottom = height - 2.4 * line - 10;
  p.setPen(qcolor(theme.text));
  p.drawText(QPointF(left, line), QString("%1 slices (%2 finite + background)")
                                      .arg(slices.size())
                                      .arg(slices.empty() ? 0 : slices.size() - 1));
  // Under the legend, a row of its own for the asymptote's label, so it never meets the
  // legend, the plane marks or the bands' edges.
  const double label_row =
      draw_diagram_legend(p, QRectF(left, 1.3 * line, right - left, line), theme);
  const double top = label_row + 1.2 * line + 4;
  std::function<double(double)> x_of = [&](double z) {
    return left + (right - left) * std::sqrt(std::min(z, max_depth) / max_depth);
  };
  auto y_of = [&](double x) { return top + (bottom - top) * (0.5 - x / (2.0 * kHalfWidth)); };
  const QColor text = qcolor(theme.text);
  // Alternate slice bands, boundaries, and the background slice.
  for (size_t i = 0; i < slices.size(); ++i) {
    const double far = std::isfinite(slices[i].far) ? slices[i].far : max_depth;
    const QRectF band(QPointF(x_of(slices[i].near), top), QPointF(x_of(far), bottom));
    p.fillRect(band, i % 2 ? kBandB : kBandA);
    p.setPen(QPen(qcolor(theme.outline), 1));
    p.drawLine(QPointF(band.left(), top), QPointF(band.left(), bottom));
  }
  // The asymptote k|V|/epsilon.
  if (std::isfinite(asymptote)) {
    p.setPen(QPen(kAsymptote, 2, Qt::DashLine));
    p.drawLine(QPointF(x_of(asymptote), top), QPointF(x_of(asymptote), bottom));
    p.drawLine(QPointF(x_of(asymptote), label_row + line), QPointF(x_of(asymptote), top));
    p.setPen(text);
    const QString label = QString("asymptote Z = %1").arg(asymptote, 0, 'f', 2);
    const double w = QFontMetricsF(p.font()).horizontalAdvance(label);
    // Centred over its line, kept inside the diagram.
    const double x = std::clamp(x_of(asymptote) - w / 2, left, std::max(left, right - w));
    p.drawText(QRectF(x, label_row, w + 1, line), Qt::AlignLeft | Qt::AlignVCenter, label);
  }
  // The scene's planes, seen from above.
  p.setPen(QPen(kPlane, 4));
  for (const DiagramPlane& pl : planes) {
    if (pl.depth <= 0) continue;
    p.drawLine(QPointF(x_of(pl.depth), y_of(std::clamp(pl.left, -kHalfWidth, kHalfWidth))),
               QPointF(x_of(pl.depth), y_of(std::clamp(pl.right, -kHalfWidth, kHalfWidth))));
  }
  // The eye.
  p.setPen(Qt::NoPen);
  p.setBrush(text);
  p.drawEllipse(QPointF(left, y_of(0.0)), 5, 5);
  p.setPen(text);
  p.drawText(QPointF(left - 30, y_of(0.0) - 8), "eye");
  draw_depth_axis(p, x_of, left, right, bottom, max_depth, text);
  return image;
}

SlicesView::SlicesView(WindowModel* window, QWidget* parent)
    : ViewPage(parent), window_(window), theme_(view_theme(false)) {
  epsilon_ = new SliderSpin("epsilon", 0.25, 8.0, 0.25, 2, " px/frame", this);
  speed_ = new SliderSpin("speed |V|", 0.01, 0.2, 0.01, 2, " units/frame", this);
  epsilon_->set_description(
      tr("Tolerance epsilon: how far apart, at most, the points of one "
         "slice may move in a frame"));
  speed_->set_description(tr("Speed |V| of the viewer moving sideways"));
  diagram_ = new QLabel(this);
  frame_label_ = new QLabel(this);
  exact_label_ = new QLabel(this);
  caption_ = new QLabel(this);
  caption_->setWordWrap(true);
  // The pictures follow the tab's size instead of setting the window's minimum width.
  for (QLabel* picture : {diagram_, frame_label_, exact_label_}) {
    picture->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Ignored);
    picture->setMinimumSize(160, 120);
    picture->setAlignment(Qt::AlignCenter);
  }
  auto* controls = new QHBoxLayout;
  controls->addWidget(epsilon_);
  controls->addWidget(speed_);
  auto* pictures = new QHBoxLayout;
  auto* frames = new QVBoxLayout;  // wide camera frames: one above the other
  frames->addWidget(frame_label_, 1);
  frames->addWidget(exact_label_, 1);
  pictures->addWidget(diagram_, 1);
  pictures->addLayout(frames, 1);
  auto* layout = new QVBoxLayout(this);
  layout->addLayout(controls);
  layout->addLayout(pictures, 1);
  layout->addWidget(caption_);
  try {
    scene_ = read_scene_file(resolve_scene_path("train-window"));
    script_ = read_viewer_script_file(resolve_viewer_script_path("train-sideways"));
  } catch (const std::exception& e) {
    problem_ = QString::fromStdString(e.what());
  }
  if (problem_.isEmpty()) {
    try {
      exact_ = exact_renderers().front().make(scene_, script_.camera, EngineSettings());
    } catch (const std::exception& e) {  // a scene the renderer refuses: the slices alone
      exact_problem_ = QString::fromStdString(e.what());
    }
  }
  epsilon_->set_value(1.0);
  speed_->set_value(0.05);
  connect(epsilon_, &SliderSpin::edited, this, [this](double) { restart(); });
  connect(speed_, &SliderSpin::edited, this, [this](double) { restart(); });
  connect(window_->scene(), &SceneModel::scene_changed, this, &SlicesView::follow_frame);
  restart();
}

SlicesView::~SlicesView() = default;

double SlicesView::epsilon_px() const { return epsilon_->value(); }

const Image& SlicesView::shifted_image() const {
  static const Image kEmpty;
  return renderer_ ? renderer_->frame() : kEmpty;
}

// The exact projection of the script's current frame (core's exact render), beside the
// slices' frame.
void SlicesView::render_exact() {
  exact_frame_ = Image();
  if (!exact_ || frame_ >= static_cast<int>(script_.frames.size())) return;
  exact_frame_ = exact_->render(script_.frames[size_t(frame_)].pose);
}
double SlicesView::speed() const { return speed_->value(); }

void SlicesView::restart() {
  frame_ = 0;
  renderer_.reset();
  slices_.clear();
  diagram_current_ = false;
  if (problem_.isEmpty() && !script_.frames.empty()) {
    SceneShiftingSettings s;
    s.epsilon_px = epsilon_->value();
    s.design_speed = speed_->value();
    try {
      renderer_ = std::make_unique<SceneShiftingRenderer>(scene_, script_.camera, s);
      renderer_->start(script_.frames[0].pose);
      slices_ = renderer_->slices();
    } catch (const std::exception& e) {
      renderer_.reset();
      caption_->setText(QString("Cannot slice: ") + e.what());
    }
  }
  refresh();
}

void SlicesView::follow_frame() {
  if (isVisible()) catch_up();
}

void SlicesView::showEvent(QShowEvent* event) {
  ViewPage::showEvent(event);
  catch_up();
}

void SlicesView::catch_up() {
  if (!renderer_ || script_.frames.size() < 2) return;
  const int target = window_->scene()->frame() % static_cast<int>(script_.frames.size());
  if (target == frame_) return;
  // Scene shifting keeps no undo state: going back restarts from frame 0 (as the animation
  // model does), so every frame shown is what an uninterrupted run shows.
  if (target < frame_) {
    const int kept = target;
    restart();
    if (kept == 0) return;
  }
  while (frame_ < target) {
    const ViewerFrame& previous = script_.frames[size_t(frame_)];
    ++frame_;
    renderer_->advance(previous.pose, previous.motion, script_.frames[size_t(frame_)].pose);
  }
  refresh();
}

void SlicesView::refresh() {
  if (!problem_.isEmpty()) {
    caption_->setText("Scene shifting needs the train-window scene: " + problem_);
    return;
  }
  std::vector<DiagramPlane> planes;
  if (!script_.frames.empty()) {
    for (const ScenePolygon& poly : scene_.polygons) {
      const Vec3 c = to_view(script_.frames[0].pose, poly.centre);
      planes.push_back({c.z, c.x - 0.5 * poly.size.x, c.x + 0.5 * poly.size.x});
    }
  }
  const double k = script_.camera.focal_px;
  const double asymptote = k * speed_->value() / epsilon_->value();
  const double max_depth = std::max(50.0, 1.25 * asymptote);
  // The diagram changes with the slices (a restart), the theme and the size, not per frame.
  const QSize area = diagram_->size().expandedTo(QSize(160, 120));
  if (!diagram_current_ || area != diagram_size_) {
    diagram_->setPixmap(QPixmap::fromImage(
        slice_diagram(area.width(), area.height(), slices_, asymptote, planes, max_depth, theme_)));
    diagram_current_ = true;
    diagram_size_ = area;
  }
  if (renderer_) {
    frame_label_->setPixmap(titled_picture(renderer_->frame(), tr("scene shifting (slices)"),
                                           frame_label_->size().expandedTo(QSize(160, 120)),
                                           theme_));
  }
  render_exact();
  exact_label_->setPixmap(titled_picture(
      exact_frame_,
      exact_problem_.isEmpty() ? QString::fromStdString(exact_renderers().front().title)
                               : exact_problem_,
      exact_label_->size().expandedTo(QSize(160, 120)), theme_));
  // The walk is shorter than the window's loop: say which of its frames the play bar's is.
  const int window_frame = window_->scene()->frame();
  const QString wrapped = window_frame == frame_
                              ? QString()
                              : QString(" (the play bar's frame %1: the %2-frame walk repeats)")
                                    .arg(window_frame)
                                    .arg(script_.frames.size());
  caption_->setText(QString("Frame %1%2: a viewer moving sideways at %3 units/frame, slices "
                            "cut so every point of a slice moves within %4 px of the others "
                            "(eq. 9, asymptote k|V|/epsilon = %5).")
                        .arg(frame_)
                        .arg(wrapped)
                        .arg(speed_->value())
                        .arg(epsilon_->value())
                        .arg(asymptote, 0, 'f', 2));
}

QString SlicesView::caption() const { return caption_->text(); }

QImage SlicesView::render_image() {
  catch_up();
  refresh();
  return grab().toImage();
}

void SlicesView::resizeEvent(QResizeEvent* event) {
  ViewPage::resizeEvent(event);
  refresh();
}

QString SlicesView::scene_panel_note() const {
  return tr(
      "This view plays its own train-window scene, not the plane of this panel: the "
      "plane, motion and camera below apply to the flow and basis views.");
}

double SlicesView::smallest_text_px() const { return QFontInfo(diagram_font(theme_)).pixelSize(); }

void SlicesView::set_theme(const ViewTheme& theme) {
  theme_ = theme;
  diagram_current_ = false;
  refresh();
}

}  // namespace oflab
