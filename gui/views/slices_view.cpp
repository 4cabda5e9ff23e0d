#include "views/slices_view.h"

#include <QHBoxLayout>
#include <QPainter>
#include <QVBoxLayout>
#include <cmath>

#include "formats/scene_file.h"
#include "formats/viewer_script_file.h"
#include "adapters/frame_images.h"
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

}  // namespace

QImage slice_diagram(int width, int height, const std::vector<Slice>& slices, double asymptote,
                     const std::vector<DiagramPlane>& planes, double max_depth,
                     const ViewTheme& theme) {
  QImage image(width, height, QImage::Format_RGB32);
  image.fill(qcolor(theme.background));
  QPainter p(&image);
  p.setRenderHint(QPainter::Antialiasing);
  const double left = 40, right = width - 20, top = 30, bottom = height - 30;
  auto x_of = [&](double z) {
    return left + (right - left) * std::sqrt(std::min(z, max_depth) / max_depth);
  };
  auto y_of = [&](double x) { return top + (bottom - top) * (0.5 - x / (2.0 * kHalfWidth)); };
  p.setFont(diagram_font(theme));
  const QColor text = qcolor(theme.text);
  // Alternate slice bands, boundaries, and the background slice.
  for (size_t i = 0; i < slices.size(); ++i) {
    const double far = std::isfinite(slices[i].far) ? slices[i].far : max_depth;
    const QRectF band(QPointF(x_of(slices[i].near), top), QPointF(x_of(far), bottom));
    p.fillRect(band, i % 2 ? QColor(90, 120, 170, 60) : QColor(90, 170, 120, 60));
    p.setPen(QPen(qcolor(theme.outline), 1));
    p.drawLine(QPointF(band.left(), top), QPointF(band.left(), bottom));
  }
  // The asymptote k|V|/epsilon.
  if (std::isfinite(asymptote)) {
    p.setPen(QPen(QColor(213, 94, 0), 2, Qt::DashLine));
    p.drawLine(QPointF(x_of(asymptote), top), QPointF(x_of(asymptote), bottom));
    p.setPen(text);
    p.drawText(QPointF(x_of(asymptote) + 4, top + theme.font_size),
               QString("asymptote Z = %1").arg(asymptote, 0, 'f', 2));
  }
  // The scene's planes, seen from above.
  p.setPen(QPen(QColor(230, 159, 0), 4));
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
  p.drawText(QPointF(left - 30, bottom + 20), "eye");
  // Right-aligned to the diagram's edge, whatever the font size.
  p.drawText(QRectF(left, bottom + 4, right - left, p.fontMetrics().height()), Qt::AlignRight,
             QString("depth (sqrt scale) to %1").arg(max_depth, 0, 'f', 0));
  p.drawText(QPointF(left, top - 10), QString("%1 slices (%2 finite + background)")
                                          .arg(slices.size())
                                          .arg(slices.empty() ? 0 : slices.size() - 1));
  return image;
}

SlicesView::SlicesView(QWidget* parent) : ViewPage(parent), theme_(view_theme(false)) {
  epsilon_ = new SliderSpin("epsilon", 0.25, 8.0, 0.25, 2, " px/frame", this);
  speed_ = new SliderSpin("speed |V|", 0.01, 0.2, 0.01, 2, " units/frame", this);
  epsilon_->set_description(tr("Tolerance epsilon: how far apart, at most, the points of one "
                               "slice may move in a frame"));
  speed_->set_description(tr("Speed |V| of the viewer moving sideways"));
  diagram_ = new QLabel(this);
  frame_label_ = new QLabel(this);
  caption_ = new QLabel(this);
  caption_->setWordWrap(true);
  // The pictures follow the tab's size instead of setting the window's minimum width.
  for (QLabel* picture : {diagram_, frame_label_}) {
    picture->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Ignored);
    picture->setMinimumSize(160, 120);
    picture->setAlignment(Qt::AlignCenter);
  }
  auto* controls = new QHBoxLayout;
  controls->addWidget(epsilon_);
  controls->addWidget(speed_);
  auto* pictures = new QHBoxLayout;
  pictures->addWidget(diagram_);
  pictures->addWidget(frame_label_);
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
  epsilon_->set_value(1.0);
  speed_->set_value(0.05);
  connect(epsilon_, &SliderSpin::edited, this, [this](double) { restart(); });
  connect(speed_, &SliderSpin::edited, this, [this](double) { restart(); });
  restart();
}

SlicesView::~SlicesView() = default;

double SlicesView::epsilon_px() const { return epsilon_->value(); }
double SlicesView::speed() const { return speed_->value(); }

void SlicesView::restart() {
  frame_ = 0;
  renderer_.reset();
  slices_.clear();
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

void SlicesView::step_animation() {
  if (!renderer_ || script_.frames.size() < 2) return;
  if (frame_ + 1 >= static_cast<int>(script_.frames.size())) {
    restart();
    return;
  }
  const ViewerFrame& previous = script_.frames[frame_];
  ++frame_;
  renderer_->advance(previous.pose, previous.motion, script_.frames[frame_].pose);
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
  const QSize area = diagram_->size().expandedTo(QSize(160, 120));
  diagram_->setPixmap(QPixmap::fromImage(slice_diagram(area.width(), area.height(), slices_,
                                                       asymptote, planes, max_depth, theme_)));
  if (renderer_) {
    const QImage frame = flatten_image(renderer_->frame(), qcolor(theme_.background));
    frame_label_->setPixmap(QPixmap::fromImage(
        frame.scaled(frame_label_->size().expandedTo(QSize(160, 120)), Qt::KeepAspectRatio,
                     Qt::SmoothTransformation)));
  }
  caption_->setText(QString("Frame %1: a viewer moving sideways at %2 units/frame, slices "
                            "cut so every point of a slice moves within %3 px of the others "
                            "(eq. 9, asymptote k|V|/epsilon = %4).")
                        .arg(frame_)
                        .arg(speed_->value())
                        .arg(epsilon_->value())
                        .arg(asymptote, 0, 'f', 2));
}

QImage SlicesView::render_image() {
  refresh();
  return grab().toImage();
}

void SlicesView::resizeEvent(QResizeEvent* event) {
  ViewPage::resizeEvent(event);
  refresh();
}

double SlicesView::smallest_text_px() const { return QFontInfo(diagram_font(theme_)).pixelSize(); }

void SlicesView::set_theme(const ViewTheme& theme) {
  theme_ = theme;
  refresh();
}

}  // namespace oflab
