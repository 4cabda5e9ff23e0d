// The animation view's kept text measurements (adapters/text_cache.h): every answer is Qt's
// for the same font, width and text, whether it was computed now or kept from before, and a
// change of font, width or text is measured anew (controls).
#include "adapters/text_cache.h"

#include <gtest/gtest.h>

#include <QFontMetrics>

namespace oflab::test {
namespace {

QFont font_of(int pixels, bool bold) {
  QFont font;
  font.setPixelSize(pixels);
  font.setBold(bold);
  return font;
}

TEST(TextCache, ElidedTextsAreQtsFirstAndAfter) {
  TextCache cache;
  const QStringList texts = {QStringLiteral("depth-reprojection policy"),
                             QStringLiteral("coverage IoU 0.953 \u00b7 PSNR 31.2 dB"), QString()};
  int elided = 0;
  for (const QFont& font : {font_of(14, false), font_of(16, true)}) {
    for (const QString& text : texts) {
      for (int width : {40, 120, 1000}) {
        const QString qt = QFontMetrics(font).elidedText(text, Qt::ElideRight, width);
        EXPECT_EQ(cache.elided(font, text, width), qt);  // computed
        EXPECT_EQ(cache.elided(font, text, width), qt);  // kept
        elided += qt != text;
      }
    }
  }
  EXPECT_GT(elided, 0);  // control: some widths do elide
}

TEST(TextCache, AMeasurementIsKeptForItsFontWidthAndTextOnly) {
  TextCache cache;
  const QFont regular = font_of(14, false), bold = font_of(14, true);
  const QString text = QStringLiteral("cadence policy");
  int measured = 0;
  const auto measure = [&](const QFont& font) {
    return [&, font] {
      ++measured;
      return QFontMetrics(font).horizontalAdvance(text);
    };
  };
  const int width = cache.advance(regular, text, measure(regular));
  EXPECT_EQ(width, QFontMetrics(regular).horizontalAdvance(text));
  EXPECT_EQ(cache.advance(regular, text, measure(regular)), width);
  EXPECT_EQ(measured, 1);  // the second answer was kept
  // Controls: another font and another text are measured.
  EXPECT_EQ(cache.advance(bold, text, measure(bold)), QFontMetrics(bold).horizontalAdvance(text));
  EXPECT_EQ(measured, 2);
  EXPECT_NE(QFontMetrics(bold).horizontalAdvance(text), width);
  cache.advance(regular, text + QLatin1Char('s'), measure(regular));
  EXPECT_EQ(measured, 3);
  // Lines: kept per width, to the bit.
  int wrapped = 0;
  const auto wrap = [&] {
    ++wrapped;
    return QStringList{QStringLiteral("a"), QStringLiteral("b")};
  };
  EXPECT_EQ(cache.lines(regular, 120.0, text, wrap), QStringList({"a", "b"}));
  cache.lines(regular, 120.0, text, wrap);
  EXPECT_EQ(wrapped, 1);
  cache.lines(regular, 120.5, text, wrap);
  EXPECT_EQ(wrapped, 2);
}

TEST(TextCache, PastItsSizeItStillAnswersQts) {
  TextCache cache;
  const QFont font = font_of(13, false);
  for (int k = 0; k < TextCache::kMaxEntries + 10; ++k) {
    const QString text = QStringLiteral("frame %1").arg(k);
    ASSERT_EQ(cache.elided(font, text, 50), QFontMetrics(font).elidedText(text, Qt::ElideRight, 50))
        << k;
  }
}

}  // namespace
}  // namespace oflab::test
