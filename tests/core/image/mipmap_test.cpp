// The mip pyramid and the mipmap kernel against independent computations: the levels
// against direct box averages of the source, the level choice against the analytic
// Jacobian of known affine and perspective warps, a pure 2x minification against level 1,
// and magnification against the bilinear kernel.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "image/inverse_map.h"
#include "image/mip_pyramid.h"
#include "image/mip_row_levels.h"
#include "image/mipmap_kernel.h"
#include "image/polygon.h"
#include "image/scan_conversion.h"
#include "image/thread_pool.h"
#include "image/trilinear_row.h"
#include "image/warp.h"
#include "image/warp_kernels.h"
#include "image/warp_plan.h"
#include "warp_reference.h"

namespace oflab {
namespace {

constexpr double kPi = 3.14159265358979323846;

Mat3 scaling(double sx, double sy) {
  return mat3_from_rows({sx, 0.0, 0.0}, {0.0, sy, 0.0}, {0.0, 0.0, 1.0});
}

Mat3 rotation(double radians) {
  return mat3_from_rows({std::cos(radians), -std::sin(radians), 0.0},
                        {std::sin(radians), std::cos(radians), 0.0}, {0.0, 0.0, 1.0});
}

// The largest difference of a channel between two pixels.
int max_channel_difference(const Pixel& a, const Pixel& b) {
  return std::max(
      {std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b), std::abs(a.a - b.a)});
}

TEST(MipPyramid, LevelsAreBoxAveragesOfTheSource) {
  std::mt19937 rng(5);
  for (const auto& [w, h] : {std::pair{64, 64}, std::pair{37, 23}, std::pair{1, 9}}) {
    const Image source = testing::random_image(rng, w, h);
    MipPyramid pyramid;
    build_mip_pyramid(source, pyramid);
    ASSERT_EQ(pyramid.top(), static_cast<int>(std::ceil(std::log2(std::max(w, h)))));
    EXPECT_EQ(pyramid.level(pyramid.top()).width(), 1);
    EXPECT_EQ(pyramid.level(pyramid.top()).height(), 1);
    for (int k = 1; k <= pyramid.top(); ++k) {
      const Image& level = pyramid.level(k);
      const int side = 1 << k;
      ASSERT_EQ(level.width(), (w + side - 1) / side);
      ASSERT_EQ(level.height(), (h + side - 1) / side);
      // Blocks wholly inside the source: the plain mean of its 2^k x 2^k pixels. Each level
      // rounds once, so after k levels the value is within k / 2 of the exact mean.
      for (int j = 0; (j + 1) * side <= h; ++j) {
        for (int i = 0; (i + 1) * side <= w; ++i) {
          double sum[4] = {0, 0, 0, 0};
          for (int y = j * side; y < (j + 1) * side; ++y) {
            for (int x = i * side; x < (i + 1) * side; ++x) {
              const Pixel& p = source.at(x, y);
              sum[0] += p.r, sum[1] += p.g, sum[2] += p.b, sum[3] += p.a;
            }
          }
          const Pixel& got = level.at(i, j);
          const double values[4] = {double(got.r), double(got.g), double(got.b), double(got.a)};
          for (int c = 0; c < 4; ++c) {
            ASSERT_LE(std::abs(values[c] - sum[c] / (side * side)), 0.5 * k)
                << w << "x" << h << " level " << k << " pixel " << i << "," << j;
          }
        }
      }
    }
  }
}

// halve_image (each level of the pyramid) is every pixel's (a + b + c + d + 2) / 4 per channel,
// worked out here tap by tap with odd edges clamped: on an image with both sides odd, large
// enough to be reduced in bands of rows, on 1 thread and on 2 (the SSE2 pairs, the scalar
// tail and the clamped last column and row all met).
TEST(MipPyramid, HalvingIsTheRoundedMeanOfEachTwoByTwo) {
  std::mt19937 rng(21);
  const Image fine = testing::random_image(rng, 1025, 767);
  for (int threads : {1, 2}) {
    set_worker_threads(threads);
    Image coarse;
    halve_image(fine, coarse);
    set_worker_threads(1);
    ASSERT_EQ(coarse.width(), 513);
    ASSERT_EQ(coarse.height(), 384);
    std::int64_t wrong = 0;
    for (int j = 0; j < coarse.height(); ++j) {
      for (int i = 0; i < coarse.width(); ++i) {
        const int x0 = 2 * i, x1 = std::min(2 * i + 1, 1024);
        const int y0 = 2 * j, y1 = std::min(2 * j + 1, 766);
        const Pixel t[4] = {fine.at(x0, y0), fine.at(x1, y0), fine.at(x0, y1), fine.at(x1, y1)};
        const auto mean = [&](std::uint8_t Pixel::*c) {
          return (t[0].*c + t[1].*c + t[2].*c + t[3].*c + 2) / 4;
        };
        const Pixel& got = coarse.at(i, j);
        wrong += got.r != mean(&Pixel::r) || got.g != mean(&Pixel::g) || got.b != mean(&Pixel::b) ||
                 got.a != mean(&Pixel::a);
      }
    }
    EXPECT_EQ(wrong, 0) << threads << " threads";
  }
}

// Two independent reductions agree: box_reduce by 2 is level 1 of an even image; by 4 it is
// the plain mean of each 4 x 4 block (within the rounding of one mean).
TEST(MipPyramid, BoxReduceIsTheBlockMean) {
  std::mt19937 rng(6);
  const Image source = testing::random_image(rng, 48, 32);
  MipPyramid pyramid;
  build_mip_pyramid(source, pyramid);
  EXPECT_EQ(box_reduce(source, 2).pixels(), pyramid.level(1).pixels());
  const Image by4 = box_reduce(source, 4);
  ASSERT_EQ(by4.width(), 12);
  ASSERT_EQ(by4.height(), 8);
  for (int j = 0; j < 8; ++j) {
    for (int i = 0; i < 12; ++i) {
      double alpha = 0.0;
      for (int y = 4 * j; y < 4 * j + 4; ++y) {
        for (int x = 4 * i; x < 4 * i + 4; ++x) alpha += source.at(x, y).a;
      }
      ASSERT_LE(std::abs(by4.at(i, j).a - alpha / 16.0), 0.5);
    }
  }
  EXPECT_THROW(box_reduce(source, 5), std::invalid_argument);
  EXPECT_THROW(box_reduce(source, 0), std::invalid_argument);
}

TEST(MipPyramid, ALevelOfAnOddImageClampsItsLastColumn) {
  Image source(3, 1);
  source.at(0, 0) = Pixel{0, 0, 0, 0};
  source.at(1, 0) = Pixel{100, 100, 100, 200};
  source.at(2, 0) = Pixel{40, 40, 40, 80};
  MipPyramid pyramid;
  build_mip_pyramid(source, pyramid);
  ASSERT_EQ(pyramid.level(1).width(), 2);
  EXPECT_EQ(pyramid.level(1).at(0, 0), (Pixel{50, 50, 50, 100}));
  EXPECT_EQ(pyramid.level(1).at(1, 0), (Pixel{40, 40, 40, 80}));  // its own tap, clamped
}

// Each bordered copy is its level with every coordinate clamped to the level, computed
// texel by texel; the copies of a pyramid rebuilt at another size follow it.
TEST(MipPyramid, BorderedLevelsReplicateTheEdgeTexels) {
  std::mt19937 rng(12);
  MipPyramid pyramid;
  for (const auto& size : {std::pair<int, int>{37, 22}, std::pair<int, int>{16, 16}}) {
    build_mip_pyramid(testing::random_image(rng, size.first, size.second), pyramid);
    ASSERT_TRUE(pyramid.has_borders());
    for (int k = 1; k <= pyramid.top(); ++k) {
      const Image& level = pyramid.level(k);
      const Image& copy = pyramid.bordered_level(k);
      ASSERT_EQ(copy.width(), level.width() + 2 * kMipBorder);
      ASSERT_EQ(copy.height(), level.height() + 2 * kMipBorder);
      for (int j = 0; j < copy.height(); ++j) {
        for (int i = 0; i < copy.width(); ++i) {
          const int x = std::min(std::max(i - kMipBorder, 0), level.width() - 1);
          const int y = std::min(std::max(j - kMipBorder, 0), level.height() - 1);
          ASSERT_EQ(copy.at(i, j), level.at(x, y)) << "level " << k << " at " << i << ", " << j;
        }
      }
    }
  }
}

// The footprint's longer axis of an affine warp A (source -> destination) is 1 / the smaller
// singular value of A, known here by construction: A = R(a) diag(s1, s2) R(b).
TEST(MipLevel, AffineLevelIsLog2OfTheInverseOfTheSmallerScale) {
  for (double s1 : {0.1, 0.3, 0.5, 0.9, 2.0}) {
    for (double s2 : {0.2, 0.5, 1.0, 3.0}) {
      const Mat3 a = rotation(0.7) * scaling(s1, s2) * rotation(-1.9);
      const Mat3 j = glm::inverse(a);
      const double expected = std::clamp(std::log2(1.0 / std::min(s1, s2)), 0.0, 5.0);
      EXPECT_NEAR(mip_level(entry(j, 0, 0), entry(j, 0, 1), entry(j, 1, 0), entry(j, 1, 1), 5),
                  expected, 1e-12)
          << s1 << " " << s2;
    }
  }
}

// A perspective warp: the inverse map's Jacobian at a pixel by central differences of the
// inverse homography, and the longer footprint axis as a brute-force maximum over directions.
TEST(MipLevel, PerspectiveLevelFollowsTheJacobianOfTheInverseMap) {
  const Mat3 h = mat3_from_rows({0.8, 0.1, 5.0}, {-0.05, 0.6, 3.0}, {0.002, 0.004, 1.0});
  const Mat3 inverse = glm::inverse(h);
  for (const Vec2& p : {Vec2(10.5, 20.5), Vec2(100.5, 5.5), Vec2(60.5, 90.5)}) {
    const double step = 1e-4;
    const Vec2 dx = (apply_homography(inverse, p + Vec2(step, 0)) -
                     apply_homography(inverse, p - Vec2(step, 0))) /
                    (2 * step);
    const Vec2 dy = (apply_homography(inverse, p + Vec2(0, step)) -
                     apply_homography(inverse, p - Vec2(0, step))) /
                    (2 * step);
    double sigma = 0.0;
    for (int k = 0; k < 20000; ++k) {
      const double t = k * kPi / 20000;
      sigma = std::max(sigma, glm::length(std::cos(t) * dx + std::sin(t) * dy));
    }
    // The analytic Jacobian the kernel uses: (A - s g^T) / D at the pixel.
    const Vec3 q = inverse * Vec3(p, 1.0);
    const Vec2 s(q.x / q.z, q.y / q.z);
    const double d = q.z;
    auto e = [&](int r, int c) { return entry(inverse, r, c); };
    const double level = mip_level((e(0, 0) - s.x * e(2, 0)) / d, (e(0, 1) - s.x * e(2, 1)) / d,
                                   (e(1, 0) - s.y * e(2, 0)) / d, (e(1, 1) - s.y * e(2, 1)) / d, 8);
    EXPECT_GT(sigma, 1.0);
    EXPECT_NEAR(level, std::log2(sigma), 1e-6) << p.x << "," << p.y;
  }
}

// The analytic Jacobian of the inverse map h at the centre of pixel (x, y).
std::array<double, 4> jacobian_at(const Mat3& h, int x, int y) {
  auto e = [&](int r, int c) { return entry(h, r, c); };
  const Vec3 q = h * Vec3(x + 0.5, y + 0.5, 1.0);
  const double su = q.x / q.z, sv = q.y / q.z;
  return {(e(0, 0) - su * e(2, 0)) / q.z, (e(0, 1) - su * e(2, 1)) / q.z,
          (e(1, 0) - sv * e(2, 0)) / q.z, (e(1, 1) - sv * e(2, 1)) / q.z};
}

// How one row's level indices compare with the exact levels (256 log2 of the footprint axis
// of the analytic Jacobian, mip_pyramid.h's eigenvalue closed form, not the row's |P| + |R|
// form; all in steps, clamped to [0, 256 top]): the largest distance of an index from the
// exact level, from the linear interpolation of the exact levels at the knots (pixels 0, 8,
// 16, ... and the last), of that interpolation from the exact level, and of an index from
// the exact index; and the pixels where the Frobenius norm (the control) rounds more than
// half a step from the exact level.
struct RowCheck {
  double off_exact = 0.0, off_interpolated = 0.0, interpolation_off = 0.0, off_index = 0.0;
  double scalar_off = 0.0;  // mip_row_levels_scalar's largest distance from the exact level
  std::int64_t pixels = 0, frobenius_far = 0;
};

RowCheck check_row(const Mat3& h, int top, int y, int x_begin, int x_end) {
  const int count = x_end - x_begin;
  std::vector<std::uint16_t> fast(static_cast<std::size_t>(count)), scalar(fast.size());
  mip_row_levels(h, top, y, x_begin, x_end, fast.data());
  mip_row_levels_scalar(h, top, y, x_begin, x_end, scalar.data());
  std::vector<double> exact(fast.size()), frobenius(fast.size());
  for (int i = 0; i < count; ++i) {
    const auto [j00, j01, j10, j11] = jacobian_at(h, x_begin + i, y);
    exact[i] = 256.0 * std::log2(footprint_axis(j00, j01, j10, j11));
    frobenius[i] = 256.0 * std::log2(std::sqrt(j00 * j00 + j01 * j01 + j10 * j10 + j11 * j11));
  }
  const double most = 256.0 * top;
  RowCheck c;
  for (int i = 0; i < count; ++i) {
    const int a = i / kMipLevelKnotStep * kMipLevelKnotStep;
    const int b = std::min(a + kMipLevelKnotStep, count - 1);
    const double along = b > a ? double(i - a) / (b - a) : 0.0;
    const double interpolated = std::clamp(exact[a] + along * (exact[b] - exact[a]), 0.0, most);
    const double level = std::clamp(exact[i], 0.0, most);
    c.off_exact = std::max(c.off_exact, std::abs(fast[i] - level));
    c.off_interpolated = std::max(c.off_interpolated, std::abs(fast[i] - interpolated));
    c.interpolation_off = std::max(c.interpolation_off, std::abs(interpolated - level));
    c.off_index = std::max(c.off_index, std::abs(fast[i] - std::round(level)));
    c.scalar_off = std::max(c.scalar_off, std::abs(scalar[i] - level));
    c.frobenius_far += std::abs(std::round(std::clamp(frobenius[i], 0.0, most)) - level) > 0.51;
    ++c.pixels;
  }
  return c;
}

// The level index along a row (mip_row_levels.h, the perspective kernel's levels) against
// the exact level in double (check_row) on random minifying tilts, on the bench's tilt,
// whose rows pass where the two singular values meet, and on nearly conformal tilts, where
// they nearly meet on many rows (the level then bends sharply). Each row is either computed
// at every pixel (each index within 1/200 of a step of the exact level before rounding) or
// interpolated (each index within 1/200 of a step of the linear interpolation of the exact
// levels at the knots before rounding), and either way within one step of the exact index.
// Both kinds occur. The controls: on the rows where that interpolation would be more than
// half a step off, every pixel is computed (without mip_row_levels' bound some of them are
// interpolated and fail this); and the Frobenius norm in place of the largest singular
// value is off by more on most pixels.
TEST(MipRowLevels, EachIndexIsTheExactLevelOrItsInterpolationBetweenKnotsRounded) {
  std::mt19937 rng(44);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<Mat3> inverses;
  const double t = 20.0 * kPi / 180.0;
  Mat3 tilt(1.0);
  entry(tilt, 2, 0) = 0.6 / 1024.0;
  const Mat3 bench = translation_matrix(300.0, 200.0) * scaling(0.4, 0.4) * rotation(t) *
                     translation_matrix(-512, -384) * translation_matrix(512, 384) * tilt *
                     translation_matrix(-512, -384);
  inverses.push_back(glm::inverse(bench));
  for (int k = 0; k < 260; ++k) {  // after the first 60, nearly conformal
    const double scale = std::exp2(1.0 + 2.0 * std::abs(unit(rng)));
    const double stretch = k < 60 ? 0.5 : 0.05, perspective = k < 60 ? 0.002 : 0.0015;
    Mat3 h = rotation(kPi * unit(rng)) * scaling(scale, scale * (1.0 + stretch * unit(rng)));
    entry(h, 0, 2) = 50.0 * unit(rng);
    entry(h, 1, 2) = 50.0 * unit(rng);
    entry(h, 2, 0) = perspective * unit(rng);  // D in [0.2, 1.8] over the rows below
    entry(h, 2, 1) = perspective * unit(rng);
    inverses.push_back(h);
  }
  std::int64_t pixels = 0, frobenius_far = 0;
  int rows = 0, every_pixel_rows = 0, interpolated_rows = 0, rough_rows = 0;
  double worst = 0.0, worst_scalar = 0.0;
  for (const Mat3& h : inverses) {
    for (int y : {0, 50, 199, 200, 201, 399}) {
      const RowCheck c = check_row(h, 10, y, y % 7, 397 - y % 5);
      const bool every_pixel = c.off_exact <= 0.505, interpolated = c.off_interpolated <= 0.505;
      EXPECT_TRUE(every_pixel || interpolated)
          << y << ": " << c.off_exact << " " << c.off_interpolated;
      every_pixel_rows += every_pixel && !interpolated;
      interpolated_rows += interpolated && !every_pixel;
      if (c.interpolation_off > 0.55) {
        ++rough_rows;
        EXPECT_TRUE(every_pixel) << "row " << y << " interpolated: " << c.interpolation_off;
      }
      worst = std::max(worst, c.off_index);
      worst_scalar = std::max(worst_scalar, c.scalar_off);
      pixels += c.pixels;
      frobenius_far += c.frobenius_far;
      ++rows;
    }
  }
  ASSERT_GT(pixels, 100000);
  EXPECT_LE(worst, 1.0) << "steps from the exact index";
  EXPECT_LE(worst_scalar, 0.5 + 1e-6);
  if (warp_avx2_enabled()) {  // else every pixel in double
    EXPECT_GT(interpolated_rows, rows / 4);
  }
  EXPECT_GT(every_pixel_rows, 0);
  EXPECT_GT(rough_rows, 0);
  EXPECT_GT(frobenius_far, pixels / 2);
}

// Level k's map of a perspective plan as the mipmap kernel makes it (positions scaled by
// 2^-k, pixel-centre indices, over the plan's polygon clipped to the output), its image, and
// the bordered copies of `borders` (levels 1 and up; none if null).
MipLevelMaps plan_level_maps(const WarpPlan& plan, const Image& source, const MipPyramid& pyramid,
                             const MipPyramid* borders) {
  MipLevelMaps levels;
  const ConvexPolygon region =
      clip_to_box(plan.polygon, BoundingBox{0.0, 0.0, static_cast<double>(plan.output_width),
                                            static_cast<double>(plan.output_height)});
  for (int k = 0; k <= pyramid.top(); ++k) {
    const double s = std::ldexp(1.0, -k);
    levels.maps.push_back(make_inverse_map(
        translation_matrix(-0.5, -0.5) * scaling(s, s) * plan.dest_to_source, region, false));
    levels.images.push_back(k == 0 ? &source : &pyramid.level(k));
    levels.bordered.push_back(k > 0 && borders ? &borders->bordered_level(k) : nullptr);
  }
  return levels;
}

// Each pixel of the span sampled alone on its level pair (index: 256 lower + weight per
// pixel): run_trilinear_row over one pixel, run_bilinear_row where the weight is 0.
std::vector<Pixel> each_pixel_alone(const MipLevelMaps& levels, const std::uint16_t* index,
                                    const PixelSpan& span) {
  std::vector<Pixel> pixels(static_cast<std::size_t>(span.x_end - span.x_begin));
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    const auto k = static_cast<std::size_t>(index[i] >> 8);
    const std::uint16_t w = index[i] & 255;
    const int x = span.x_begin + static_cast<int>(i);
    if (w == 0) {
      run_bilinear_row(levels.maps[k], *levels.images[k], span.y, x, x + 1, &pixels[i]);
    } else {
      run_trilinear_row(levels.maps[k], *levels.images[k], levels.maps[k + 1],
                        *levels.images[k + 1], span.y, x, x + 1, &w, &pixels[i]);
    }
  }
  return pixels;
}

// The level row (run_trilinear_levels_row: one loop over a span that stops where the lower
// level changes) against each pixel computed alone by the stretch rows it replaces
// (each_pixel_alone; a one-pixel call takes the clamped path, so this also checks that a
// pixel's bytes do not depend on the run it is part of). Whole spans and random pieces of
// them, on tilts whose rows cross several levels, reach the top level and leave the source.
// The row runs with the levels' bordered copies (the pixels whose taps leave a level by less
// than its border sampled from the copies) and without (clamped taps). The controls: the same
// rows with every weight one step higher differ on blended pixels, and with the copies'
// borders spoiled (each border texel inverted) they differ too, so the copies are read.
TEST(TrilinearLevelsRow, EachPixelHasTheBytesOfItsLevelPairSampledAlone) {
  if (!warp_avx2_enabled()) GTEST_SKIP() << "the level row needs the AVX2 loops";
  std::mt19937 rng(45);
  const Layer source = make_layer(testing::random_image(rng, 160, 120));
  MipPyramid pyramid;
  build_mip_pyramid(source.image, pyramid);
  MipPyramid spoiled = pyramid;
  for (Image& copy : spoiled.bordered) {
    for (int j = 0; j < copy.height(); ++j) {
      for (int i = 0; i < copy.width(); ++i) {
        const bool inner = i >= kMipBorder && i < copy.width() - kMipBorder && j >= kMipBorder &&
                           j < copy.height() - kMipBorder;
        Pixel& p = copy.at(i, j);
        if (!inner) p = Pixel{static_cast<std::uint8_t>(255 - p.r), p.g, p.b, p.a};
      }
    }
  }
  const int top = pyramid.top();
  std::int64_t border_far = 0;
  const Mat3 tilts[] = {mat3_from_rows({0.5, 0.05, 4.0}, {-0.02, 0.45, 3.0}, {0.012, 0.003, 1.0}),
                        mat3_from_rows({0.3, -0.1, 20.0}, {0.1, 0.35, -6.0}, {-0.004, 0.02, 1.0}),
                        mat3_from_rows({1.2, 0.3, -5.0}, {-0.2, 1.1, 2.0}, {0.03, 0.01, 1.0}),
                        mat3_from_rows({8.0, 0.5, 0.0}, {0.0, 8.0, 0.0}, {0.01, 0.8, 1.0})};
  std::int64_t pixels = 0, blended = 0, at_top = 0, control_far = 0;
  int differing = 0;
  std::vector<int> levels_seen(static_cast<std::size_t>(top) + 1, 0);
  for (const Mat3& m : tilts) {
    const WarpOptions options{Sampling::kMipmap, WarpKernel::kPerspective, kDefaultHorizonEpsilon,
                              &pyramid};
    const WarpPlan plan =
        plan_warp(prepare_warp(source, m, options), Sampling::kMipmap, 120, 90, -6, -4);
    const MipLevelMaps levels = plan_level_maps(plan, source.image, pyramid, &pyramid);
    const MipLevelMaps clamped = plan_level_maps(plan, source.image, pyramid, nullptr);
    const MipLevelMaps spoilt = plan_level_maps(plan, source.image, pyramid, &spoiled);
    ScanConverter scan(plan.polygon, 120, 90);
    PixelSpan span;
    while (scan.next(span)) {
      const int count = span.x_end - span.x_begin;
      if (count <= 0) continue;
      std::vector<std::uint16_t> index(static_cast<std::size_t>(count) + 7, 0x0101);  // padding
      mip_row_levels(plan.dest_to_source, top, span.y, span.x_begin, span.x_end, index.data());
      const std::vector<Pixel> want = each_pixel_alone(levels, index.data(), span);
      for (int i = 0; i < count; ++i) {
        const int k = index[static_cast<std::size_t>(i)] >> 8;
        ++levels_seen[static_cast<std::size_t>(k)];
        blended += (index[static_cast<std::size_t>(i)] & 255) != 0;
        at_top += k == top;
      }
      // The whole span, then a random piece of it.
      const int a = std::uniform_int_distribution<int>(0, count - 1)(rng);
      const int b = std::uniform_int_distribution<int>(a + 1, count)(rng);
      for (const MipLevelMaps* maps : {&levels, &clamped}) {
        for (const auto& piece : {std::pair<int, int>{0, count}, std::pair<int, int>{a, b}}) {
          std::vector<Pixel> got(static_cast<std::size_t>(count), testing::kSentinel);
          ASSERT_TRUE(run_trilinear_levels_row(
              *maps, index.data() + piece.first, span.y, span.x_begin + piece.first,
              span.x_begin + piece.second, got.data() + piece.first));
          for (int i = piece.first; i < piece.second; ++i) {
            differing += got[static_cast<std::size_t>(i)] != want[static_cast<std::size_t>(i)];
            pixels += maps == &levels;  // each pixel counted once
          }
        }
      }
      std::vector<Pixel> from_spoilt(static_cast<std::size_t>(count));
      run_trilinear_levels_row(spoilt, index.data(), span.y, span.x_begin, span.x_end,
                               from_spoilt.data());
      for (int i = 0; i < count; ++i) {
        border_far += from_spoilt[static_cast<std::size_t>(i)] != want[static_cast<std::size_t>(i)];
      }
      std::vector<std::uint16_t> heavier = index;
      for (std::uint16_t& i : heavier) {
        if ((i & 255) != 0 && (i & 255) < 255) ++i;
      }
      std::vector<Pixel> shifted(static_cast<std::size_t>(count));
      run_trilinear_levels_row(levels, heavier.data(), span.y, span.x_begin, span.x_end,
                               shifted.data());
      for (int i = 0; i < count; ++i) {
        control_far += shifted[static_cast<std::size_t>(i)] != want[static_cast<std::size_t>(i)];
      }
    }
  }
  EXPECT_EQ(differing, 0) << "of " << pixels << " pixels";
  ASSERT_GT(pixels, 5000);
  int distinct = 0;
  for (int n : levels_seen) distinct += n > 0;
  EXPECT_GE(distinct, 4) << "lower levels crossed";
  EXPECT_GT(at_top, 0) << "pixels on the top level";
  EXPECT_GT(blended, pixels / 4);
  EXPECT_GT(control_far, blended / 20);
  EXPECT_GT(border_far, 0) << "pixels read from the borders";
}

// A pure 2x minification puts every output pixel centre on a level-1 pixel centre with
// footprint 2: level 1 exactly, in both kernels.
TEST(MipmapWarp, APure2xMinificationSamplesLevel1Exactly) {
  std::mt19937 rng(8);
  const Layer source = make_layer(testing::random_image(rng, 64, 48));
  MipPyramid pyramid;
  build_mip_pyramid(source.image, pyramid);
  for (WarpKernel kernel : {WarpKernel::kAffine, WarpKernel::kPerspective}) {
    Image output(32, 24, testing::kSentinel);
    WarpOptions options{Sampling::kMipmap, kernel, kDefaultHorizonEpsilon, &pyramid};
    const WarpStats stats = warp_layer_into(source, scaling(0.5, 0.5), output, 0, 0, options);
    EXPECT_EQ(stats.pixels_written, 32 * 24);
    int differing = 0;
    for (int y = 0; y < 24; ++y) {
      for (int x = 0; x < 32; ++x) differing += output.at(x, y) != pyramid.level(1).at(x, y);
    }
    EXPECT_EQ(differing, 0) << "kernel " << static_cast<int>(kernel);
    // The control: bilinear sampling of the same warp is not level 1 (it skips texels).
    Image bilinear(32, 24, testing::kSentinel);
    options.sampling = Sampling::kBilinear;
    warp_layer_into(source, scaling(0.5, 0.5), bilinear, 0, 0, options);
    int bilinear_differing = 0;
    for (int y = 0; y < 24; ++y) {
      for (int x = 0; x < 32; ++x)
        bilinear_differing += bilinear.at(x, y) != pyramid.level(1).at(x, y);
    }
    EXPECT_GT(bilinear_differing, 32 * 24 / 2);
  }
}

// An affine warp between two levels is the bilinear warps of those levels blended: a turn of
// 45 degrees that shrinks by 2^1.5 (level 1.5: levels 1 and 2, weight 128), whose matrices and
// their inverses are exact in binary, so that warping level k by M diag(2^k, 2^k) samples the
// positions the mipmap kernel samples. Every pixel is (a (256 - w) + b w + 128) / 256 of
// the two bilinear warps' a and b, inside a partial warp's wanted pixels too (the rest keep
// what the output held). The control: level 1 alone differs.
TEST(MipmapWarp, AnAffineWarpBetweenTwoLevelsBlendsTheBilinearWarpsOfBoth) {
  std::mt19937 rng(12);
  const Layer source = make_layer(testing::random_image(rng, 300, 260));
  MipPyramid pyramid;
  build_mip_pyramid(source.image, pyramid);
  const Mat3 m = translation_matrix(96.0, 17.5) *
                 mat3_from_rows({0.25, -0.25, 0.0}, {0.25, 0.25, 0.0}, {0.0, 0.0, 1.0});
  const int w = 200, h = 160, weight = 128;
  std::array<Image, 2> levels;
  for (int k = 1; k <= 2; ++k) {
    Image& level = levels[static_cast<std::size_t>(k - 1)];
    level = Image(w, h, testing::kSentinel);
    const double s = std::ldexp(1.0, k);
    warp_layer_into(make_layer(pyramid.level(k)), m * scaling(s, s), level, -3, 2,
                    {Sampling::kBilinear, WarpKernel::kAffine});
  }
  PixelRows only = PixelRows::full(w + 10, h + 10);
  only.remove_centres_inside(make_polygon_unchecked(
      {Vec2(20.0, 30.0), Vec2(150.0, 40.0), Vec2(120.0, 140.0), Vec2(30.0, 120.0)}));
  const PixelRows* const cases[] = {nullptr, &only};
  for (const PixelRows* wanted : cases) {
    Image mip(w, h, testing::kSentinel);
    WarpOptions options{Sampling::kMipmap, WarpKernel::kAffine, kDefaultHorizonEpsilon, &pyramid};
    options.only = wanted;
    const WarpStats stats = warp_layer_into(source, m, mip, -3, 2, options);
    int blended = 0, kept = 0, level_one = 0;
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        const Pixel a = levels[0].at(x, y), b = levels[1].at(x, y);
        ASSERT_EQ(a == testing::kSentinel, b == testing::kSentinel) << x << "," << y;
        if (a == testing::kSentinel || (wanted && !wanted->any(y + 2, x - 3, x - 2))) {
          kept += a != testing::kSentinel;
          ASSERT_EQ(mip.at(x, y), testing::kSentinel) << x << "," << y;
          continue;
        }
        const auto lerp = [&](int p, int q) {
          return (p * (256 - weight) + q * weight + 128) >> 8;
        };
        const Pixel expected{
            static_cast<std::uint8_t>(lerp(a.r, b.r)), static_cast<std::uint8_t>(lerp(a.g, b.g)),
            static_cast<std::uint8_t>(lerp(a.b, b.b)), static_cast<std::uint8_t>(lerp(a.a, b.a))};
        ASSERT_EQ(mip.at(x, y), expected) << x << "," << y;
        ++blended;
        level_one += mip.at(x, y) != a;
      }
    }
    EXPECT_EQ(blended, stats.pixels_computed);
    EXPECT_GT(blended, wanted ? 2000 : 9000);
    EXPECT_GT(level_one, blended / 2) << "the control: level 1 alone is not the blend";
    EXPECT_EQ(kept > 5000, wanted != nullptr);
  }
}

// Where a warp magnifies (or keeps the scale) everywhere, mipmap is the bilinear kernel, pixel
// for pixel: affine rotations and enlargements, and perspective warps that enlarge.
TEST(MipmapWarp, MagnificationIsBilinearExactly) {
  std::mt19937 rng(9);
  const Layer source = make_layer(testing::random_image(rng, 40, 30));
  const Mat3 perspective = mat3_from_rows({1.5, 0.2, 3.0}, {0.1, 1.4, 2.0}, {0.001, 0.002, 1.0});
  for (const Mat3& m :
       {rotation(0.4), translation_matrix(3.3, -2.1) * scaling(1.7, 1.2), perspective}) {
    for (WarpKernel kernel : {WarpKernel::kAutomatic, WarpKernel::kPerspective}) {
      Image mip(90, 80, testing::kSentinel), bilinear(90, 80, testing::kSentinel);
      warp_layer_into(source, m, mip, -20, -20, {Sampling::kMipmap, kernel});
      warp_layer_into(source, m, bilinear, -20, -20, {Sampling::kBilinear, kernel});
      EXPECT_EQ(mip.pixels(), bilinear.pixels());
    }
  }
}

// How a mipmap warp of `source` by m into a w x h output compares with mipmap_pixel, the
// exact per-pixel definition, over the warp's polygon: the worst channel difference, the
// pixels that differ and those where bilinear sampling of the same warp is more than 8 levels
// from the definition (the control), and the least and most exact level.
struct AgainstDefinition {
  std::int64_t pixels = 0, written = 0;
  int worst = 0, differing = 0, bilinear_far = 0;
  double least = 1e9, most = 0.0;
};

AgainstDefinition against_definition(const Layer& source, const MipPyramid& pyramid, const Mat3& m,
                                     WarpKernel kernel, int w, int h) {
  const WarpOptions options{Sampling::kMipmap, kernel, kDefaultHorizonEpsilon, &pyramid};
  Image output(w, h, testing::kSentinel), bilinear(w, h, testing::kSentinel);
  AgainstDefinition r;
  r.written = warp_layer_into(source, m, output, 0, 0, options).pixels_written;
  warp_layer_into(source, m, bilinear, 0, 0, {Sampling::kBilinear, kernel});
  const WarpPlan plan = plan_warp(prepare_warp(source, m, options), Sampling::kMipmap, w, h, 0, 0);
  const Mat3& hm = plan.dest_to_source;
  auto level_at = [&](double x, double y) {
    const Vec3 q = hm * Vec3(x, y, 1.0);
    const double su = q.x / q.z, sv = q.y / q.z;
    auto e = [&](int row, int c) { return entry(hm, row, c); };
    return mip_level((e(0, 0) - su * e(2, 0)) / q.z, (e(0, 1) - su * e(2, 1)) / q.z,
                     (e(1, 0) - sv * e(2, 0)) / q.z, (e(1, 1) - sv * e(2, 1)) / q.z, pyramid.top());
  };
  ScanConverter scan(plan.polygon, w, h);
  PixelSpan span;
  while (scan.next(span)) {
    for (int x = span.x_begin; x < span.x_end; ++x) {
      ++r.pixels;
      r.least = std::min(r.least, level_at(x + 0.5, span.y + 0.5));
      r.most = std::max(r.most, level_at(x + 0.5, span.y + 0.5));
      const Pixel want = mipmap_pixel(hm, source.image, pyramid, x, span.y);
      const int d = max_channel_difference(output.at(x, span.y), want);
      r.worst = std::max(r.worst, d);
      r.differing += d > 0;
      r.bilinear_far += max_channel_difference(bilinear.at(x, span.y), want) > 8;
    }
  }
  return r;
}

// The perspective kernel takes each pixel's level from a polynomial log2 and samples the
// levels with the fast bilinear row: within 2 levels per channel of mipmap_pixel, the exact
// per-pixel definition (mipmap_kernel.h states the bound), on a tilt whose footprint spans
// more than three levels across the output. The control: bilinear sampling of the same warp
// is far from it, so the comparison can fail.
TEST(MipmapWarp, PerspectiveKernelIsWithinTwoLevelsOfThePerPixelDefinition) {
  std::mt19937 rng(10);
  const Layer source = make_layer(testing::random_image(rng, 320, 240));
  MipPyramid pyramid;
  build_mip_pyramid(source.image, pyramid);
  const Mat3 m = mat3_from_rows({0.5, 0.05, 4.0}, {-0.02, 0.45, 3.0}, {0.006, 0.0015, 1.0});
  const AgainstDefinition r =
      against_definition(source, pyramid, m, WarpKernel::kPerspective, 96, 80);
  EXPECT_EQ(r.written, r.pixels);
  ASSERT_GT(r.pixels, 2000);
  EXPECT_GT(r.most - r.least, 3.0) << r.least << " .. " << r.most;  // a strong tilt
  EXPECT_LE(r.worst, 2) << r.differing << " of " << r.pixels << " pixels differ";
  EXPECT_GT(r.bilinear_far, r.pixels / 2);
}

// An affine warp between two levels (shrunk 2.5 times and turned by 20 degrees: levels 1 and
// 2, matrices not exact in binary, so the fast loops' stepped positions differ slightly from
// the exact ones) samples the bordered copies of both levels: every pixel of its polygon,
// those along its edges whose taps the copies' borders hold included, within 2 levels of
// mipmap_pixel, which clamps each tap to its level. The control: bilinear sampling is far.
TEST(MipmapWarp, AffineKernelIsWithinTwoLevelsOfThePerPixelDefinition) {
  std::mt19937 rng(14);
  const Layer source = make_layer(testing::random_image(rng, 320, 240));
  MipPyramid pyramid;
  build_mip_pyramid(source.image, pyramid);
  const double t = 20.0 * 3.14159265358979323846 / 180.0, s = 1.0 / 2.5;
  const Mat3 m = translation_matrix(70.0, 50.0) *
                 mat3_from_rows({s * std::cos(t), -s * std::sin(t), 0.0},
                                {s * std::sin(t), s * std::cos(t), 0.0}, {0.0, 0.0, 1.0}) *
                 translation_matrix(-160.0, -120.0);
  const AgainstDefinition r = against_definition(source, pyramid, m, WarpKernel::kAffine, 140, 100);
  EXPECT_EQ(r.written, r.pixels);
  ASSERT_GT(r.pixels, 2000);
  EXPECT_NEAR(r.least, std::log2(2.5), 1e-9);
  EXPECT_LE(r.worst, 2) << r.differing << " of " << r.pixels << " pixels differ";
  EXPECT_GT(r.bilinear_far, r.pixels / 2);
}

TEST(MipmapWarp, APyramidOfAnotherImageIsRefused) {
  const Layer source = make_layer(Image(16, 16, Pixel{9, 9, 9, 9}));
  MipPyramid pyramid;
  build_mip_pyramid(Image(8, 16), pyramid);
  Image output(8, 8);
  try {
    warp_layer_into(source, scaling(0.5, 0.5), output, 0, 0,
                    {Sampling::kMipmap, WarpKernel::kAutomatic, kDefaultHorizonEpsilon, &pyramid});
    FAIL() << "accepted a pyramid of an 8 x 16 image for a 16 x 16 source";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("8 x 16"), std::string::npos) << e.what();
  }
  EXPECT_EQ(output.at(0, 0), Pixel{});  // nothing written
}

// A stripe pattern minified 6x: bilinear aliases (it keeps single texels, so the mean shows
// in no pixel), mipmap gives the stripes' mean grey, as a 16-sample box filter does.
TEST(MipmapWarp, MinifiedStripesBecomeTheirMeanNotAnAlias) {
  Image stripes(192, 192);
  for (int y = 0; y < 192; ++y) {
    for (int x = 0; x < 192; ++x) {
      const std::uint8_t v = (x / 2) % 2 == 0 ? 255 : 0;
      stripes.at(x, y) = Pixel{v, v, v, 255};
    }
  }
  const Layer source = make_layer(stripes);
  const Mat3 m = scaling(1.0 / 6.0, 1.0 / 6.0);
  auto worst_distance_from_grey = [&](Sampling sampling) {
    Image out(32, 32);
    warp_layer_into(source, m, out, 0, 0, {sampling});
    int worst = 0;
    for (int y = 2; y < 30; ++y) {
      for (int x = 2; x < 30; ++x) worst = std::max(worst, std::abs(int(out.at(x, y).r) - 128));
    }
    return worst;
  };
  EXPECT_LE(worst_distance_from_grey(Sampling::kMipmap), 24);
  EXPECT_GE(worst_distance_from_grey(Sampling::kBilinear), 100);  // the control aliases
}

}  // namespace
}  // namespace oflab
