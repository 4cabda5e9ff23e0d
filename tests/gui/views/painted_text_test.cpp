// The text recorder sees what a painter writes, where, after the painter's transform; its
// checks find an elided text, a text off the canvas and two overlapping texts, and pass
// lines that only touch.
#include "adapters/painted_text.h"

#include <gtest/gtest.h>

#include <QFont>
#include <QFontMetrics>
#include <QPainter>

namespace oflab::test {
namespace {

const QSize kCanvas(400, 200);

QFont font_px(int px) {
  QFont font;
  font.setPixelSize(px);
  return font;
}

TEST(PaintedText, RecordsEachTextWithItsBoxAfterTheTransform) {
  const std::vector<PaintedText> texts = record_painted_text(kCanvas, [](QPainter& p) {
    p.setFont(font_px(20));
    p.fillRect(QRectF(0, 0, 400, 200), Qt::white);  // not text: not recorded
    p.drawText(QPointF(10, 40), QStringLiteral("first"));
    p.translate(100, 50);
    p.drawText(QPointF(10, 40), QStringLiteral("second"));
  });
  ASSERT_EQ(texts.size(), 2u);
  EXPECT_EQ(texts[0].text, QStringLiteral("first"));
  const QFontMetricsF metrics(font_px(20));
  EXPECT_NEAR(texts[0].box.left(), 10, 0.5);
  EXPECT_NEAR(texts[0].box.bottom(), 40 + metrics.descent(), 0.5);
  EXPECT_NEAR(texts[0].box.width(), metrics.horizontalAdvance(QStringLiteral("first")), 0.5);
  EXPECT_NEAR(texts[1].box.left(), 110, 0.5);
  EXPECT_NEAR(texts[1].box.bottom(), 90 + metrics.descent(), 0.5);
}

TEST(PaintedText, LegibleLinesHaveNoProblems) {
  const auto texts = record_painted_text(kCanvas, [](QPainter& p) {
    p.setFont(font_px(16));
    const double line = QFontMetricsF(p.font()).height();
    for (int i = 0; i < 4; ++i) {  // lines that touch, one under another
      p.drawText(QRectF(0, i * line, 400, line), Qt::AlignCenter, QStringLiteral("a line"));
    }
  });
  EXPECT_TRUE(text_problems(texts, kCanvas).empty());
}

TEST(PaintedText, FindsElidedOffCanvasAndOverlappingTexts) {
  const auto texts = record_painted_text(kCanvas, [](QPainter& p) {
    p.setFont(font_px(16));
    const QString longer = QStringLiteral("exact projection (core warp)");
    p.drawText(QPointF(0, 20), QFontMetrics(p.font()).elidedText(longer, Qt::ElideRight, 80));
    p.drawText(QPointF(360, 60), QStringLiteral("past the edge"));
    p.drawText(QPointF(0, 120), QStringLiteral("96"));
    p.drawText(QPointF(8, 124), QStringLiteral("128+"));
  });
  const std::vector<QString> problems = text_problems(texts, kCanvas);
  ASSERT_EQ(problems.size(), 3u);
  EXPECT_TRUE(problems[0].startsWith(QStringLiteral("elided")));
  EXPECT_TRUE(problems[1].contains(QStringLiteral("leaves the canvas")));
  EXPECT_TRUE(problems[2].contains(QStringLiteral("overlaps")));
}

}  // namespace
}  // namespace oflab::test
