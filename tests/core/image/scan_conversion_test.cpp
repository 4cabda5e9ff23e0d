// Scan conversion: the pixel-centre rule against per-pixel half-plane tests, and exact
// partition of shared edges.
#include "image/scan_conversion.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "warp_reference.h"

namespace oflab {
namespace {

std::vector<int> coverage_counts(const ConvexPolygon& polygon, int width, int height) {
  std::vector<int> counts(static_cast<std::size_t>(width) * height, 0);
  ScanConverter scan(polygon, width, height);
  PixelSpan span;
  int previous = -1;
  while (scan.next(span)) {
    EXPECT_GT(span.y, previous);
    previous = span.y;
    EXPECT_GE(span.x_begin, 0);
    EXPECT_LE(span.x_end, width);
    for (int x = span.x_begin; x < span.x_end; ++x) ++counts[span.y * width + x];
  }
  return counts;
}

TEST(ScanConversion, CoversExactlyThePixelsWhoseCentresAreInside) {
  std::mt19937 rng(5);
  for (int k = 0; k < 300; ++k) {
    // Polygons inside [0, 60]^2, partly beyond the 50 x 55 clip rectangle.
    const ConvexPolygon polygon = testing::random_polygon(rng, 60, 60);
    const std::vector<int> counts = coverage_counts(polygon, 50, 55);
    for (int y = 0; y < 55; ++y) {
      for (int x = 0; x < 50; ++x) {
        const testing::Coverage c = testing::classify(polygon, Vec2(x + 0.5, y + 0.5), 1e-9);
        const int n = counts[y * 50 + x];
        if (c == testing::Coverage::kInside) {
          EXPECT_EQ(n, 1) << x << "," << y;
        } else if (c == testing::Coverage::kOutside) {
          EXPECT_EQ(n, 0) << x << "," << y;
        }
      }
    }
  }
}

TEST(ScanConversion, PolygonsSharingAnEdgeCoverEveryPixelOnce) {
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const ConvexPolygon square = ConvexPolygon::rectangle(0.0, 0.0, 40.0, 30.0);
  for (int k = 0; k < 200; ++k) {
    // A cut through two random boundary points; the centre of pixel rows and columns is
    // hit exactly by some cuts (k % 4 == 0 uses half-integer end points).
    Vec2 p(40.0 * unit(rng), 0.0);
    Vec2 q(40.0 * unit(rng), 30.0);
    if (k % 4 == 0) {
      p.x = std::floor(p.x) + 0.5;
      q.x = std::floor(q.x) + 0.5;
    }
    const Vec3 line(q.y - p.y, p.x - q.x, q.x * p.y - p.x * q.y);
    const ConvexPolygon left = clip_to_half_plane(square, line);
    const ConvexPolygon right = clip_to_half_plane(square, -line);
    const std::vector<int> a = coverage_counts(left, 40, 30);
    const std::vector<int> b = coverage_counts(right, 40, 30);
    for (std::size_t i = 0; i < a.size(); ++i) ASSERT_EQ(a[i] + b[i], 1) << "cut " << k;
  }
}

// Two polygons whose shared edge passes through pixel centres, each computed from its own
// vertices: they differ by a rounding (1e-13 px), the left one's just short of the centres
// and the right one's just past them. Without the tie snap the right one would leave the
// centres on its left edge and the left one would leave them to it (a one-pixel gap); with
// it every pixel is covered once. Control: a real offset (1e-6 px) is no tie and moves the
// column to the polygon that truly covers its centres.
TEST(ScanConversion, SharedEdgesThroughCentresComputedFromDifferentVerticesLeaveNoGap) {
  for (const double x : {10.5, 552.5, 727.5}) {
    for (const double lean : {0.0, 2.0}) {  // vertical, and slanted through centres
      const double w = x + 20.0;
      const ConvexPolygon left = ConvexPolygon::from_vertices(
          {Vec2(0, 0), Vec2(x - 1e-13, 0), Vec2(x + 8.0 * lean - 1e-13, 8), Vec2(0, 8)});
      const ConvexPolygon right = ConvexPolygon::from_vertices(
          {Vec2(x + 1e-13, 0), Vec2(w, 0), Vec2(w, 8), Vec2(x + 8.0 * lean + 1e-13, 8)});
      const std::vector<int> a = coverage_counts(left, static_cast<int>(w), 8);
      const std::vector<int> b = coverage_counts(right, static_cast<int>(w), 8);
      for (std::size_t i = 0; i < a.size(); ++i) {
        ASSERT_EQ(a[i] + b[i], 1) << "edge at " << x << ", lean " << lean << ", pixel " << i;
      }
      // The centre on the edge goes to the right-hand polygon (x_left <= c.x).
      if (lean == 0.0) {
        EXPECT_EQ(b[static_cast<std::size_t>(x - 0.5)], 1);
      }
    }
    const ConvexPolygon short_of = ConvexPolygon::rectangle(0.0, 0.0, x - 1e-6, 8.0);
    EXPECT_EQ(
        coverage_counts(short_of, static_cast<int>(x + 20.0), 8)[static_cast<std::size_t>(x - 0.5)],
        0);
  }
}

TEST(ScanConversion, HugeAndDegeneratePolygonsAreClampedOrEmpty) {
  const ConvexPolygon huge = ConvexPolygon::rectangle(-1e300, -1e300, 1e300, 1e300);
  const std::vector<int> counts = coverage_counts(huge, 7, 5);
  for (int n : counts) EXPECT_EQ(n, 1);
  const ConvexPolygon line = ConvexPolygon::from_vertices({{0, 0}, {10, 10}, {5, 5}});
  for (int n : coverage_counts(line, 10, 10)) EXPECT_EQ(n, 0);
  for (int n : coverage_counts(ConvexPolygon::rectangle(0.2, 0.2, 0.4, 0.4), 3, 3)) {
    EXPECT_EQ(n, 0);  // contains no pixel centre
  }
  ScanConverter nothing(ConvexPolygon::rectangle(0, 0, 5, 5), 0, 5);
  PixelSpan span;
  EXPECT_FALSE(nothing.next(span));
}

}  // namespace
}  // namespace oflab
