#include "views/image_canvas.h"

#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>

#include "player/stage_times.h"

namespace oflab {

ImageCanvas::ImageCanvas(QWidget* parent) : QWidget(parent) {
  setMouseTracking(true);
  setAttribute(Qt::WA_OpaquePaintEvent);
  setMinimumSize(200, 120);
}

void ImageCanvas::set_image(const QImage& image) {
  take_pending();
  image_ = image;
  update();
}

void ImageCanvas::set_pending_image(std::shared_future<QImage> image) {
  take_pending();
  pending_ = std::move(image);
  update();
}

const QImage& ImageCanvas::image() const {
  take_pending();
  return image_;
}

void ImageCanvas::take_pending() const {
  if (!pending_.valid()) return;
  const StageTimer drawing(FrameStage::kDrawing);  // what the worker has left to paint
  image_ = pending_.get();
  pending_ = std::shared_future<QImage>();
}

void ImageCanvas::set_background(const QColor& colour) {
  background_ = colour;
  update();
}

QRectF ImageCanvas::target_rect() const {
  take_pending();
  if (image_.isNull()) return QRectF();
  const double scale =
      std::min(double(width()) / image_.width(), double(height()) / image_.height());
  const QSizeF size(image_.width() * scale, image_.height() * scale);
  return QRectF(QPointF((width() - size.width()) / 2, (height() - size.height()) / 2), size);
}

void ImageCanvas::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  const QRectF target = target_rect();
  // Only the margins around the image: filling the whole widget first costs a full-size
  // pass per frame in software.
  if (!target.contains(QRectF(rect()))) {
    painter.fillRect(QRectF(0, 0, width(), target.top()), background_);
    painter.fillRect(QRectF(0, target.bottom(), width(), height() - target.bottom()), background_);
    painter.fillRect(QRectF(0, target.top(), target.left(), target.height()), background_);
    painter.fillRect(
        QRectF(target.right(), target.top(), width() - target.right(), target.height()),
        background_);
  }
  if (image_.isNull()) return;
  // Smooth scaling costs a few milliseconds per frame on software rendering; the panels
  // are shown near their own size, so the fast filter looks the same.
  painter.drawImage(target, image_);
}

void ImageCanvas::mousePressEvent(QMouseEvent* event) {
  last_mouse_ = event->localPos();
  event->accept();
}

void ImageCanvas::mouseMoveEvent(QMouseEvent* event) {
  if (event->buttons() != Qt::NoButton) {
    const QPointF delta = event->localPos() - last_mouse_;
    last_mouse_ = event->localPos();
    emit dragged(delta, event->buttons(), event->modifiers());
  }
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
