// A widget that shows one image scaled to fit (aspect kept, centred) and reports the image
// pixel under the mouse, drags, wheel turns and resizes. The animation view paints its panels into
// one image and shows it here, so what the window shows is exactly what render_image returns.
#pragma once

#include <QImage>
#include <QPointF>
#include <QWidget>
#include <future>

namespace oflab {

class ImageCanvas : public QWidget {
  Q_OBJECT

 public:
  explicit ImageCanvas(QWidget* parent = nullptr);

  // Shows `image` (after any pending image is taken).
  void set_image(const QImage& image);
  // Shows the image a worker thread is painting: it is waited for and taken when the canvas
  // paints, or when image() or a mouse event needs it, so the picture on screen is always
  // the last one set. The worker must not depend on this canvas or the GUI thread.
  void set_pending_image(std::shared_future<QImage> image);
  const QImage& image() const;
  void set_background(const QColor& colour);

 signals:
  // The mouse is over image pixel `pixel` (continuous, top-left origin of the image).
  void hovered(QPointF pixel);
  // The mouse moved by `delta` widget pixels (x right, y down) with `buttons` held down
  // and `modifiers` pressed (a drag: some button is down).
  void dragged(QPointF delta, Qt::MouseButtons buttons, Qt::KeyboardModifiers modifiers);
  // The mouse wheel turned by `notches` (positive: away from the user) over the widget.
  void wheel_turned(double notches);
  // The widget changed size (a view painting at the canvas's size paints again).
  void resized();

 protected:
  void paintEvent(QPaintEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;

 private:
  QRectF target_rect() const;
  void take_pending() const;  // the pending image, waited for, becomes image_

  mutable QImage image_;
  mutable std::shared_future<QImage> pending_;
  QColor background_{Qt::white};
  QPointF last_mouse_;  // where the drag under way was last reported, widget pixels
};

}  // namespace oflab
