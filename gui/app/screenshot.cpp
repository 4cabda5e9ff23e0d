#include "app/screenshot.h"

#include <QImageWriter>
#include <QWidget>

namespace oflab {

QImage grab_with_vtk(QWidget* root) {
  return root->grab().toImage().convertToFormat(QImage::Format_RGB32);
}

bool save_png(const QImage& image, const QString& path, QString* error) {
  QImageWriter writer(path, "png");
  if (image.isNull() || !writer.write(image)) {
    if (error) *error = QStringLiteral("cannot write %1: %2").arg(path, writer.errorString());
    return false;
  }
  return true;
}

bool has_content(const QImage& image) {
  if (image.isNull()) return false;
  const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
  const QRgb first = rgb.pixel(0, 0);
  for (int y = 0; y < rgb.height(); ++y) {
    const auto* line = reinterpret_cast<const QRgb*>(rgb.constScanLine(y));
    for (int x = 0; x < rgb.width(); ++x) {
      if (line[x] != first) return true;
    }
  }
  return false;
}

}  // namespace oflab
