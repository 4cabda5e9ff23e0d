// Where the world view's texts go (gui/adapters/label_layout.h): labels crowded on one point
// still neither overlap nor leave their area nor cover the caption, and wrapped captions fit
// their width without losing a word.
#include "adapters/label_layout.h"

#include <gtest/gtest.h>

#include <QFont>
#include <QStringList>
#include <algorithm>

namespace oflab::test {
namespace {

double overlap_area(const QRectF& a, const QRectF& b) {
  const QRectF both = a.intersected(b);
  return both.width() * both.height();
}

TEST(LabelLayout, AFreeLabelSitsRightOfAndAboveItsPoint) {
  const std::vector<QRectF> boxes =
      place_labels({QSizeF(50, 20)}, {QPointF(100, 100)}, QRectF(0, 0, 400, 300), {}, 6.0);
  ASSERT_EQ(boxes.size(), 1u);
  EXPECT_EQ(boxes[0], QRectF(106, 74, 50, 20));
}

TEST(LabelLayout, CrowdedLabelsNeitherOverlapNorLeaveTheAreaNorCoverTheCaption) {
  const QRectF area(10, 10, 400, 300);
  const QRectF caption(10, 280, 390, 30);
  std::vector<QSizeF> sizes = {{40, 20}, {110, 20}, {20, 20}, {20, 20}, {90, 20}, {250, 20}};
  std::vector<QPointF> anchors(sizes.size(), QPointF(200, 150));  // all on one point
  anchors.back() = QPointF(405, 295);                             // in the caption's corner
  const std::vector<QRectF> boxes = place_labels(sizes, anchors, area, {caption});
  ASSERT_EQ(boxes.size(), sizes.size());
  for (size_t i = 0; i < boxes.size(); ++i) {
    EXPECT_TRUE(area.contains(boxes[i])) << i;
    EXPECT_EQ(boxes[i].size(), sizes[i]) << i;
    EXPECT_LE(overlap_area(boxes[i], caption), 0.0) << i;
    for (size_t j = i + 1; j < boxes.size(); ++j) {
      EXPECT_LE(overlap_area(boxes[i], boxes[j]), 0.0) << i << " and " << j;
    }
  }
}

TEST(LabelLayout, WrappedLinesFitTheWidthAndKeepEveryWord) {
  QFont font;
  font.setPixelSize(20);
  const QFontMetricsF metrics(font);
  const QString text = QStringLiteral(
      "Omega turns about the eye, the viewer's origin (the theory's convention); V is the "
      "velocity of the body point at the eye.\nPath of the plane's centre: past thick.");
  const std::vector<QString> lines = wrap_text(text, metrics, 300.0);
  EXPECT_GT(lines.size(), 3u);
  QStringList words;
  for (const QString& line : lines) {
    EXPECT_LE(metrics.horizontalAdvance(line), 300.0) << line.toStdString();
    words += line.split(QLatin1Char(' '), Qt::SkipEmptyParts);
  }
  EXPECT_EQ(words, text.split(QRegExp(QStringLiteral("[ \n]")), Qt::SkipEmptyParts));
  // A new paragraph starts a new line.
  const auto path = std::find_if(lines.begin(), lines.end(), [](const QString& line) {
    return line.startsWith(QStringLiteral("Path of"));
  });
  EXPECT_NE(path, lines.end());
}

}  // namespace
}  // namespace oflab::test
