// Convex polygons: validation, clipping against half-planes, boxes and the horizon line,
// and projective transformation.
#include "image/polygon.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

namespace oflab {
namespace {

TEST(ConvexPolygon, RectangleHasItsAreaAndPositiveOrientation) {
  const ConvexPolygon r = ConvexPolygon::rectangle(1.0, 2.0, 4.0, 7.0);
  EXPECT_EQ(r.size(), 4u);
  EXPECT_DOUBLE_EQ(r.area(), 15.0);
  EXPECT_FALSE(r.empty());
  const BoundingBox box = r.bounds();
  EXPECT_EQ(box.x_min, 1.0);
  EXPECT_EQ(box.y_max, 7.0);
  EXPECT_TRUE(ConvexPolygon::rectangle(0.0, 0.0, 0.0, 5.0).empty());
  EXPECT_TRUE(ConvexPolygon().empty());
}

TEST(ConvexPolygon, FromVerticesAcceptsEitherOrientationAndNormalisesIt) {
  const ConvexPolygon cw = ConvexPolygon::from_vertices({{0, 0}, {2, 0}, {2, 1}, {0, 1}});
  const ConvexPolygon ccw = ConvexPolygon::from_vertices({{0, 0}, {0, 1}, {2, 1}, {2, 0}});
  EXPECT_DOUBLE_EQ(cw.area(), 2.0);
  EXPECT_DOUBLE_EQ(ccw.area(), 2.0);
}

TEST(ConvexPolygon, FromVerticesRejectsNonConvexStarAndNonFiniteInput) {
  EXPECT_THROW(ConvexPolygon::from_vertices({{0, 0}, {4, 0}, {1, 1}, {0, 4}}),
               std::invalid_argument);
  std::vector<Vec2> star;
  for (int k = 0; k < 5; ++k) {
    const double t = 2.0 * 3.14159265358979323846 * (2 * k) / 5.0;
    star.emplace_back(std::cos(t), std::sin(t));
  }
  EXPECT_THROW(ConvexPolygon::from_vertices(star), std::invalid_argument);
  EXPECT_THROW(ConvexPolygon::from_vertices({{0, 0}, {1, std::nan("")}, {0, 1}}),
               std::invalid_argument);
  EXPECT_THROW(ConvexPolygon::rectangle(0, 0, std::numeric_limits<double>::infinity(), 1),
               std::invalid_argument);
  // Duplicates and collinear points are fine.
  EXPECT_DOUBLE_EQ(
      ConvexPolygon::from_vertices({{0, 0}, {0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}}).area(), 4.0);
}

TEST(ConvexPolygon, HalfPlaneClipMatchesTheAnalyticArea) {
  const ConvexPolygon square = ConvexPolygon::rectangle(0.0, 0.0, 1.0, 1.0);
  // x + y <= 1 keeps the lower-left triangle.
  EXPECT_NEAR(clip_to_half_plane(square, {-1.0, -1.0, 1.0}).area(), 0.5, 1e-15);
  // x >= 0.25 keeps 3/4.
  EXPECT_NEAR(clip_to_half_plane(square, {1.0, 0.0, -0.25}).area(), 0.75, 1e-15);
  EXPECT_TRUE(clip_to_half_plane(square, {1.0, 0.0, -2.0}).empty());
  EXPECT_EQ(clip_to_half_plane(square, {1.0, 0.0, 0.0}).size(), 4u);  // edge on the line
}

TEST(ConvexPolygon, RandomHalfPlaneClipsPartitionTheArea) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const ConvexPolygon hexagon =
      ConvexPolygon::from_vertices({{2, 0}, {1, 1.7}, {-1, 1.7}, {-2, 0}, {-1, -1.7}, {1, -1.7}});
  for (int k = 0; k < 200; ++k) {
    const Vec3 line(unit(rng), unit(rng), unit(rng));
    const ConvexPolygon a = clip_to_half_plane(hexagon, line);
    const ConvexPolygon b = clip_to_half_plane(hexagon, -line);
    EXPECT_NEAR(a.area() + b.area(), hexagon.area(), 1e-12);
    for (const Vec2& p : a.vertices()) {
      EXPECT_GE(line.x * p.x + line.y * p.y + line.z, -1e-12);
    }
  }
}

TEST(ConvexPolygon, BoxClipKeepsTheIntersection) {
  const ConvexPolygon diamond = ConvexPolygon::from_vertices({{0, -2}, {2, 0}, {0, 2}, {-2, 0}});
  const ConvexPolygon clipped = clip_to_box(diamond, {0.0, 0.0, 10.0, 10.0});
  EXPECT_NEAR(clipped.area(), 2.0, 1e-15);
  EXPECT_TRUE(clip_to_box(diamond, {5.0, 5.0, 6.0, 6.0}).empty());
}

TEST(ConvexPolygon, TransformMapsEveryVertexThroughTheHomography) {
  const Mat3 h = mat3_from_rows({0.9, 0.2, 3.0}, {-0.1, 1.1, -2.0}, {1e-3, 2e-3, 1.0});
  const ConvexPolygon r = ConvexPolygon::rectangle(0.0, 0.0, 100.0, 50.0);
  const ConvexPolygon t = transform(r, h);
  ASSERT_EQ(t.size(), 4u);
  for (const Vec2& v : r.vertices()) {
    const Vec2 expected = apply_homography(h, v);
    bool found = false;
    for (const Vec2& w : t.vertices()) found = found || glm::length(w - expected) < 1e-12;
    EXPECT_TRUE(found);
  }
  EXPECT_GT(t.area(), 0.0);
  // A mirror keeps a positive orientation.
  EXPECT_GT(transform(r, mat3_from_rows({-1, 0, 0}, {0, 1, 0}, {0, 0, 1})).area(), 0.0);
}

TEST(ConvexPolygon, TransformRefusesVerticesOnOrBeyondTheHorizon) {
  const Mat3 h = mat3_from_rows({1, 0, 0}, {0, 1, 0}, {-0.02, 0, 1});  // zero at x = 50
  EXPECT_THROW(transform(ConvexPolygon::rectangle(0, 0, 100, 10), h), std::invalid_argument);
}

TEST(ConvexPolygon, HorizonClipKeepsDenominatorsAboveEpsilonAndTheImageBounded) {
  const Mat3 h = mat3_from_rows({1, 0, 0}, {0, 1, 0}, {-0.02, 0.001, 1});  // crosses x ~ 50
  const ConvexPolygon r = ConvexPolygon::rectangle(0, 0, 100, 10);
  for (double eps : {1e-4, 1e-3, 0.1}) {
    const ConvexPolygon visible = clip_near_horizon(r, h, eps);
    ASSERT_FALSE(visible.empty());
    double largest = 0.0;
    for (const Vec2& p : r.vertices()) largest = std::max(largest, homography_denominator(h, p));
    for (const Vec2& p : visible.vertices()) {
      EXPECT_GE(homography_denominator(h, p), eps * largest * (1.0 - 1e-12));
    }
    const ConvexPolygon image = transform(visible, h);
    const BoundingBox box = image.bounds();
    EXPECT_LT(box.x_max, 100.0 / (eps * largest) * 1.01);
    // Still convex: from_vertices validates it.
    EXPECT_NO_THROW(ConvexPolygon::from_vertices(image.vertices()));
  }
  // Wholly behind: empty.
  EXPECT_TRUE(clip_near_horizon(r, -h * translation_matrix(-60, 0), 1e-3).empty());
  EXPECT_THROW(clip_near_horizon(r, h, 0.0), std::invalid_argument);
}

TEST(ConvexPolygon, ContainsUsesClosedBoundary) {
  const ConvexPolygon r = ConvexPolygon::rectangle(0, 0, 2, 2);
  EXPECT_TRUE(contains(r, {1, 1}));
  EXPECT_TRUE(contains(r, {0, 1}));
  EXPECT_FALSE(contains(r, {2.0001, 1}));
  EXPECT_FALSE(contains(ConvexPolygon(), {0, 0}));
  EXPECT_DOUBLE_EQ(translated(r, 5, -1).bounds().x_min, 5.0);
}

}  // namespace
}  // namespace oflab
