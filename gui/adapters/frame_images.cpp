#include "adapters/frame_images.h"

#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "views/palette.h"

namespace oflab {
namespace {

QColor qcolor(const Rgb8& c) { return QColor(c.r, c.g, c.b); }

QColor level_qcolor(Level level) { return qcolor(level_colour(level)); }

// Premultiplied RGBA8 rows are exactly QImage's Format_RGBA8888_Premultiplied.
QImage wrap(const Image& image) {
  return QImage(reinterpret_cast<const uchar*>(image.row(0)), image.width(), image.height(),
                image.width() * 4, QImage::Format_RGBA8888_Premultiplied);
}

}  // namespace

Image image_from_qimage(const QImage& qimage) {
  const QImage rgba = qimage.convertToFormat(QImage::Format_RGBA8888_Premultiplied);
  Image image(rgba.width(), rgba.height());
  for (int y = 0; y < rgba.height(); ++y) {
    std::memcpy(image.row(y), rgba.constScanLine(y), size_t(rgba.width()) * 4);
  }
  return image;
}

QImage flatten_image(const Image& image, const QColor& background) {
  QImage out(std::max(1, image.width()), std::max(1, image.height()), QImage::Format_RGB32);
  out.fill(background);
  if (image.empty()) return out;
  QPainter painter(&out);
  painter.drawImage(0, 0, wrap(image));
  return out;
}

void draw_level_overlay(QImage& image, const std::vector<LayerOutline>& outlines,
                        const std::array<int, kLevelCount>& counts, const QColor& text,
                        double line_width, double text_scale) {
  QPainter painter(&image);
  painter.setRenderHint(QPainter::Antialiasing, true);
  for (const LayerOutline& outline : outlines) {
    QPolygonF polygon;
    for (const Vec2& p : outline.points) polygon << QPointF(p.x, p.y);
    painter.setPen(QPen(level_qcolor(outline.level), line_width));
    painter.setBrush(Qt::NoBrush);
    painter.drawPolygon(polygon);
  }
  QFont font = painter.font();
  font.setPixelSize(int(text_scale * std::max(12, image.height() / 32)));
  painter.setFont(font);
  const int row = font.pixelSize() + 6;
  const int x = 10;
  int y = 10;
  // A translucent box keeps the legend readable over any texture.
  const QColor box = text.lightness() > 128 ? QColor(0, 0, 0, 150) : QColor(255, 255, 255, 190);
  painter.fillRect(x - 4, y - 4, 12 * row, kLevelCount * row + 4, box);
  for (int k = 0; k < kLevelCount; ++k) {
    const Level level = static_cast<Level>(k);
    painter.fillRect(x, y, row - 4, row - 4, level_qcolor(level));
    painter.setPen(text);
    painter.drawText(x + row + 2, y + row - 8,
                     QStringLiteral("%1  %2").arg(level_name(level)).arg(counts[size_t(k)]));
    y += row;
  }
}

void draw_panel_title(QImage& image, const QString& title, const QColor& text,
                      double text_scale) {
  QPainter painter(&image);
  QFont font = painter.font();
  font.setPixelSize(int(text_scale * std::max(12, image.height() / 28)));
  font.setBold(true);
  painter.setFont(font);
  const QRect area(0, 8, image.width() - 10, font.pixelSize() + 8);
  // A backdrop of the opposite lightness keeps the title legible on any frame content.
  const QRect box = painter.boundingRect(area, Qt::AlignRight | Qt::AlignTop, title)
                        .adjusted(-6, -2, 6, 2);
  painter.fillRect(box, text.lightness() > 127 ? QColor(0, 0, 0, 170) : QColor(255, 255, 255, 190));
  painter.setPen(text);
  painter.drawText(area, Qt::AlignRight | Qt::AlignTop, title);
}

QImage difference_heat_map(const Image& a, const Image& b, int full_scale, const QColor& text) {
  const int bar = std::max(60, a.width() / 10);
  QImage out(a.width() + bar, a.height(), QImage::Format_RGB32);
  out.fill(QColor(0, 0, 0));
  for (int y = 0; y < a.height(); ++y) {
    const Pixel* pa = a.row(y);
    const Pixel* pb = b.row(y);
    auto* line = reinterpret_cast<QRgb*>(out.scanLine(y));
    for (int x = 0; x < a.width(); ++x) {
      const int d = std::max({std::abs(pa[x].r - pb[x].r), std::abs(pa[x].g - pb[x].g),
                              std::abs(pa[x].b - pb[x].b), std::abs(pa[x].a - pb[x].a)});
      const Rgb8 c = magnitude_colour(static_cast<double>(d) / full_scale);
      line[x] = qRgb(c.r, c.g, c.b);
    }
  }
  QPainter painter(&out);
  painter.fillRect(a.width(), 0, bar, a.height(), QColor(250, 250, 250));
  const int top = 30, bottom = a.height() - 30, left = a.width() + 10, width = bar / 3;
  for (int y = top; y <= bottom; ++y) {
    const Rgb8 c = magnitude_colour(1.0 - double(y - top) / std::max(1, bottom - top));
    painter.fillRect(left, y, width, 1, qcolor(c));
  }
  QFont font = painter.font();
  font.setPixelSize(std::max(10, a.height() / 40));
  painter.setFont(font);
  painter.setPen(text.lightness() > 128 ? QColor(30, 30, 30) : text);
  for (int i = 0; i <= 4; ++i) {
    const int y = bottom - (bottom - top) * i / 4;
    painter.drawText(left + width + 4, y + font.pixelSize() / 2,
                     QString::number(full_scale * i / 4) + (i == 4 ? QStringLiteral("+") : QString()));
  }
  painter.drawText(QRect(a.width(), 4, bar, top - 6), Qt::AlignCenter, QStringLiteral("|diff|"));
  return out;
}

FrameAgreement frame_agreement(const Image& a, const Image& b) {
  FrameAgreement result;
  long both = 0, either = 0;
  double squared = 0.0;
  for (int y = 0; y < a.height(); ++y) {
    const Pixel* pa = a.row(y);
    const Pixel* pb = b.row(y);
    for (int x = 0; x < a.width(); ++x) {
      const bool ca = pa[x].a > 127, cb = pb[x].a > 127;
      either += (ca || cb);
      if (!(ca && cb)) continue;
      ++both;
      for (int d : {pa[x].r - pb[x].r, pa[x].g - pb[x].g, pa[x].b - pb[x].b}) squared += d * d;
    }
  }
  result.mask_iou = either > 0 ? static_cast<double>(both) / either : 1.0;
  const double mse = both > 0 ? squared / (3.0 * both) : 0.0;
  result.psnr_db = mse > 0 ? 10.0 * std::log10(255.0 * 255.0 / mse)
                           : std::numeric_limits<double>::infinity();
  return result;
}

}  // namespace oflab
