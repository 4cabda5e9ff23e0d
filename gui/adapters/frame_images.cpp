#include "adapters/frame_images.h"

#include <QFontMetricsF>
#include <QObject>
#include <QPainterPath>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "display/palette.h"
#include "image/thread_pool.h"

namespace oflab {
namespace {

QColor qcolor(const Rgb8& c) { return QColor(c.r, c.g, c.b); }

QColor level_qcolor(Level level) { return qcolor(level_colour(level)); }

}  // namespace

// Premultiplied RGBA8 rows are exactly QImage's Format_RGBA8888_Premultiplied.
QImage image_view(const Image& image) {
  if (image.empty()) return QImage();
  return QImage(reinterpret_cast<const uchar*>(image.row(0)), image.width(), image.height(),
                image.width() * 4, QImage::Format_RGBA8888_Premultiplied);
}

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
  painter.drawImage(0, 0, image_view(image));
  return out;
}

void draw_level_outlines(QPainter& painter, const std::vector<LayerOutline>& outlines,
                         const QTransform& to_view, double line_width) {
  painter.save();
  painter.setRenderHint(QPainter::Antialiasing, true);
  painter.setBrush(Qt::NoBrush);
  for (const LayerOutline& outline : outlines) {
    QPolygonF polygon;
    for (const Vec2& p : outline.points) polygon << to_view.map(QPointF(p.x, p.y));
    painter.setPen(QPen(level_qcolor(outline.level), line_width));
    painter.drawPolygon(polygon);
  }
  painter.restore();
}

void draw_level_legend(QPainter& painter, const QRectF& area, const QColor& text, int text_px) {
  painter.save();
  QFont font = painter.font();
  font.setPixelSize(text_px);
  painter.setFont(font);
  const QFontMetricsF metrics(font);
  const double swatch = text_px, row = text_px * 1.6;
  // One row when it fits, else as many rows as needed, centred vertically in the area.
  double width = 0.0;
  for (int k = 0; k < kLevelCount; ++k) {
    width += swatch * 2.4 + metrics.horizontalAdvance(QString::fromLatin1(level_name(Level(k))));
  }
  const int rows = std::max(1, int(std::ceil(width / std::max(1.0, area.width()))));
  double x = area.left(), y = area.center().y() - rows * row / 2;
  for (int k = 0; k < kLevelCount; ++k) {
    const Level level = static_cast<Level>(k);
    const QString name = QString::fromLatin1(level_name(level));
    const double item = swatch * 2.4 + metrics.horizontalAdvance(name);
    if (x > area.left() && x + item > area.right()) {
      x = area.left();
      y += row;
    }
    painter.fillRect(QRectF(x, y + (row - swatch) / 2, swatch, swatch), level_qcolor(level));
    painter.setPen(text);
    painter.drawText(QRectF(x + swatch * 1.4, y, item, row), Qt::AlignLeft | Qt::AlignVCenter,
                     name);
    x += item;
  }
  painter.restore();
}

QImage difference_map(const Image& a, const Image& b, int full_scale) {
  QImage out;
  difference_map_into(a, b, full_scale, out);
  return out;
}

namespace {

// One row of the difference map: the largest channel difference of each pixel through the
// colour table (`channels` is scratch of 4 x width bytes).
void difference_row(const Pixel* row_a, const Pixel* row_b, const std::array<QRgb, 256>& colours,
                    std::vector<std::uint8_t>& channels, QRgb* line, int width) {
  const auto* pa = reinterpret_cast<const std::uint8_t*>(row_a);
  const auto* pb = reinterpret_cast<const std::uint8_t*>(row_b);
  if (std::memcmp(pa, pb, channels.size()) == 0) {  // most rows miss the plane in both
    std::fill(line, line + width, colours[0]);
    return;
  }
  for (size_t i = 0; i < channels.size(); ++i) {
    channels[i] = std::uint8_t(pa[i] > pb[i] ? pa[i] - pb[i] : pb[i] - pa[i]);
  }
  for (int x = 0; x < width; ++x) {
    const std::uint8_t* c = &channels[size_t(x) * 4];
    line[x] = colours[std::max(std::max(c[0], c[1]), std::max(c[2], c[3]))];
  }
}

}  // namespace

void difference_map_into(const Image& a, const Image& b, int full_scale, QImage& out) {
  const QSize size(std::max(1, a.width()), std::max(1, a.height()));
  if (out.size() != size || out.format() != QImage::Format_RGB32) {
    out = QImage(size, QImage::Format_RGB32);
  }
  if (a.empty()) out.fill(QColor(0, 0, 0));
  // Differences are whole grey levels 0..255: colour each once.
  std::array<QRgb, 256> colours;
  for (int d = 0; d < 256; ++d) {
    const Rgb8 c = magnitude_colour(static_cast<double>(d) / full_scale);
    colours[size_t(d)] = qRgb(c.r, c.g, c.b);
  }
  // One frame against itself (the comparison's exact panel showing a compared re-render's
  // frame): every difference is 0, so the map is its colour throughout.
  if (&a == &b) {
    out.fill(colours[0]);
    return;
  }
  // The channel differences of a row first, in a loop over bytes the compiler vectorises,
  // then the largest of each pixel's four through the colour table; bands of rows on core's
  // worker threads (core/image/thread_pool.h), each with its own row of differences. The
  // image is detached here, once, so that the bands' scanLine() only reads its sharing.
  out.bits();
  for_each_band(a.height(), std::max(8, 65536 / std::max(1, a.width())),
                [&](int, int begin, int end) {
                  std::vector<std::uint8_t> channels(size_t(a.width()) * 4);
                  for (int y = begin; y < end; ++y) {
                    difference_row(a.row(y), b.row(y), colours, channels,
                                   reinterpret_cast<QRgb*>(out.scanLine(y)), a.width());
                  }
                });
}

namespace {

// The colour bar's caption, on one line when it fits `width`, else broken after its comma.
QStringList difference_bar_caption(const QFontMetricsF& metrics, double width) {
  const QString caption = QObject::tr("|shown - exact|, grey levels");
  if (metrics.horizontalAdvance(caption) <= width) return {caption};
  return caption.split(QStringLiteral(", "));
}

}  // namespace

namespace {

// The step between the colour bar's caption lines: their boxes (ascent + descent) never touch,
// also in fonts whose leading is negative.
double caption_line_step(const QFontMetricsF& metrics) {
  return std::max(metrics.lineSpacing(), metrics.height()) + 2.0;
}

}  // namespace

double difference_bar_height(double width, int text_px) {
  QFont font;
  font.setPixelSize(text_px);
  const QFontMetricsF metrics(font);
  return text_px * 2.4 + caption_line_step(metrics) * difference_bar_caption(metrics, width).size();
}

void draw_difference_bar(QPainter& painter, const QRectF& area, int full_scale, const QColor& text,
                         int text_px) {
  painter.save();
  QFont font = painter.font();
  font.setPixelSize(text_px);
  painter.setFont(font);
  painter.setPen(text);
  const QFontMetricsF metrics(font);
  // Caption rows, the ramp row, the tick-label row.
  const QStringList caption = difference_bar_caption(metrics, area.width());
  // Caption lines a line spacing apart (so two never touch), the ramp and labels below.
  const double line = caption_line_step(metrics);
  const double row = std::max(0.0, area.height() - caption.size() * line) / 2;
  for (int i = 0; i < caption.size(); ++i) {
    painter.drawText(QRectF(area.left(), area.top() + i * line, area.width(), line),
                     Qt::AlignLeft | Qt::AlignVCenter, caption[i]);
  }
  const double left = area.left() + text_px, width = area.width() - 3 * text_px;
  const QRectF ramp(left, area.top() + caption.size() * line, width, row * 0.8);
  for (int x = 0; x < int(width); ++x) {
    painter.fillRect(QRectF(left + x, ramp.top(), 1.5, ramp.height()),
                     qcolor(magnitude_colour(double(x) / std::max(1.0, width - 1))));
  }
  // Every tick labelled when the labels stay a text size apart, else every other one.
  const QString widest = QString::number(full_scale) + QStringLiteral("+");
  const int label_every = width / 4 >= metrics.horizontalAdvance(widest) + text_px ? 1 : 2;
  for (int i = 0; i <= 4; ++i) {
    const double x = left + width * i / 4;
    painter.drawLine(QPointF(x, ramp.bottom()), QPointF(x, ramp.bottom() + row * 0.2));
    if (i % label_every != 0) continue;
    const QString label =
        QString::number(full_scale * i / 4) + (i == 4 ? QStringLiteral("+") : QString());
    painter.drawText(QRectF(x - 3 * text_px, ramp.bottom(), 6 * text_px, row * 1.2),
                     Qt::AlignCenter, label);
  }
  painter.restore();
}

FrameAgreement frame_agreement(const Image& a, const Image& b) {
  FrameAgreement result;
  // One frame against itself: its mask is its own (IoU 1, as for two empty ones) and no
  // colour differs (PSNR infinite), what the tallies below would find, without the pass.
  if (&a == &b) {
    result.psnr_db = std::numeric_limits<double>::infinity();
    return result;
  }
  // Whole-number tallies per band of rows (core's worker threads), summed in band order.
  struct Tally {
    std::int64_t both = 0, either = 0, squared = 0;
  };
  std::array<Tally, kMaxBands> tallies{};
  for_each_band(
      a.height(), std::max(8, 65536 / std::max(1, a.width())), [&](int band, int begin, int end) {
        Tally& t = tallies[size_t(band)];
        for (int y = begin; y < end; ++y) {
          const Pixel* pa = a.row(y);
          const Pixel* pb = b.row(y);
          // Without branches, so that the compiler vectorises the row: a pixel
          // not covered in both adds 0 to the squares.
          std::int64_t both = 0, either = 0, squared = 0;
          for (int x = 0; x < a.width(); ++x) {
            const int ca = pa[x].a > 127, cb = pb[x].a > 127;
            const int dr = pa[x].r - pb[x].r, dg = pa[x].g - pb[x].g, db = pa[x].b - pb[x].b;
            either += ca | cb;
            both += ca & cb;
            squared += std::int64_t(ca & cb) * (dr * dr + dg * dg + db * db);
          }
          t.both += both;
          t.either += either;
          t.squared += squared;
        }
      });
  Tally total;
  for (const Tally& t : tallies) {
    total.both += t.both;
    total.either += t.either;
    total.squared += t.squared;
  }
  result.mask_iou = total.either > 0 ? static_cast<double>(total.both) / total.either : 1.0;
  const double mse = total.both > 0 ? static_cast<double>(total.squared) / (3.0 * total.both) : 0.0;
  result.psnr_db =
      mse > 0 ? 10.0 * std::log10(255.0 * 255.0 / mse) : std::numeric_limits<double>::infinity();
  return result;
}

}  // namespace oflab
