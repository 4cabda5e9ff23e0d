// Partial warps (core/image/warp.h WarpOptions::only) and the pixel sets they take
// (core/image/pixel_rows.h): every pixel a partial warp computes is the same bytes as the
// whole warp's, for both kernels and both samplings, and the set operations against a
// brute-force bitmap.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "image/pixel_rows.h"
#include "image/warp.h"
#include "warp_reference.h"

namespace oflab {
namespace {

using testing::kSentinel;
using testing::rotation_about;

// A bitmap of the pixels (x, y) in [x0, x0 + w) x [y0, y0 + h) that `set` holds.
std::vector<char> bitmap(const PixelRows& set, int x0, int y0, int w, int h) {
  std::vector<char> b(static_cast<std::size_t>(w) * h, 0);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x)
      b[static_cast<std::size_t>(y) * w + x] = set.any(y0 + y, x0 + x, x0 + x + 1);
  }
  return b;
}

bool centre_inside(const ConvexPolygon& p, double x, double y) {
  const auto& v = p.vertices();
  for (std::size_t k = 0; k < v.size(); ++k) {
    const Vec2& a = v[k];
    const Vec2& b = v[(k + 1) % v.size()];
    if ((b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x) <= 1e-9) return false;
  }
  return true;
}

TEST(PixelRows, RemovingAPolygonDropsExactlyThePixelsWhoseCentresItHolds) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> at(-20.0, 120.0);
  for (int trial = 0; trial < 40; ++trial) {
    const ConvexPolygon p = make_polygon_unchecked(
        {Vec2(at(rng), at(rng)), Vec2(at(rng), at(rng)), Vec2(at(rng), at(rng))});
    PixelRows set = PixelRows::full(100, 90);
    set.remove_centres_inside(p);
    std::int64_t left = 0;
    for (int y = 0; y < 90; ++y) {
      for (int x = 0; x < 100; ++x) {
        const bool in = set.any(y, x, x + 1);
        left += in;
        ASSERT_EQ(in, !centre_inside(p, x + 0.5, y + 0.5)) << trial << " at " << x << "," << y;
      }
    }
    EXPECT_EQ(set.count(), left);
  }
}

TEST(PixelRows, MinusAddAndShiftedAgreeWithBitmaps) {
  PixelRows a = PixelRows::full(50, 40);
  a.remove_centres_inside(ConvexPolygon::rectangle(10.2, 5.0, 30.7, 22.0));
  PixelRows b = PixelRows::full(20, 30).shifted(-7, 12);  // reaches above and left of a
  const PixelRows d = a.minus(b);
  PixelRows u = a;
  u.add(b);
  const PixelRows s = a.shifted(3, -4);
  const auto ba = bitmap(a, -10, -10, 70, 60), bb = bitmap(b, -10, -10, 70, 60);
  const auto bd = bitmap(d, -10, -10, 70, 60), bu = bitmap(u, -10, -10, 70, 60);
  const auto bs = bitmap(s, -7, -14, 70, 60);
  std::int64_t in_union = 0;
  for (std::size_t k = 0; k < ba.size(); ++k) {
    EXPECT_EQ(bd[k], ba[k] && !bb[k]) << k;
    EXPECT_EQ(bu[k], ba[k] || bb[k]) << k;
    EXPECT_EQ(bs[k], ba[k]) << k;
    in_union += bu[k];
  }
  EXPECT_EQ(u.count(), in_union);
}

TEST(PixelRows, FromRunsMergesUnsortedAndOverlappingRuns) {
  const PixelRows set = PixelRows::from_runs(
      -3, {{{5, 9}, {0, 2}, {7, 12}}, {}, {{4, 5}, {5, 6}, {-2, 1}}, {{3, 3}}});
  EXPECT_EQ(set.top(), -3);
  EXPECT_EQ(set.rows(), 4);
  ASSERT_EQ(set.row(-3).size(), 2u);  // [0, 2) and [5, 12)
  EXPECT_EQ(set.row(-3)[1].begin, 5);
  EXPECT_EQ(set.row(-3)[1].end, 12);
  ASSERT_EQ(set.row(-1).size(), 2u);  // [-2, 1) and [4, 6): touching runs merged
  EXPECT_EQ(set.row(-1)[1].begin, 4);
  EXPECT_EQ(set.row(-1)[1].end, 6);
  EXPECT_TRUE(set.row(0).empty());  // an empty run is no pixel
  EXPECT_EQ(set.count(), 2 + 7 + 3 + 2);
}

// Each case: the whole warp into a sentinel frame, then the partial warp of `only` into
// another; the partial one's pixels are each either the sentinel (left out) or the whole
// one's to the byte, it computes every pixel of `only` inside the polygon, and it leaves
// some out (the control: it did skip). The pixels it records as computed
// (WarpOptions::computed_pixels) are exactly those it wrote.
void expect_partial_matches_whole(const Layer& source, const Mat3& m, WarpOptions options) {
  const int w = 720, h = 560, ox = -10, oy = -30;
  Image whole(w, h, kSentinel), partial(w, h, kSentinel);
  const WarpStats all = warp_layer_into(source, m, whole, ox, oy, options);
  PixelRows only = PixelRows::full(w, h).shifted(ox, oy);
  only.remove_centres_inside(ConvexPolygon::rectangle(100.0, 50.0, 400.3, 300.0));
  only.remove_centres_inside(
      make_polygon_unchecked({Vec2(300, 200), Vec2(700, 260), Vec2(420, 520)}));
  options.only = &only;
  PixelRows recorded;
  options.computed_pixels = &recorded;
  const WarpStats some = warp_layer_into(source, m, partial, ox, oy, options);
  EXPECT_EQ(some.pixels_written, all.pixels_written);
  EXPECT_EQ(all.pixels_computed, all.pixels_written);
  std::int64_t computed = 0, skipped = 0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const Pixel p = partial.row(y)[x], q = whole.row(y)[x];
      ASSERT_EQ(p != kSentinel, recorded.any(y + oy, x + ox, x + ox + 1))
          << "recorded pixel " << x << "," << y;
      if (p != kSentinel) {
        ++computed;
        ASSERT_EQ(p, q) << "pixel " << x << "," << y;
      } else if (q != kSentinel) {
        ++skipped;
        ASSERT_FALSE(only.any(y + oy, x + ox, x + ox + 1)) << "wanted pixel " << x << "," << y;
      }
    }
  }
  EXPECT_EQ(computed, some.pixels_computed);
  EXPECT_EQ(recorded.count(), computed);
  EXPECT_GT(skipped, 10000);
  EXPECT_EQ(skipped, all.pixels_written - some.pixels_computed);
}

TEST(PartialWarp, EveryPixelComputedIsTheWholeWarpsToTheByte) {
  std::mt19937 rng(16);
  const Layer source = make_layer(testing::random_image(rng, 700, 500));
  const Mat3 tilt = rotation_about(17.0, 350.0, 250.0) *
                    mat3_from_rows({1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {2e-4, -4e-4, 1.0});
  const Mat3 turn = rotation_about(31.0, 350.0, 250.0) * translation_matrix(0.37, -0.21);
  for (const Mat3& m : {turn, tilt}) {
    for (Sampling sampling : {Sampling::kNearest, Sampling::kBilinear}) {
      for (WarpKernel kernel : {WarpKernel::kAutomatic, WarpKernel::kPerspective}) {
        SCOPED_TRACE(::testing::Message() << "sampling " << sampling_name(sampling) << " kernel "
                                          << static_cast<int>(kernel));
        expect_partial_matches_whole(source, m, WarpOptions{sampling, kernel});
      }
    }
  }
}

// Mipmap sampling (core/image/mipmap_kernel.h): a minifying affine warp between two levels
// (both levels' partial warps blended), one on a whole level (the bilinear kernel on level 1),
// and a perspective one that picks each pixel's level; every pixel computed is the whole
// warp's, every wanted pixel computed.
TEST(PartialWarp, MipmapPixelsComputedAreTheWholeWarpsToTheByte) {
  std::mt19937 rng(23);
  const Layer source = make_layer(testing::random_image(rng, 700, 500));
  const Mat3 shrink = [](double s) {
    return translation_matrix(360.0, 280.0) *
           mat3_from_rows({s, 0.0, 0.0}, {0.0, s, 0.0}, {0.0, 0.0, 1.0}) *
           translation_matrix(-350.0, -250.0);
  }(0.62);
  const Mat3 blended = rotation_about(23.0, 360.0, 280.0) * shrink;
  const Mat3 level_one = translation_matrix(10.25, 30.5) *
                         mat3_from_rows({0.5, 0.0, 0.0}, {0.0, 0.5, 0.0}, {0.0, 0.0, 1.0});
  const Mat3 tilt = shrink * mat3_from_rows({1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {6e-4, 9e-4, 1.0});
  const std::pair<const char*, Mat3> cases[] = {
      {"blended", blended}, {"level one", level_one}, {"tilt", tilt}};
  for (const auto& [name, m] : cases) {
    SCOPED_TRACE(name);
    expect_partial_matches_whole(source, m, WarpOptions{Sampling::kMipmap});
  }
}

}  // namespace
}  // namespace oflab
