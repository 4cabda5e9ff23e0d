// A widget that shows one image scaled to fit (aspect kept, centred) and reports the image
// pixel under the mouse, drags, wheel turns and resizes. The animation view paints its panels into
// one image and shows it here, so what the window shows is exactly what render_image returns.
#pragma once

#include <QImage>
#include <QPointF>
#include <QWidget>

namespace oflab {

class ImageCanvas : public QWidget {
  Q_OBJECT

 public:
  explicit ImageCanvas(QWidget* parent = nullptr);

  void set_image(const QImage& image);
  const QImage& image() const { return image_; }
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

  QImage image_;
  QColor background_{Qt::white};
  QPointF last_mouse_;  // where the drag under way was last reported, widget pixels
};

}  // namespace oflab
