// The panels' framing (session/display/panel_framing.h), the desktop's and the page's: the
// bounds around a frame, the framed part of the camera image, the hugging aspect and the
// exact outlines.
#include "display/panel_framing.h"

#include <gtest/gtest.h>

#include "scene/view_culling.h"

namespace oflab::test {
namespace {

constexpr double kNear = 0.05;  // the exact render's near plane (SceneSettings::near)

void expect_box(const std::optional<BoundingBox>& box, double x0, double y0, double x1, double y1) {
  ASSERT_TRUE(box.has_value());
  EXPECT_DOUBLE_EQ(box->x_min, x0);
  EXPECT_DOUBLE_EQ(box->y_min, y0);
  EXPECT_DOUBLE_EQ(box->x_max, x1);
  EXPECT_DOUBLE_EQ(box->y_max, y1);
}

// The union of the frames' bounds around one frame, clamped to the loop; all of them with a
// negative reach; none where no frame in reach sees anything.
TEST(BoundsAround, UnitesTheFramesWithinReach) {
  const FrameBounds bounds = {BoundingBox{0, 0, 10, 10}, std::nullopt, BoundingBox{20, 20, 25, 25},
                              BoundingBox{100, 0, 101, 1}};
  expect_box(bounds_around(bounds, 0, 0), 0, 0, 10, 10);
  expect_box(bounds_around(bounds, 1, 1), 0, 0, 25, 25);
  EXPECT_FALSE(bounds_around(bounds, 1, 0).has_value());
  expect_box(bounds_around(bounds, 3, 1), 20, 0, 101, 25);
  expect_box(bounds_around(bounds, 3, 5), 0, 0, 101, 25);
  expect_box(bounds_around(bounds, 0, -1), 0, 0, 101, 25);
}

// The frame is the content grown by 2 % of its size on every side, widened (or heightened)
// about its centre to the aspect, then shrunk by the zoom: worked by hand.
TEST(PanelFrame, GrowsTheContentByTheMarginToTheAspectThenZooms) {
  // 100 x 50 at (100, 200): with the margin 104 x 52 about (150, 225).
  const BoundingBox content{100, 200, 200, 250};
  const BoundingBox wide = panel_frame(content, 640, 480, 4.0, 1.0);  // 208 x 52
  EXPECT_DOUBLE_EQ(wide.x_min, 150 - 104);
  EXPECT_DOUBLE_EQ(wide.x_max, 150 + 104);
  EXPECT_DOUBLE_EQ(wide.y_min, 225 - 26);
  EXPECT_DOUBLE_EQ(wide.y_max, 225 + 26);
  const BoundingBox square = panel_frame(content, 640, 480, 1.0, 2.0);  // 104 x 104, halved
  EXPECT_DOUBLE_EQ(square.x_max - square.x_min, 52.0);
  EXPECT_DOUBLE_EQ(square.y_max - square.y_min, 52.0);
  EXPECT_DOUBLE_EQ(square.x_min, 150 - 26);
  EXPECT_DOUBLE_EQ(square.y_min, 225 - 26);
  // No content: the camera image whole, with the same margin (640 x 480 -> 665.6 x 499.2).
  const BoundingBox whole = panel_frame(std::nullopt, 640, 480, 4.0 / 3.0, 1.0);
  EXPECT_NEAR(whole.x_min, -12.8, 1e-12);
  EXPECT_NEAR(whole.y_max, 489.6, 1e-12);
}

// The panels hug the content's aspect, within 4 of a square; the cell's aspect without content
// or when zoomed in.
TEST(PanelFrame, TheAspectHugsTheContentWithinFourOfASquare) {
  EXPECT_DOUBLE_EQ(hugging_aspect(2.0, BoundingBox{0, 0, 30, 10}, 1.0), 3.0);
  EXPECT_DOUBLE_EQ(hugging_aspect(2.0, BoundingBox{0, 0, 100, 10}, 1.0), 4.0);
  EXPECT_DOUBLE_EQ(hugging_aspect(2.0, BoundingBox{0, 0, 10, 100}, 1.0), 0.25);
  EXPECT_DOUBLE_EQ(hugging_aspect(2.0, std::nullopt, 1.0), 2.0);
  EXPECT_DOUBLE_EQ(hugging_aspect(2.0, BoundingBox{0, 0, 30, 10}, 1.5), 2.0);
  EXPECT_DOUBLE_EQ(hugging_aspect(2.0, BoundingBox{0, 0, 30, 0}, 1.0), 2.0);  // a line
}

// The share of the shown part inside the outlines, against areas worked by hand: a square
// over the left half, a right triangle over half of the rest (within a row of cells on its
// slanted edge), their overlap counted once; nothing outside.
TEST(OutlineFill, IsTheShareOfTheShownPartInsideTheOutlines) {
  const BoundingBox shown{10, 20, 110, 70};  // 100 x 50: 400 x 200 cells
  const std::vector<Vec2> left = {{10, 20}, {60, 20}, {60, 70}, {10, 70}};
  EXPECT_DOUBLE_EQ(outline_fill({left}, shown), 0.5);
  const std::vector<Vec2> triangle = {{60, 20}, {110, 20}, {60, 70}};  // half of the right half
  EXPECT_NEAR(outline_fill({triangle}, shown), 0.25, 200.0 / 80000.0);
  EXPECT_NEAR(outline_fill({left, triangle}, shown), 0.75, 200.0 / 80000.0);
  EXPECT_DOUBLE_EQ(outline_fill({left, left}, shown), 0.5);  // union, not sum
  const std::vector<Vec2> outside = {{200, 200}, {300, 200}, {300, 300}};
  EXPECT_DOUBLE_EQ(outline_fill({outside}, shown), 0.0);
  EXPECT_DOUBLE_EQ(outline_fill({left}, BoundingBox{0, 0, 0, 10}), 0.0);  // nothing shown
}

// A plane seen from behind (a two-sided sheet, drawn by every engine) keeps its dashed exact
// outline; a one-sided polygon (a solid's face) seen from behind has none, as it is culled.
TEST(ExactOutlines, TwoSidedSheetIsOutlinedFromBehindAndAOneSidedFaceIsNot) {
  Scene scene;
  ScenePolygon sheet;
  sheet.centre = Vec3(0.0, 0.0, 4.0);
  sheet.front = Vec3(0.0, 0.0, 1.0);  // facing away from an eye at the origin looking down +z
  sheet.size = Vec2(1.0, 1.0);
  sheet.two_sided = true;
  scene.polygons.push_back(sheet);
  const Camera camera;
  const ViewerPose eye;
  ASSERT_TRUE(is_back_facing(direction_to_view(eye, sheet.front), to_view(eye, sheet.centre)));
  const auto outlines = exact_outlines(scene, eye, camera, kNear);
  ASSERT_EQ(outlines.size(), 1u);
  EXPECT_EQ(outlines[0].size(), 4u);
  scene.polygons[0].two_sided = false;
  EXPECT_TRUE(exact_outlines(scene, eye, camera, kNear).empty());
  scene.polygons[0].front = Vec3(0.0, 0.0, -1.0);  // facing the eye: outlined either way
  EXPECT_EQ(exact_outlines(scene, eye, camera, kNear).size(), 1u);
}

}  // namespace
}  // namespace oflab::test
