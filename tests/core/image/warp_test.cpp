// Warp kernels against the per-pixel reference (warp_reference.h), exact copies,
// chained warps, and hostile inputs.
#include "image/warp.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include "image/inverse_map.h"
#include "image/warp_kernels.h"
#include "image/warp_plan.h"
#include "warp_reference.h"

namespace oflab {
namespace {

using testing::kSentinel;
using testing::rotation_about;

struct RandomCase {
  Layer source;
  Mat3 matrix;
  int output_width = 0;
  int output_height = 0;
  int origin_x = 0;
  int origin_y = 0;
};

// A random layer, a random warp that puts it roughly over a random output (sometimes
// partly outside it), and, when `perspective` is set, a perspective row strong enough that
// the polygon sometimes crosses the horizon line.
RandomCase random_case(std::mt19937& rng, bool perspective) {
  std::uniform_int_distribution<int> size(1, 48);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  RandomCase c;
  const int w = size(rng);
  const int h = size(rng);
  c.source = make_layer(testing::random_image(rng, w, h), testing::random_polygon(rng, w, h));
  c.output_width = std::uniform_int_distribution<int>(1, 64)(rng);
  c.output_height = std::uniform_int_distribution<int>(1, 64)(rng);
  c.origin_x = std::uniform_int_distribution<int>(-20, 20)(rng);
  c.origin_y = std::uniform_int_distribution<int>(-20, 20)(rng);
  const double angle = 3.14159265358979323846 * unit(rng);
  const double sx = std::exp(1.1 * unit(rng));
  const double sy = sx * std::exp(0.3 * unit(rng));
  const double shear = 0.3 * unit(rng);
  const Mat3 linear = mat3_from_rows({std::cos(angle), -std::sin(angle), 0.0},
                                     {std::sin(angle), std::cos(angle), 0.0}, {0.0, 0.0, 1.0}) *
                      mat3_from_rows({sx, shear, 0.0}, {0.0, sy, 0.0}, {0.0, 0.0, 1.0});
  Mat3 projective(1.0);
  if (perspective) {
    const double strength = 1.5 * (0.5 + 0.5 * unit(rng));
    entry(projective, 2, 0) = strength * unit(rng) / w;
    entry(projective, 2, 1) = strength * unit(rng) / h;
  }
  const Vec2 centre(c.origin_x + c.output_width * (0.5 + 0.4 * unit(rng)),
                    c.origin_y + c.output_height * (0.5 + 0.4 * unit(rng)));
  c.matrix = translation_matrix(centre.x, centre.y) * linear * projective *
             translation_matrix(-0.5 * w, -0.5 * h);
  // The overall scale of a homography is irrelevant; vary it to exercise normalisation.
  c.matrix *= std::exp(3.0 * unit(rng));
  return c;
}

// Runs the kernel selected by `options` and compares every output pixel with the
// reference; returns the number of mismatches.
int compare_with_reference(const RandomCase& c, const WarpOptions& options, int tolerance,
                           std::string* report) {
  Image output(c.output_width, c.output_height, kSentinel);
  const WarpStats stats =
      warp_layer_into(c.source, c.matrix, output, c.origin_x, c.origin_y, options);
  const PreparedWarp prepared = prepare_warp(c.source, c.matrix, options);
  const WarpPlan plan = plan_warp(prepared, options.sampling, c.output_width, c.output_height,
                                  c.origin_x, c.origin_y);
  const auto reference = testing::reference_warp(plan, c.source.image);
  int mismatches = testing::count_mismatches(reference, output, kSentinel, tolerance, report);
  std::int64_t touched = 0;
  for (const Pixel& p : output.pixels()) touched += p != kSentinel;
  if (touched != stats.pixels_written) {
    ++mismatches;
    *report += "pixels_written " + std::to_string(stats.pixels_written) + " but " +
               std::to_string(touched) + " pixels changed\n";
  }
  return mismatches;
}

void check_random_cases(unsigned seed, bool perspective, WarpOptions options, int tolerance) {
  std::mt19937 rng(seed);
  int non_empty = 0;
  for (int k = 0; k < 400; ++k) {
    const RandomCase c = random_case(rng, perspective);
    std::string report;
    const int mismatches = compare_with_reference(c, options, tolerance, &report);
    ASSERT_EQ(mismatches, 0) << "case " << k << " (source " << c.source.image.width() << "x"
                             << c.source.image.height() << ")\n"
                             << report;
    Image probe(c.output_width, c.output_height, kSentinel);
    non_empty +=
        warp_layer_into(c.source, c.matrix, probe, c.origin_x, c.origin_y, options).pixels_written >
        0;
  }
  // Most random cases must actually draw something, or the comparison proves little.
  EXPECT_GT(non_empty, 250);
}

TEST(Sampling, NamesRoundTripAndUnknownWordsAreRejected) {
  for (int i = 0; i < kSamplingCount; ++i) {
    Sampling parsed = Sampling((i + 1) % kSamplingCount);
    ASSERT_TRUE(parse_sampling(sampling_name(Sampling(i)), &parsed));
    EXPECT_EQ(parsed, Sampling(i));
  }
  EXPECT_STREQ(sampling_name(Sampling::kNearest), "nearest");
  EXPECT_STREQ(sampling_name(Sampling::kBilinear), "bilinear");
  EXPECT_STREQ(sampling_name(Sampling::kMipmap), "mipmap");
  EXPECT_EQ(sampling_name_list(), "nearest, bilinear, mipmap");
  EXPECT_EQ(sampling_name_list("|"), "nearest|bilinear|mipmap");
  Sampling untouched = Sampling::kBilinear;
  EXPECT_FALSE(parse_sampling("Nearest", &untouched));
  EXPECT_FALSE(parse_sampling("", &untouched));
  EXPECT_EQ(untouched, Sampling::kBilinear);
}

TEST(WarpKernels, NearestAffineKernelMatchesReferenceOnRandomMatrices) {
  check_random_cases(11, false, {Sampling::kNearest, WarpKernel::kAffine}, 0);
}

TEST(WarpKernels, NearestPerspectiveKernelMatchesReferenceOnRandomHomographies) {
  check_random_cases(12, true, {Sampling::kNearest, WarpKernel::kPerspective}, 0);
}

// Mipmap against the reference's own double pyramid and brute-force footprint: the kernel's
// levels are rounded once per level (k / 2 levels at worst after k reductions, far less on
// average as the roundings mix), its blend weight to 1/256 and its bilinear taps within one
// level: within 2 levels on these 400 cases each.
TEST(WarpKernels, MipmapAffineKernelMatchesReferenceOnRandomMatrices) {
  check_random_cases(41, false, {Sampling::kMipmap, WarpKernel::kAffine}, 2);
}

TEST(WarpKernels, MipmapPerspectiveKernelMatchesReferenceOnRandomHomographies) {
  check_random_cases(42, true, {Sampling::kMipmap, WarpKernel::kPerspective}, 2);
}

TEST(WarpKernels, NearestPerspectiveKernelMatchesReferenceOnAffineMatrices) {
  check_random_cases(13, false, {Sampling::kNearest, WarpKernel::kPerspective}, 0);
}

TEST(WarpKernels, BilinearAffineKernelIsWithinOneLevelOfReference) {
  check_random_cases(14, false, {Sampling::kBilinear, WarpKernel::kAffine}, 1);
}

TEST(WarpKernels, BilinearPerspectiveKernelIsWithinOneLevelOfReference) {
  check_random_cases(15, true, {Sampling::kBilinear, WarpKernel::kPerspective}, 1);
}

TEST(WarpKernels, KernelsMatchReferenceOnLargeImagesWithLongSpans) {
  std::mt19937 rng(16);
  const Layer source = make_layer(testing::random_image(rng, 700, 500));
  const Mat3 tilt = rotation_about(17.0, 350.0, 250.0) *
                    mat3_from_rows({1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {2e-4, -4e-4, 1.0});
  for (const Mat3& m : {rotation_about(31.0, 350.0, 250.0), tilt}) {
    for (Sampling sampling : {Sampling::kNearest, Sampling::kBilinear}) {
      RandomCase c{source, m, 720, 560, -10, -30};
      std::string report;
      EXPECT_EQ(compare_with_reference(c, {sampling, WarpKernel::kAutomatic},
                                       sampling == Sampling::kBilinear ? 1 : 0, &report),
                0)
          << report;
    }
  }
}

// Sampling positions that are exact integers are the ties where a quotient computed
// through a reciprocal, (N / D) * (1 - 2^-53), could fall just below the integer. The
// maps that make_inverse_map builds for affine matrices have a power-of-two D (exact
// reciprocals), so this test builds maps by hand: a 2x minification, u = X = 2x + 1 and
// v = Y, with D = 2K for many odd K that are not powers of two. Every pixel is a tie,
// and the perspective kernel must still take the exact floor.
TEST(WarpKernels, NearestPerspectiveKernelIsExactOnIntegerSamplingPositions) {
  std::mt19937 rng(21);
  const int width = 40;
  const int height = 30;
  const Image source = testing::random_image(rng, 2 * width + 2, 2 * height + 2);
  for (std::int64_t k = 3; k < 1200; k += 2) {
    for (int power : {0, 13, 26}) {
      const std::int64_t K = k << power;
      WarpPlan plan;
      plan.empty = false;
      plan.affine_kernel = false;
      plan.sampling = Sampling::kNearest;
      plan.output_width = width;
      plan.output_height = height;
      plan.polygon = ConvexPolygon::rectangle(0.0, 0.0, width, height);
      plan.map.a = 2 * K;  // Nu = 2K X, D = 2K: u = X
      plan.map.e = 2 * K;
      plan.map.i = 2 * K;
      Image output(width, height, kSentinel);
      ASSERT_EQ(run_warp_kernel(plan, source, output), std::int64_t{width} * height);
      std::string report;
      ASSERT_EQ(testing::count_mismatches(testing::reference_warp(plan, source), output, kSentinel,
                                          0, &report),
                0)
          << "D = " << 2 * K << "\n"
          << report;
    }
  }
}

// Far from the source origin (a source wider than 2^13 pixels, with the map's
// denominator near its 2^37 ceiling) the numerators pass 2^50, where the perspective
// kernel switches from reciprocals to one division per pixel to keep the floors exact.
TEST(WarpKernels, NearestPerspectiveKernelIsExactWithNumeratorsBeyondTwoToTheFifty) {
  std::mt19937 rng(22);
  const int width = 12000;
  const Layer source = make_layer(testing::random_image(rng, width, 6));
  const Mat3 m = mat3_from_rows({1.0, 0.01, 0.0}, {0.0, 1.0, 0.0}, {1e-7, 0.0, 1.0});
  RandomCase c{source, m, width, 6, 0, 0};
  const WarpOptions options{Sampling::kNearest, WarpKernel::kPerspective};
  const PreparedWarp prepared = prepare_warp(c.source, c.matrix, options);
  const WarpPlan plan = plan_warp(prepared, options.sampling, width, 6, 0, 0);
  ASSERT_FALSE(plan.empty);
  const MapSample far = evaluate(plan.map, width - 100, 3);
  const MapSample near = evaluate(plan.map, 100, 3);
  ASSERT_GT(static_cast<double>(far.nu), 1125899906842624.0);   // 2^50: the division path
  ASSERT_LT(static_cast<double>(near.nu), 1125899906842624.0);  // the reciprocal path
  std::string report;
  EXPECT_EQ(compare_with_reference(c, options, 0, &report), 0) << report;
}

// The integer map of inverse_map.h is only a definition if it is close to the true
// inverse: compare its sampling positions with apply_homography(M^-1, centre) in double.
TEST(WarpKernels, InverseMapIsWithinAMicropixelOfTheExactInverse) {
  std::mt19937 rng(17);
  double worst = 0.0;
  for (int k = 0; k < 200; ++k) {
    const RandomCase c = random_case(rng, k % 2 == 1);
    for (Sampling sampling : {Sampling::kNearest, Sampling::kBilinear}) {
      const WarpOptions options{sampling, WarpKernel::kAutomatic};
      const PreparedWarp prepared = prepare_warp(c.source, c.matrix, options);
      const WarpPlan plan =
          plan_warp(prepared, sampling, c.output_width, c.output_height, c.origin_x, c.origin_y);
      if (plan.empty) continue;
      const Mat3 inverse = glm::inverse(c.matrix);
      const double shift = sampling == Sampling::kBilinear ? 0.5 : 0.0;
      for (int y = 0; y < c.output_height; ++y) {
        for (int x = 0; x < c.output_width; ++x) {
          const Vec2 centre(x + 0.5, y + 0.5);
          if (!contains(plan.polygon, centre)) continue;
          const Vec2 dest = centre + Vec2(c.origin_x, c.origin_y);
          const Vec2 exact = apply_homography(inverse, dest) - Vec2(shift);
          const MapSample s = evaluate(plan.map, x, y);
          const Vec2 fixed(static_cast<double>(s.nu) / s.d, static_cast<double>(s.nv) / s.d);
          worst = std::max(worst, glm::length(fixed - exact));
        }
      }
    }
  }
  EXPECT_LT(worst, 1e-6);
}

// Away from exact ties, nearest sampling must agree with the plain double-precision
// definition floor(M^-1(centre)) (an independent check of the integer map's floors).
TEST(WarpKernels, NearestKernelAgreesWithDoubleInverseAwayFromTies) {
  std::mt19937 rng(18);
  int compared = 0;
  for (int k = 0; k < 200; ++k) {
    const RandomCase c = random_case(rng, k % 2 == 1);
    Image output(c.output_width, c.output_height, kSentinel);
    warp_layer_into(c.source, c.matrix, output, c.origin_x, c.origin_y);
    const Mat3 inverse = glm::inverse(c.matrix);
    const Image& src = c.source.image;
    for (int y = 0; y < c.output_height; ++y) {
      for (int x = 0; x < c.output_width; ++x) {
        if (output.at(x, y) == kSentinel) continue;
        const Vec2 s = apply_homography(inverse, Vec2(c.origin_x + x + 0.5, c.origin_y + y + 0.5));
        const Vec2 nearest_integer(std::round(s.x), std::round(s.y));
        if (glm::length(s - nearest_integer) < 1e-6 * (1.0 + glm::length(s))) continue;
        const int u = std::clamp(static_cast<int>(std::floor(s.x)), 0, src.width() - 1);
        const int v = std::clamp(static_cast<int>(std::floor(s.y)), 0, src.height() - 1);
        ASSERT_EQ(output.at(x, y), src.at(u, v)) << "case " << k << " pixel " << x << "," << y;
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 30000);
}

TEST(WarpKernels, IdentityWarpIsAnExactCopy) {
  std::mt19937 rng(19);
  const Image image = testing::random_image(rng, 97, 61);
  const Layer layer = make_layer(image);
  for (WarpKernel kernel : {WarpKernel::kAffine, WarpKernel::kPerspective}) {
    for (Sampling sampling : {Sampling::kNearest, Sampling::kBilinear}) {
      Image output(97, 61, kSentinel);
      const WarpStats stats = warp_layer_into(layer, Mat3(1.0), output, 0, 0, {sampling, kernel});
      EXPECT_EQ(stats.pixels_written, 97 * 61);
      EXPECT_TRUE(output.pixels() == image.pixels());
      const WarpedLayer warped = warp_layer(layer, Mat3(2.5), {sampling, kernel});
      EXPECT_EQ(warped.offset_x, 0);
      EXPECT_EQ(warped.offset_y, 0);
      EXPECT_TRUE(warped.layer.image.pixels() == image.pixels());
    }
  }
}

TEST(WarpKernels, IntegerTranslationIsAnExactShift) {
  std::mt19937 rng(20);
  const Layer layer = make_layer(testing::random_image(rng, 40, 30));
  for (Sampling sampling : {Sampling::kNearest, Sampling::kBilinear}) {
    const WarpedLayer warped = warp_layer(layer, translation_matrix(-7.0, 12.0), {sampling});
    EXPECT_EQ(warped.offset_x, -7);
    EXPECT_EQ(warped.offset_y, 12);
    EXPECT_TRUE(warped.layer.image.pixels() == layer.image.pixels());
  }
}

TEST(WarpKernels, AutomaticChoiceUsesAffineKernelOnlyForAffineMatrices) {
  const Layer layer = make_layer(Image(8, 8, Pixel{1, 2, 3, 255}));
  Image output(16, 16);
  const Mat3 scaled_affine = mat3_from_rows({2.0, 0.2, 1.0}, {0.1, 2.0, 0.0}, {0.0, 0.0, 2.0});
  EXPECT_EQ(warp_layer_into(layer, scaled_affine, output, 0, 0).kernel_used, WarpKernel::kAffine);
  const Mat3 negated = -scaled_affine;  // same map
  EXPECT_EQ(warp_layer_into(layer, negated, output, 0, 0).kernel_used, WarpKernel::kAffine);
  EXPECT_EQ(warp_layer_into(layer, negated, output, 0, 0).pixels_written, 64);
  Mat3 projective = scaled_affine;
  entry(projective, 2, 0) = 1e-3;
  EXPECT_EQ(warp_layer_into(layer, projective, output, 0, 0).kernel_used, WarpKernel::kPerspective);
  EXPECT_THROW(warp_affine_into(layer, projective, output, 0, 0, Sampling::kNearest),
               std::invalid_argument);
}

// Fig. 28: the polygon carried through a chain of warps is the image of the original
// polygon under the product of the matrices, so no empty space builds up.
TEST(WarpKernels, ChainOfWarpsAndTheirProductGiveTheSamePolygon) {
  std::mt19937 rng(21);
  for (int trial = 0; trial < 20; ++trial) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    Layer layer =
        make_layer(testing::random_image(rng, 60, 40), testing::random_polygon(rng, 60, 40));
    const ConvexPolygon original = layer.polygon;
    Mat3 product(1.0);
    Vec2 offset(0.0);
    for (int step = 0; step < 4; ++step) {
      Mat3 m = rotation_about(25.0 * unit(rng), 30.0, 20.0) *
               mat3_from_rows({1.0 + 0.2 * unit(rng), 0.1 * unit(rng), 5.0 * unit(rng)},
                              {0.1 * unit(rng), 1.0 + 0.2 * unit(rng), 5.0 * unit(rng)},
                              {1e-3 * unit(rng), 1e-3 * unit(rng), 1.0});
      // m acts in the caller's frame; the layer's own pixels sit at `offset` in it.
      const WarpedLayer next = warp_layer(layer, m * translation_matrix(offset.x, offset.y));
      product = m * product;
      layer = next.layer;
      offset = Vec2(next.offset_x, next.offset_y);
    }
    const ConvexPolygon chained = translated(layer.polygon, offset.x, offset.y);
    const ConvexPolygon direct = transform(original, product);
    ASSERT_EQ(chained.size(), direct.size());
    // Same cyclic order; find the matching start vertex.
    std::size_t start = 0;
    for (std::size_t k = 0; k < direct.size(); ++k) {
      if (glm::length(direct.vertices()[k] - chained.vertices()[0]) <
          glm::length(direct.vertices()[start] - chained.vertices()[0])) {
        start = k;
      }
    }
    for (std::size_t k = 0; k < direct.size(); ++k) {
      EXPECT_NEAR(
          glm::length(chained.vertices()[k] - direct.vertices()[(start + k) % direct.size()]), 0.0,
          1e-9);
    }
    EXPECT_NEAR(chained.area(), direct.area(), 1e-9 * direct.area());
  }
}

TEST(WarpKernels, NewLayerIsTransparentOutsideItsPolygonAndCoversIt) {
  std::mt19937 rng(22);
  const Layer layer = make_layer(Image(50, 50, Pixel{10, 20, 30, 255}));
  const WarpedLayer warped = warp_layer(layer, rotation_about(45.0, 25.0, 25.0));
  const Image& image = warped.layer.image;
  // The rotated square spans 25 -+ 25 * sqrt(2) = [-10.36, 60.36] on both axes.
  EXPECT_EQ(warped.offset_x, -11);
  EXPECT_EQ(image.width(), 72);
  EXPECT_EQ(image.height(), 72);
  int opaque = 0;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      const bool inside = contains(warped.layer.polygon, Vec2(x + 0.5, y + 0.5));
      const Pixel p = image.at(x, y);
      if (p.a == 255) ++opaque;
      if (!inside) {
        EXPECT_EQ(p, Pixel{}) << x << "," << y;
      }
    }
  }
  EXPECT_EQ(opaque, warped.stats.pixels_written);
  EXPECT_NEAR(opaque, 2500.0, 100.0);
}

// warp_layer_reusing against a fresh warp_layer of the same case (the reference: a new,
// zero-filled layer), over a chain of warps into one result whose layers grow, shrink,
// change shape, move and sometimes vanish, with either sampling.
TEST(WarpKernels, ReusingWarpEqualsAFreshWarpPixelForPixel) {
  std::mt19937 rng(41);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (Sampling sampling : {Sampling::kNearest, Sampling::kBilinear}) {
    WarpedLayer reused;
    for (int step = 0; step < 200; ++step) {
      const Layer source =
          make_layer(testing::random_image(rng, 40, 30), testing::random_polygon(rng, 40, 30));
      const double scale = std::exp(0.8 * unit(rng));
      Mat3 m = rotation_about(180.0 * unit(rng), 20.0, 15.0) *
               mat3_from_rows({scale, 0.2 * unit(rng), 30.0 * unit(rng)},
                              {0.0, scale, 30.0 * unit(rng)}, {0.0, 0.0, 1.0});
      if (step % 3 == 0)
        m = mat3_from_rows({1, 0, 0}, {0, 1, 0}, {0.004 * unit(rng), 0.004 * unit(rng), 1}) * m;
      if (step % 17 == 0) m = translation_matrix(1e4, 0.0) * m;  // may leave nothing visible
      const WarpedLayer fresh = warp_layer(source, m, {sampling});
      warp_layer_reusing(source, m, reused, {sampling});
      ASSERT_EQ(reused.offset_x, fresh.offset_x) << step;
      ASSERT_EQ(reused.offset_y, fresh.offset_y) << step;
      ASSERT_EQ(reused.stats.pixels_written, fresh.stats.pixels_written) << step;
      ASSERT_EQ(reused.layer.image.width(), fresh.layer.image.width()) << step;
      ASSERT_EQ(reused.layer.image.height(), fresh.layer.image.height()) << step;
      ASSERT_TRUE(reused.layer.image.pixels() == fresh.layer.image.pixels()) << "step " << step;
      ASSERT_EQ(reused.layer.polygon.vertices(), fresh.layer.polygon.vertices()) << step;
    }
  }
}

TEST(WarpKernels, ReusingWarpKeepsTheMemoryWhenTheLayerDoesNotGrow) {
  const Layer layer = make_layer(Image(50, 50, Pixel{10, 20, 30, 255}));
  WarpedLayer reused;
  warp_layer_reusing(layer, rotation_about(45.0, 25.0, 25.0), reused);
  const Pixel* memory = reused.layer.image.pixels().data();
  for (double degrees : {40.0, 10.0, 0.0, 30.0, 45.0}) {
    warp_layer_reusing(layer, rotation_about(degrees, 25.0, 25.0), reused);
    EXPECT_EQ(reused.layer.image.pixels().data(), memory) << degrees;
  }
}

TEST(WarpKernels, RefusedReusingWarpLeavesTheResultAsItWas) {
  const Layer layer = make_layer(Image(20, 20, Pixel{1, 2, 3, 255}));
  WarpedLayer reused;
  warp_layer_reusing(layer, translation_matrix(3.0, 4.0), reused);
  const WarpedLayer before = reused;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(warp_layer_reusing(layer, translation_matrix(nan, 0.0), reused),
               std::invalid_argument);
  EXPECT_TRUE(reused.layer.image.pixels() == before.layer.image.pixels());
  EXPECT_EQ(reused.offset_x, before.offset_x);
  EXPECT_EQ(reused.layer.polygon.vertices(), before.layer.polygon.vertices());
}

TEST(WarpKernels, ZeroSizeImagesGiveEmptyResults) {
  const Layer empty = make_layer(Image());
  Image output(10, 10, kSentinel);
  EXPECT_EQ(warp_layer_into(empty, Mat3(1.0), output, 0, 0).pixels_written, 0);
  EXPECT_TRUE(warp_layer(empty, Mat3(1.0)).layer.empty());
  const Layer layer = make_layer(Image(5, 5, Pixel{1, 1, 1, 1}));
  Image nothing;
  EXPECT_EQ(warp_layer_into(layer, Mat3(1.0), nothing, 0, 0).pixels_written, 0);
  const Layer thin = make_layer(Image(5, 0));
  EXPECT_TRUE(warp_layer(thin, Mat3(1.0)).layer.empty());
  for (const Pixel& p : output.pixels()) EXPECT_EQ(p, kSentinel);
}

TEST(WarpKernels, NonFiniteMatricesAreRejected) {
  const Layer layer = make_layer(Image(5, 5));
  Image output(10, 10);
  for (double bad :
       {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) {
        Mat3 m(1.0);
        entry(m, r, c) = bad;
        EXPECT_THROW(warp_layer_into(layer, m, output, 0, 0), std::invalid_argument);
        EXPECT_THROW(warp_layer(layer, m), std::invalid_argument);
      }
    }
  }
}

TEST(WarpKernels, SingularMatricesAreRejected) {
  const Layer layer = make_layer(Image(5, 5));
  Image output(10, 10);
  const Mat3 rank_two = mat3_from_rows({1.0, 2.0, 3.0}, {2.0, 4.0, 6.0}, {0.0, 0.0, 1.0});
  for (const Mat3& m :
       {Mat3(0.0), rank_two, mat3_from_rows({1.0, 0.0, 0.0}, {0.0, 1e-14, 0.0}, {0.0, 0.0, 1.0})}) {
    EXPECT_THROW(warp_layer_into(layer, m, output, 0, 0), std::invalid_argument);
  }
  try {
    warp_layer(layer, rank_two);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("singular"), std::string::npos);
  }
}

TEST(WarpKernels, HugeMagnificationIntoAFrameIsClippedAndMatchesReference) {
  std::mt19937 rng(23);
  const Layer layer = make_layer(testing::random_image(rng, 4, 3));
  const Mat3 m = mat3_from_rows({1e5, 0.0, -1.5e5}, {0.0, 1e5, -1.2e5}, {0.0, 0.0, 1.0});
  RandomCase c{layer, m, 50, 40, 0, 0};
  std::string report;
  EXPECT_EQ(compare_with_reference(c, {}, 0, &report), 0) << report;
  Image output(50, 40, kSentinel);
  EXPECT_EQ(warp_layer_into(layer, m, output, 0, 0).pixels_written, 50 * 40);
  EXPECT_THROW(warp_layer(layer, m), std::invalid_argument);
}

TEST(WarpKernels, ExtremeMinificationGivesAtMostOnePixelOrAClearError) {
  std::mt19937 rng(24);
  const Layer layer = make_layer(testing::random_image(rng, 300, 200));
  for (double scale : {1e-3, 1e-6, 1e-9, 1e-12}) {
    const Mat3 m = mat3_from_rows({scale, 0.0, 10.3}, {0.0, scale, 7.6}, {0.0, 0.0, 1.0});
    try {
      const WarpedLayer warped = warp_layer(layer, m);
      EXPECT_LE(warped.stats.pixels_written, 1);
      RandomCase c{layer, m, 20, 20, 0, 0};
      std::string report;
      EXPECT_EQ(compare_with_reference(c, {}, 0, &report), 0) << report;
    } catch (const std::invalid_argument& e) {
      EXPECT_LT(scale, 1e-8) << e.what();  // only beyond the documented range
    }
  }
}

TEST(WarpKernels, PolygonCrossingTheHorizonIsClippedAndStaysBounded) {
  std::mt19937 rng(25);
  const Layer layer = make_layer(testing::random_image(rng, 100, 80));
  // Denominator 1 - 0.015 x: zero at x = 66.7, negative beyond.
  const Mat3 m = mat3_from_rows({1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {-0.015, 0.0, 1.0});
  const PreparedWarp prepared = prepare_warp(layer, m, {});
  ASSERT_FALSE(prepared.warped_polygon.empty());
  const BoundingBox box = prepared.warped_polygon.bounds();
  EXPECT_LT(box.x_max, 1e6);
  for (WarpKernel kernel : {WarpKernel::kAutomatic, WarpKernel::kPerspective}) {
    for (Sampling sampling : {Sampling::kNearest, Sampling::kBilinear}) {
      RandomCase c{layer, m, 300, 200, -50, -50};
      std::string report;
      EXPECT_EQ(compare_with_reference(c, {sampling, kernel},
                                       sampling == Sampling::kBilinear ? 1 : 0, &report),
                0)
          << report;
    }
  }
  // Into a new layer: the far part maps too far away for a layer of bounded size.
  EXPECT_THROW(warp_layer(layer, m), std::invalid_argument);
  const WarpedLayer near_part =
      warp_layer(layer, m, {Sampling::kNearest, WarpKernel::kAutomatic, 0.3});
  EXPECT_GT(near_part.stats.pixels_written, 0);
}

TEST(WarpKernels, PolygonWhollyBehindTheHorizonGivesEmptyResult) {
  const Layer layer = make_layer(Image(10, 10, Pixel{5, 5, 5, 5}));
  const Mat3 m = mat3_from_rows({1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, -1.0}) *
                 mat3_from_rows({1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.01, 0.0, 1.0});
  Image output(20, 20, kSentinel);
  EXPECT_EQ(warp_layer_into(layer, m, output, 0, 0).pixels_written, 0);
  EXPECT_TRUE(warp_layer(layer, m).layer.empty());
  for (const Pixel& p : output.pixels()) EXPECT_EQ(p, kSentinel);
}

TEST(WarpKernels, PolygonOutsideTheOutputWritesNothing) {
  const Layer layer = make_layer(Image(10, 10, Pixel{5, 5, 5, 5}));
  Image output(20, 20, kSentinel);
  for (const Vec2& shift :
       {Vec2(-30.0, 0.0), Vec2(25.0, 3.0), Vec2(0.0, 1e9), Vec2(-1e15, -1e15)}) {
    EXPECT_EQ(
        warp_layer_into(layer, translation_matrix(shift.x, shift.y), output, 0, 0).pixels_written,
        0);
  }
  EXPECT_EQ(warp_layer_into(layer, Mat3(1.0), output, 1000000000, -1000000000).pixels_written, 0);
  for (const Pixel& p : output.pixels()) EXPECT_EQ(p, kSentinel);
}

TEST(WarpKernels, HorizonEpsilonOutsideItsRangeIsRejected) {
  const Layer layer = make_layer(Image(4, 4));
  Image output(4, 4);
  for (double eps : {0.0, 1e-9, 0.9, std::numeric_limits<double>::quiet_NaN()}) {
    EXPECT_THROW(warp_layer_into(layer, Mat3(1.0), output, 0, 0,
                                 {Sampling::kNearest, WarpKernel::kAutomatic, eps}),
                 std::invalid_argument);
  }
}

}  // namespace
}  // namespace oflab
