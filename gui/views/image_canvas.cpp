#include "views/image_canvas.h"

#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>

namespace oflab {

ImageCanvas::ImageCanvas(QWidget* parent) : QWidget(parent) {
  setMouseTracking(true);
  setAttribute(Qt::WA_OpaquePaintEvent);
  setMinimumSize(200, 120);
}

void ImageCanvas::set_image(const QImage& image) {
  image_ = image;
  update();
}

void ImageCanvas::set_background(const QColor& colour) {
  background_ = colour;
  update();
}

QRectF ImageCanvas::target_rect() const {
  if (image_.isNull()) return QRectF();
  const double scale =
      std::min(double(width()) / image_.width(), double(height()) / image_.height());
  const QSizeF size(image_.width() * scale, image_.height() * scale);
  return QRectF(QPointF((width() - size.width()) / 2, (height() - size.height()) / 2), size);
}

void ImageCanvas::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.fillRect(rect(), background_);
  if (image_.isNull()) return;
  // Smooth scaling costs a few milliseconds per frame on software rendering; the panels
  // are shown near their own size, so the fast filter looks the same.
  painter.drawImage(target_rect(), image_);
}

void ImageCanvas::mouseMoveEvent(QMouseEvent* event) {
  const QRectF r = target_rect();
  if (r.isEmpty() || !r.contains(event->pos())) return;
  const double scale = image_.width() / r.width();
  emit hovered(
      QPointF((event->pos().x() - r.left()) * scale, (event->pos().y() - r.top()) * scale));
}

void ImageCanvas::wheelEvent(QWheelEvent* event) {
  emit wheel_turned(event->angleDelta().y() / 120.0);
  event->accept();
}

void ImageCanvas::resizeEvent(QResizeEvent* event) {
  QWidget::resizeEvent(event);
  emit resized();
}

}  // namespace oflab
