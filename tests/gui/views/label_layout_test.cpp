// Where the world view's texts go (gui/adapters/label_layout.h): the teaching layer's label
// rule in Qt's types, and wrapped captions that fit their width without losing a word.
#include "adapters/label_layout.h"

#include <gtest/gtest.h>

#include <QFont>
#include <QStringList>
#include <algorithm>

#include "display/label_layout.h"

namespace oflab::test {
namespace {

// The rule itself is the teaching layer's (tests/session/display/label_layout_test.cpp); Qt's
// types carry it here unchanged: the crowded case, placed through both, gives the same boxes.
TEST(LabelLayout, QtsTypesPlaceAsTheTeachingLayer) {
  const std::vector<QSizeF> sizes = {{40, 20}, {110, 20}, {20, 20}, {90, 20}};
  const std::vector<QPointF> anchors(sizes.size(), QPointF(200, 150));
  const QPolygonF picture(
      {QPointF(150, 40), QPointF(260, 40), QPointF(260, 140), QPointF(150, 140)});
  const std::vector<QRectF> boxes = place_labels(sizes, anchors, QRectF(10, 10, 400, 300),
                                                 {QRectF(10, 280, 390, 30)}, 6.0, {picture});
  std::vector<Vec2> plain_sizes, plain_anchors;
  for (const QSizeF& s : sizes) plain_sizes.emplace_back(s.width(), s.height());
  for (const QPointF& a : anchors) plain_anchors.emplace_back(a.x(), a.y());
  const std::vector<LabelBox> plain = place_labels(
      plain_sizes, plain_anchors, LabelBox{10, 10, 400, 300}, {LabelBox{10, 280, 390, 30}}, 6.0,
      {{{150, 40}, {260, 40}, {260, 140}, {150, 140}}});
  ASSERT_EQ(boxes.size(), plain.size());
  for (size_t i = 0; i < boxes.size(); ++i)
    EXPECT_EQ(boxes[i], QRectF(plain[i].x, plain[i].y, plain[i].width, plain[i].height)) << i;
  EXPECT_NEAR(covered_area(QRectF(160, 50, 10, 10), picture), 100.0, 1e-9);
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
