#include "adapters/frame_images.h"

#include <QFontMetricsF>
#include <QObject>
#include <QPainterPath>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "display/palette.h"
#include "image/bilinear_blend.h"  // OFLAB_WARP_SSE2 with <emmintrin.h> on x86-64
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

// The colour of each difference 0..255 (whole grey levels) over [0, full_scale].
std::array<QRgb, 256> difference_colours(int full_scale) {
  std::array<QRgb, 256> colours;
  for (int d = 0; d < 256; ++d) {
    const Rgb8 c = magnitude_colour(static_cast<double>(d) / full_scale);
    colours[size_t(d)] = qRgb(c.r, c.g, c.b);
  }
  return colours;
}

// The largest of the four channels' absolute differences of each pixel of a row into
// `largest` (width entries); returns whether any is not 0 (the rows differ). SSE2 takes four
// pixels at a time: the bytes' differences both ways (saturated, so one of them is 0), then
// the largest byte of each pixel's 32 bits. The rest, and other targets, one pixel at a time.
bool largest_differences(const Pixel* row_a, const Pixel* row_b, int width,
                         std::vector<std::uint32_t>& largest) {
  const auto* pa = reinterpret_cast<const std::uint8_t*>(row_a);
  const auto* pb = reinterpret_cast<const std::uint8_t*>(row_b);
  std::uint32_t any = 0;
  int x = 0;
#if defined(OFLAB_WARP_SSE2)
  __m128i any4 = _mm_setzero_si128();
  const __m128i low_byte = _mm_set1_epi32(0xff);
  for (; x + 4 <= width; x += 4) {
    const __m128i a = _mm_loadu_si128(reinterpret_cast<const __m128i*>(pa + size_t(x) * 4));
    const __m128i b = _mm_loadu_si128(reinterpret_cast<const __m128i*>(pb + size_t(x) * 4));
    __m128i d = _mm_or_si128(_mm_subs_epu8(a, b), _mm_subs_epu8(b, a));
    d = _mm_max_epu8(d, _mm_srli_epi32(d, 8));
    d = _mm_and_si128(_mm_max_epu8(d, _mm_srli_epi32(d, 16)), low_byte);
    any4 = _mm_or_si128(any4, d);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(largest.data() + x), d);
  }
  any = std::uint32_t(_mm_movemask_epi8(_mm_cmpeq_epi8(any4, _mm_setzero_si128())) != 0xffff);
#endif
  for (; x < width; ++x) {
    std::uint32_t m = 0;
    for (int c = 0; c < 4; ++c) {
      const std::uint8_t u = pa[size_t(x) * 4 + size_t(c)], v = pb[size_t(x) * 4 + size_t(c)];
      m = std::max<std::uint32_t>(m, u > v ? u - v : v - u);
    }
    largest[size_t(x)] = m;
    any |= m;
  }
  return any != 0;
}

// One row of the difference map: each pixel's largest channel difference through the colour
// table (`largest` is scratch of width entries). Returns whether the rows differ.
bool difference_row(const Pixel* row_a, const Pixel* row_b, const std::array<QRgb, 256>& colours,
                    std::vector<std::uint32_t>& largest, QRgb* line, int width) {
  if (!largest_differences(row_a, row_b, width, largest)) {  // most rows miss the plane in both
    std::fill(line, line + width, colours[0]);
    return false;
  }
  for (int x = 0; x < width; ++x) line[x] = colours[largest[size_t(x)]];
  return true;
}

// The difference map's image: `out` reused when it is a's size (at least 1 x 1) and RGB32.
void prepare_difference_map(const Image& a, QImage& out) {
  const QSize size(std::max(1, a.width()), std::max(1, a.height()));
  if (out.size() != size || out.format() != QImage::Format_RGB32) {
    out = QImage(size, QImage::Format_RGB32);
  }
  if (a.empty()) out.fill(QColor(0, 0, 0));
}

// Bands of the maps: at least 8 rows and about 64 K pixels each.
int band_rows(const Image& a) { return std::max(8, 65536 / std::max(1, a.width())); }

// frame_agreement's whole-number tallies: pixels covered (alpha > 127) in both images, in
// either, and the sum of squared RGB differences over those covered in both.
struct AgreementTally {
  std::int64_t both = 0, either = 0, squared = 0;
  void add(const AgreementTally& t) {
    both += t.both;
    either += t.either;
    squared += t.squared;
  }
};

// The tallies of one row, added to `t`. Without branches and in 32-bit sums over pieces of
// kPiece pixels (kPiece * 3 * 255^2 < 2^31), so that the compiler vectorises the loop: a pixel
// not covered in both adds 0 to the squares.
void tally_row(const Pixel* pa, const Pixel* pb, int width, AgreementTally& t) {
  constexpr int kPiece = 8192;
  for (int begin = 0; begin < width; begin += kPiece) {
    const int end = std::min(width, begin + kPiece);
    std::int32_t both = 0, either = 0, squared = 0;
    for (int x = begin; x < end; ++x) {
      const int ca = pa[x].a > 127, cb = pb[x].a > 127;
      const int dr = pa[x].r - pb[x].r, dg = pa[x].g - pb[x].g, db = pa[x].b - pb[x].b;
      either += ca | cb;
      both += ca & cb;
      squared += (ca & cb) * (dr * dr + dg * dg + db * db);
    }
    t.both += both;
    t.either += either;
    t.squared += squared;
  }
}

// The tallies of a row that is the same in both images: its covered pixels are covered in
// both and in either, and no colour differs.
void tally_same_row(const Pixel* pa, int width, AgreementTally& t) {
  std::int32_t covered = 0;
  for (int x = 0; x < width; ++x) covered += pa[x].a > 127;
  t.both += covered;
  t.either += covered;
}

FrameAgreement agreement_of(const AgreementTally& total) {
  FrameAgreement result;
  result.mask_iou = total.either > 0 ? static_cast<double>(total.both) / total.either : 1.0;
  const double mse = total.both > 0 ? static_cast<double>(total.squared) / (3.0 * total.both) : 0.0;
  result.psnr_db =
      mse > 0 ? 10.0 * std::log10(255.0 * 255.0 / mse) : std::numeric_limits<double>::infinity();
  return result;
}

}  // namespace

void difference_map_into(const Image& a, const Image& b, int full_scale, QImage& out) {
  prepare_difference_map(a, out);
  const std::array<QRgb, 256> colours = difference_colours(full_scale);
  // One frame against itself (the comparison's exact panel showing a compared re-render's
  // frame): every difference is 0, so the map is its colour throughout.
  if (&a == &b) {
    out.fill(colours[0]);
    return;
  }
  // Bands of rows on core's worker threads (core/image/thread_pool.h), each with its own row of
  // differences. The image is detached here, once, so that the bands' scanLine() only reads
  // its sharing.
  out.bits();
  for_each_band(a.height(), band_rows(a), [&](int, int begin, int end) {
    std::vector<std::uint32_t> largest(size_t(a.width()));
    for (int y = begin; y < end; ++y) {
      difference_row(a.row(y), b.row(y), colours, largest, reinterpret_cast<QRgb*>(out.scanLine(y)),
                     a.width());
    }
  });
}

FrameAgreement difference_map_and_agreement(const Image& a, const Image& b, int full_scale,
                                            QImage& out) {
  if (&a == &b || a.empty()) {  // no pass to share
    difference_map_into(a, b, full_scale, out);
    return frame_agreement(a, b);
  }
  prepare_difference_map(a, out);
  const std::array<QRgb, 256> colours = difference_colours(full_scale);
  out.bits();  // detached once, as in difference_map_into
  // Each band's tallies kept in locals and stored once, summed in band order after.
  std::array<AgreementTally, kMaxBands> tallies{};
  for_each_band(a.height(), band_rows(a), [&](int band, int begin, int end) {
    std::vector<std::uint32_t> largest(size_t(a.width()));
    AgreementTally tally;
    for (int y = begin; y < end; ++y) {
      // A row the same in both (its differences all 0) needs only its coverage counted.
      if (difference_row(a.row(y), b.row(y), colours, largest,
                         reinterpret_cast<QRgb*>(out.scanLine(y)), a.width())) {
        tally_row(a.row(y), b.row(y), a.width(), tally);
      } else {
        tally_same_row(a.row(y), a.width(), tally);
      }
    }
    tallies[size_t(band)] = tally;
  });
  AgreementTally total;
  for (const AgreementTally& t : tallies) total.add(t);
  return agreement_of(total);
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
  // One frame against itself: its mask is its own (IoU 1, as for two empty ones) and no
  // colour differs (PSNR infinite), what the tallies below would find, without the pass.
  if (&a == &b) {
    FrameAgreement result;
    result.psnr_db = std::numeric_limits<double>::infinity();
    return result;
  }
  // Whole-number tallies per band of rows (core's worker threads), summed in band order.
  std::array<AgreementTally, kMaxBands> tallies{};
  for_each_band(a.height(), band_rows(a), [&](int band, int begin, int end) {
    AgreementTally tally;
    for (int y = begin; y < end; ++y) tally_row(a.row(y), b.row(y), a.width(), tally);
    tallies[size_t(band)] = tally;
  });
  AgreementTally total;
  for (const AgreementTally& t : tallies) total.add(t);
  return agreement_of(total);
}

}  // namespace oflab
