// Where labels go over a picture (session/display/label_layout.h), the rule the desktop's and
// the page's world views share: labels crowded on one point still neither overlap nor leave
// their area nor cover the caption, they keep off the pictures where they can, and the area
// they cover of an outline is the area worked out by hand or counted on a fine grid.
#include "display/label_layout.h"

#include <gtest/gtest.h>

#include <cmath>

namespace oflab::test {
namespace {

double overlap_area(const LabelBox& a, const LabelBox& b) {
  const double w = std::min(a.right(), b.right()) - std::max(a.x, b.x);
  const double h = std::min(a.bottom(), b.bottom()) - std::max(a.y, b.y);
  return w > 0 && h > 0 ? w * h : 0.0;
}

bool inside(const LabelBox& inner, const LabelBox& outer) {
  return inner.x >= outer.x && inner.y >= outer.y && inner.right() <= outer.right() &&
         inner.bottom() <= outer.bottom();
}

// Point in polygon by crossings (even-odd), for the grid count.
bool contains(const std::vector<Vec2>& polygon, const Vec2& p) {
  bool in = false;
  for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Vec2 &a = polygon[i], &b = polygon[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) in = !in;
  }
  return in;
}

TEST(LabelLayout, AFreeLabelSitsRightOfAndAboveItsPoint) {
  const std::vector<LabelBox> boxes =
      place_labels({Vec2(50, 20)}, {Vec2(100, 100)}, LabelBox{0, 0, 400, 300}, {}, 6.0);
  ASSERT_EQ(boxes.size(), 1u);
  EXPECT_EQ(boxes[0], (LabelBox{106, 74, 50, 20}));
}

TEST(LabelLayout, CrowdedLabelsNeitherOverlapNorLeaveTheAreaNorCoverTheCaption) {
  const LabelBox area{10, 10, 400, 300};
  const LabelBox caption{10, 280, 390, 30};
  const std::vector<Vec2> sizes = {{40, 20}, {110, 20}, {20, 20}, {20, 20}, {90, 20}, {250, 20}};
  std::vector<Vec2> anchors(sizes.size(), Vec2(200, 150));  // all on one point
  anchors.back() = Vec2(405, 295);                          // in the caption's corner
  const std::vector<LabelBox> boxes = place_labels(sizes, anchors, area, {caption});
  ASSERT_EQ(boxes.size(), sizes.size());
  for (size_t i = 0; i < boxes.size(); ++i) {
    EXPECT_TRUE(inside(boxes[i], area)) << i;
    EXPECT_EQ(boxes[i].width, sizes[i].x) << i;
    EXPECT_LE(overlap_area(boxes[i], caption), 0.0) << i;
    for (size_t j = i + 1; j < boxes.size(); ++j) {
      EXPECT_LE(overlap_area(boxes[i], boxes[j]), 0.0) << i << " and " << j;
    }
  }
  // Control: the same labels each at its first place would overlap.
  EXPECT_GT(overlap_area(LabelBox{206, 124, 40, 20}, LabelBox{206, 124, 110, 20}), 0.0);
}

// covered_area against areas worked out by hand (a right triangle's legs of 10 px: a box
// inside it, a box holding it, a box cut by its hypotenuse) and against a grid count.
TEST(LabelLayout, CoveredAreaIsTheBoxInsideTheOutline) {
  const std::vector<Vec2> triangle = {{0, 0}, {10, 0}, {0, 10}};
  EXPECT_NEAR(covered_area(LabelBox{0, 0, 4, 4}, triangle), 16.0, 1e-9);
  EXPECT_NEAR(covered_area(LabelBox{-5, -5, 30, 30}, triangle), 50.0, 1e-9);
  EXPECT_NEAR(covered_area(LabelBox{0, 0, 10, 10}, triangle), 50.0, 1e-9);
  // The box [5, 10] x [0, 10]: the triangle's part is x from 5 to 10 under y = 10 - x.
  EXPECT_NEAR(covered_area(LabelBox{5, 0, 5, 10}, triangle), 12.5, 1e-9);
  EXPECT_EQ(covered_area(LabelBox{20, 20, 5, 5}, triangle), 0.0);
  const std::vector<Vec2> quad = {{3, 1}, {17, 4}, {14, 15}, {1, 11}};
  const LabelBox box{5, 2, 9, 7};
  double count = 0.0;
  const double step = 0.05;
  for (double x = box.x + step / 2; x < box.right(); x += step)
    for (double y = box.y + step / 2; y < box.bottom(); y += step)
      count += contains(quad, Vec2(x, y)) ? step * step : 0.0;
  EXPECT_NEAR(covered_area(box, quad), count, 0.2);
}

// A label whose wanted place covers a picture takes the nearest place clear of it; one whose
// every place covers it takes the place covering the least, still clear of the other texts.
TEST(LabelLayout, LabelsLeaveThePicturesClear) {
  const LabelBox area{0, 0, 400, 300};
  const std::vector<Vec2> picture = {{100, 40}, {200, 40}, {200, 95}, {100, 95}};
  const std::vector<LabelBox> boxes =
      place_labels({Vec2(50, 20)}, {Vec2(100, 100)}, area, {}, 6.0, {picture});
  ASSERT_EQ(boxes.size(), 1u);
  EXPECT_EQ(covered_area(boxes[0], picture), 0.0);
  EXPECT_EQ(boxes[0], (LabelBox{106, 106, 50, 20}));  // right, below
  const std::vector<Vec2> everywhere = {{0, 0}, {400, 0}, {400, 300}, {0, 300}};
  const LabelBox caption{106, 74, 50, 20};
  const std::vector<LabelBox> forced =
      place_labels({Vec2(50, 20)}, {Vec2(100, 100)}, area, {caption}, 6.0, {everywhere});
  ASSERT_EQ(forced.size(), 1u);
  EXPECT_GT(covered_area(forced[0], everywhere), 0.0);
  EXPECT_LE(overlap_area(forced[0], caption), 0.0);
}

}  // namespace
}  // namespace oflab::test
