#include "adapters/texture.h"

#include <QImageReader>
#include <QPainter>
#include <QPainterPath>

#include "display/palette.h"
#include "formats/datasets.h"
#include "formats/image_io.h"

namespace oflab {
namespace {

QColor qcolor(const Rgb8& c) { return QColor(c.r, c.g, c.b); }

void draw_checkerboard(QPainter* painter, int width, int height, int cell) {
  for (int j = 0; j * cell < height; ++j) {
    for (int i = 0; i * cell < width; ++i) {
      painter->fillRect(i * cell, j * cell, cell, cell,
                        (i + j) % 2 ? QColor(232, 228, 214) : QColor(250, 248, 240));
    }
  }
}

// One wing pair, mirrored about the body axis x = cx.
void draw_wing_pair(QPainter* painter, double cx, const QRectF& right_wing, const QColor& fill,
                    const QColor& spot) {
  const QRectF left_wing(2 * cx - right_wing.right(), right_wing.top(), right_wing.width(),
                         right_wing.height());
  for (const QRectF& wing : {right_wing, left_wing}) {
    painter->setBrush(fill);
    painter->drawEllipse(wing);
    painter->setBrush(spot);
    const double r = 0.18 * wing.height();
    painter->drawEllipse(wing.center(), r, r);
  }
}

void draw_butterfly(QPainter* painter, int width, int height) {
  const double cx = 0.5 * width, top = 0.18 * height;
  painter->setRenderHint(QPainter::Antialiasing);
  painter->setPen(QPen(QColor(40, 30, 20), 3));
  // Antennae, pointing to the top of the texture.
  painter->drawLine(QPointF(cx, top + 30), QPointF(cx - 26, top - 18));
  painter->drawLine(QPointF(cx, top + 30), QPointF(cx + 26, top - 18));
  // Fore-wings (upper, larger) and hind-wings (lower, smaller).
  draw_wing_pair(painter, cx, QRectF(cx + 4, top, 0.34 * width, 0.40 * height),
                 qcolor(okabe_ito::kOrange), qcolor(okabe_ito::kBlue));
  draw_wing_pair(painter, cx, QRectF(cx + 4, top + 0.40 * height, 0.22 * width, 0.30 * height),
                 qcolor(okabe_ito::kVermillion), qcolor(okabe_ito::kYellow));
  painter->setBrush(QColor(40, 30, 20));
  painter->drawEllipse(QPointF(cx, 0.53 * height), 9, 0.36 * height);
}

}  // namespace

QImage procedural_texture() {
  constexpr int kWidth = 320, kHeight = 256;
  QImage image(kWidth, kHeight, QImage::Format_RGBA8888);
  QPainter painter(&image);
  draw_checkerboard(&painter, kWidth, kHeight, 32);
  draw_butterfly(&painter, kWidth, kHeight);
  painter.setPen(QPen(QColor(60, 60, 60), 4));
  painter.setBrush(Qt::NoBrush);
  painter.drawRect(QRectF(2, 2, kWidth - 4, kHeight - 4));
  painter.end();
  return image;
}

QImage default_texture() {
  const QImage butterfly =
      load_texture_image(QString::fromStdString(default_texture_path()), nullptr);
  return butterfly.isNull() ? procedural_texture() : butterfly;
}

QImage load_texture_image(const QString& path, QString* error) {
  try {
    (void)check_image_file(path.toStdString());  // signature and size before any decoding
  } catch (const ImageFileError& e) {
    if (error) *error = QString::fromStdString(e.what());
    return {};
  }
  QImageReader reader(path);
  QImage image = reader.read();
  if (image.isNull()) {
    if (error) *error = QStringLiteral("cannot read %1: %2").arg(path, reader.errorString());
    return {};
  }
  return image.convertToFormat(QImage::Format_RGBA8888);
}

}  // namespace oflab
