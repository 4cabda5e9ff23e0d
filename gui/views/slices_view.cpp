#include "views/slices_view.h"

#include <QFontMetricsF>
#include <QHBoxLayout>
#include <QPainter>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <functional>

#include "adapters/frame_images.h"
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

const QColor kBandA(90, 170, 120, 60), kBandB(90, 120, 170, 60);
const QColor kAsymptote(213, 94, 0);  // Okabe-Ito vermillion
const QColor kPlane(230, 159, 0);     // Okabe-Ito orange

// The depth axis under the diagram: a tick and label at each depth_ticks value, the eye's
// 0 at the left, and the axis title at the right.
void draw_depth_axis(QPainter& p, const std::function<double(double)>& x_of, double left,
                     double right, double bottom, const std::vector<double>& ticks,
                     const QColor& text) {
  const QFontMetricsF fm(p.font());
  p.setPen(QPen(text, 1));
  p.drawLine(QPointF(left, bottom), QPointF(right, bottom));
  double last_right = -1e9;
  for (double z : ticks) {
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

// The scene's planes, seen from above: a thick line at each plane's depth across its
// lateral extent (clamped to the diagram's).
void draw_diagram_planes(QPainter& p, const std::vector<DiagramPlane>& planes,
                         const std::function<double(double)>& x_of,
                         const std::function<double(double)>& y_of) {
  p.setPen(QPen(kPlane, 4));
  const double half = kDiagramHalfWidth;
  for (const DiagramPlane& pl : planes) {
    if (pl.depth <= 0) continue;
    p.drawLine(QPointF(x_of(pl.depth), y_of(std::clamp(pl.left, -half, half))),
               QPointF(x_of(pl.depth), y_of(std::clamp(pl.right, -half, half))));
  }
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

QImage paint_slice_diagram(int width, int height, const SliceDiagram& diagram,
                           const ViewTheme& theme) {
  const std::vector<Slice>& slices = diagram.slices;
  const double asymptote = diagram.asymptote, max_depth = diagram.max_depth;
  QImage image(width, height, QImage::Format_RGB32);
  image.fill(qcolor(theme.background));
  QPainter p(&image);
  p.setRenderHint(QPainter::Antialiasing);
  p.setFont(diagram_font(theme));
  const double line = QFontMetricsF(p.font()).height();
  const double left = 40, right = width - 20, bottom = height - 2.4 * line - 10;
  p.setPen(qcolor(theme.text));
  p.drawText(QPointF(left, line), QString::fromStdString(slice_diagram_title(diagram)));
  // Under the legend, a row of its own for the asymptote's label, so it never meets the
  // legend, the plane marks or the bands' edges.
  const double label_row =
      draw_diagram_legend(p, QRectF(left, 1.3 * line, right - left, line), theme);
  const double top = label_row + 1.2 * line + 4;
  std::function<double(double)> x_of = [&](double z) {
    return left + (right - left) * diagram_depth_position(z, max_depth);
  };
  std::function<double(double)> y_of = [&](double x) {
    return top + (bottom - top) * (0.5 - x / (2.0 * kDiagramHalfWidth));
  };
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
    const QString label = QString::fromStdString(asymptote_label(diagram));
    const double w = QFontMetricsF(p.font()).horizontalAdvance(label);
    // Centred over its line, kept inside the diagram.
    const double x = std::clamp(x_of(asymptote) - w / 2, left, std::max(left, right - w));
    p.drawText(QRectF(x, label_row, w + 1, line), Qt::AlignLeft | Qt::AlignVCenter, label);
  }
  draw_diagram_planes(p, diagram.planes, x_of, y_of);
  // The eye.
  p.setPen(Qt::NoPen);
  p.setBrush(text);
  p.drawEllipse(QPointF(left, y_of(0.0)), 5, 5);
  p.setPen(text);
  p.drawText(QPointF(left - 30, y_of(0.0) - 8), "eye");
  draw_depth_axis(p, x_of, left, right, bottom, diagram.ticks, text);
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
  epsilon_->set_value(1.0);
  speed_->set_value(0.05);
  connect(epsilon_, &SliderSpin::edited, this, [this](double) { restart(); });
  connect(speed_, &SliderSpin::edited, this, [this](double) { restart(); });
  connect(window_->scene(), &SceneModel::scene_changed, this, &SlicesView::follow_frame);
  restart();
}

SlicesView::~SlicesView() = default;

double SlicesView::epsilon_px() const { return epsilon_->value(); }
double SlicesView::speed() const { return speed_->value(); }

void SlicesView::restart() {
  walk_.set_slicing(epsilon_->value(), speed_->value());
  diagram_current_ = false;
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
  const int before = walk_.frame();
  walk_.go_to(window_->scene()->frame());
  if (walk_.frame() != before) refresh();
}

void SlicesView::refresh() {
  if (!walk_.problem().empty()) {
    caption_->setText(QString::fromStdString(walk_.caption(window_->scene()->frame())));
    return;
  }
  // The diagram changes with the slices (a restart), the theme and the size, not per frame.
  const QSize area = diagram_->size().expandedTo(QSize(160, 120));
  if (!diagram_current_ || area != diagram_size_) {
    diagram_->setPixmap(QPixmap::fromImage(
        paint_slice_diagram(area.width(), area.height(), walk_.diagram(), theme_)));
    diagram_current_ = true;
    diagram_size_ = area;
  }
  if (walk_.slicing_problem().empty()) {
    frame_label_->setPixmap(titled_picture(walk_.shifted_image(), tr("scene shifting (slices)"),
                                           frame_label_->size().expandedTo(QSize(160, 120)),
                                           theme_));
  }
  const std::string& exact_problem = walk_.exact_problem();
  exact_label_->setPixmap(titled_picture(
      walk_.exact_image(),
      QString::fromStdString(exact_problem.empty() ? SliceWalk::kExactTitle : exact_problem),
      exact_label_->size().expandedTo(QSize(160, 120)), theme_));
  caption_->setText(QString::fromStdString(walk_.caption(window_->scene()->frame())));
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
