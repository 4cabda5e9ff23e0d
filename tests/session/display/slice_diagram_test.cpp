// The scene-shifting view's diagram and walk (session/display/slice_diagram.h,
// session/player/slice_walk.h), which the desktop's and the page's views draw, against
// independent computations: the image speed of a point seen by a sideways-moving pinhole,
// the square-root scale, the planes' positions in the viewer frame, and an uninterrupted run.
#include "display/slice_diagram.h"

#include <gtest/gtest.h>

#include <cmath>

#include "player/slice_walk.h"

namespace oflab::test {
namespace {

// Pixels a point at depth z moves in the image when a pinhole of focal length k moves
// sideways by `step`: the difference of its two projections k X / Z.
double image_shift(double k, double step, double z) {
  const double x = 0.3;  // any lateral position
  return std::abs(k * (x - step) / z - k * x / z);
}

TEST(SliceDiagram, DepthTicksAreOneTwoFiveStepsUpToTheLargestDepth) {
  EXPECT_EQ(depth_ticks(50.0), (std::vector<double>{1, 2, 5, 10, 20, 50}));
  EXPECT_EQ(depth_ticks(7.0), (std::vector<double>{1, 2, 5}));
  EXPECT_EQ(depth_ticks(0.5), std::vector<double>{});
}

TEST(SliceDiagram, AsymptoteIsTheDepthThatMovesEpsilonPerFrame) {
  const double k = 600.0, speed = 0.05, epsilon = 1.0;
  const SliceDiagram d = slice_diagram({}, {}, k, epsilon, speed);
  EXPECT_NEAR(image_shift(k, speed, d.asymptote), epsilon, 1e-12);
  // Control: nearer than the asymptote a point moves more than epsilon.
  EXPECT_GT(image_shift(k, speed, 0.9 * d.asymptote), 1.05 * epsilon);
  EXPECT_EQ(asymptote_label(d), "asymptote Z = 30.00");
  EXPECT_DOUBLE_EQ(d.max_depth, 50.0);  // the asymptote is nearer than 50 units
  EXPECT_DOUBLE_EQ(slice_diagram({}, {}, k, 0.25, speed).max_depth, 1.25 * 120.0);
  // Parameters core refuses (epsilon 0) draw no asymptote.
  EXPECT_TRUE(std::isnan(slice_diagram({}, {}, k, 0.0, speed).asymptote));
}

TEST(SliceDiagram, DepthPositionIsASquareRootScaleFromTheEye) {
  EXPECT_DOUBLE_EQ(diagram_depth_position(0.0, 50.0), 0.0);
  EXPECT_DOUBLE_EQ(diagram_depth_position(12.5, 50.0), 0.5);
  EXPECT_DOUBLE_EQ(diagram_depth_position(50.0, 50.0), 1.0);
  EXPECT_DOUBLE_EQ(diagram_depth_position(80.0, 50.0), 1.0);  // clamped to the picture
}

TEST(SliceDiagram, PlanesAreThePolygonsWidthsInTheStartViewersFrame) {
  Scene scene;
  ScenePolygon wall;
  wall.centre = Vec3(2.0, 0.5, 10.0);
  wall.size = Vec2(4.0, 1.0);
  scene.polygons.push_back(wall);
  ViewerPose pose;  // the world origin one unit to the viewer's left: X_viewer = X_world - 1
  pose.translation = Vec3(-1.0, 0.0, 0.0);
  const std::vector<DiagramPlane> planes = diagram_planes(scene, pose);
  ASSERT_EQ(planes.size(), 1u);
  EXPECT_DOUBLE_EQ(planes[0].depth, 10.0);
  EXPECT_DOUBLE_EQ(planes[0].left, 1.0 - 2.0);
  EXPECT_DOUBLE_EQ(planes[0].right, 1.0 + 2.0);
}

// Each finite slice of the walk is as deep as epsilon allows: its near and far edges move by
// image shifts that differ by epsilon; the background starts at the asymptote or beyond.
TEST(SliceWalk, FiniteSlicesSpanExactlyEpsilonOfImageShift) {
  SliceWalk walk;
  ASSERT_EQ(walk.problem(), "");
  walk.set_slicing(2.0, 0.1);
  ASSERT_EQ(walk.slicing_problem(), "");
  const SliceDiagram d = walk.diagram();
  ASSERT_GT(d.slices.size(), 2u);
  for (size_t i = 0; i + 1 < d.slices.size(); ++i) {
    const double near = image_shift(d.focal_px, 0.1, d.slices[i].near);
    const double far = image_shift(d.focal_px, 0.1, d.slices[i].far);
    EXPECT_NEAR(near - far, 2.0, 1e-6) << i;
    EXPECT_DOUBLE_EQ(d.slices[i].far, d.slices[i + 1].near);
  }
  EXPECT_TRUE(std::isinf(d.slices.back().far));
  EXPECT_GE(d.slices.back().near, d.asymptote * (1 - 1e-9));
  EXPECT_EQ(slice_diagram_title(d), std::to_string(d.slices.size()) + " slices (" +
                                        std::to_string(d.slices.size() - 1) +
                                        " finite + background)");
  // Control: a larger epsilon cuts fewer slices.
  walk.set_slicing(4.0, 0.1);
  EXPECT_LT(walk.slices().size(), d.slices.size());
}

// Going back restarts and plays forward: the frame shown is the uninterrupted run's.
TEST(SliceWalk, GoingBackShowsTheUninterruptedRunsFrame) {
  SliceWalk walk;
  ASSERT_EQ(walk.problem(), "");
  walk.go_to(3);
  const Image at_three = walk.shifted_image();
  ASSERT_FALSE(at_three.empty());
  walk.go_to(5);
  EXPECT_EQ(walk.frame(), 5);
  EXPECT_NE(walk.shifted_image().pixels(), at_three.pixels());  // control: the walk moved
  walk.go_to(3);
  EXPECT_EQ(walk.frame(), 3);
  EXPECT_EQ(walk.shifted_image().pixels(), at_three.pixels());
  EXPECT_FALSE(walk.exact_image().empty());
  // Past the walk's end the window's frame wraps, and the caption says so.
  walk.go_to(walk.frame_count() + 2);
  EXPECT_EQ(walk.frame(), 2);
  EXPECT_NE(walk.caption(walk.frame_count() + 2).find("walk repeats"), std::string::npos);
  EXPECT_EQ(walk.caption(2).find("walk repeats"), std::string::npos);
}

}  // namespace
}  // namespace oflab::test
