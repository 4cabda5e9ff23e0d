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

// covered_area against areas worked out by hand (a right triangle's legs of 10 px: a box
// inside it, a box holding it, a box cut by its hypotenuse) and against a pixel count.
TEST(LabelLayout, CoveredAreaIsTheBoxInsideTheOutline) {
  const QPolygonF triangle({QPointF(0, 0), QPointF(10, 0), QPointF(0, 10)});
  EXPECT_NEAR(covered_area(QRectF(0, 0, 4, 4), triangle), 16.0, 1e-9);
  EXPECT_NEAR(covered_area(QRectF(-5, -5, 30, 30), triangle), 50.0, 1e-9);
  EXPECT_NEAR(covered_area(QRectF(0, 0, 10, 10), triangle), 50.0, 1e-9);
  // The box [5, 10] x [0, 10]: the triangle's part is x from 5 to 10 under y = 10 - x.
  EXPECT_NEAR(covered_area(QRectF(5, 0, 5, 10), triangle), 12.5, 1e-9);
  EXPECT_EQ(covered_area(QRectF(20, 20, 5, 5), triangle), 0.0);
  // A tilted quad, counted at pixel centres on a fine grid.
  const QPolygonF quad({QPointF(3, 1), QPointF(17, 4), QPointF(14, 15), QPointF(1, 11)});
  const QRectF box(5, 2, 9, 7);
  double count = 0.0;
  const double step = 0.05;
  for (double x = box.left() + step / 2; x < box.right(); x += step)
    for (double y = box.top() + step / 2; y < box.bottom(); y += step)
      count += quad.containsPoint(QPointF(x, y), Qt::OddEvenFill) ? step * step : 0.0;
  EXPECT_NEAR(covered_area(box, quad), count, 0.2);
}

// A label whose wanted place covers a picture takes the nearest place clear of it; one whose
// every place covers it takes the place covering the least, still clear of the other texts.
TEST(LabelLayout, LabelsLeaveThePicturesClear) {
  const QRectF area(0, 0, 400, 300);
  const QPolygonF picture({QPointF(100, 40), QPointF(200, 40), QPointF(200, 95), QPointF(100, 95)});
  const std::vector<QRectF> boxes =
      place_labels({QSizeF(50, 20)}, {QPointF(100, 100)}, area, {}, 6.0, {picture});
  ASSERT_EQ(boxes.size(), 1u);
  EXPECT_EQ(covered_area(boxes[0], picture), 0.0);
  EXPECT_EQ(boxes[0], QRectF(106, 106, 50, 20));  // right, below
  const QPolygonF everywhere({QPointF(0, 0), QPointF(400, 0), QPointF(400, 300), QPointF(0, 300)});
  const QRectF caption(106, 74, 50, 20);
  const std::vector<QRectF> forced =
      place_labels({QSizeF(50, 20)}, {QPointF(100, 100)}, area, {caption}, 6.0, {everywhere});
  ASSERT_EQ(forced.size(), 1u);
  EXPECT_GT(covered_area(forced[0], everywhere), 0.0);
  EXPECT_LE(overlap_area(forced[0], caption), 0.0);
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
