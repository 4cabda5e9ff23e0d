// The level bias and the blend of the mipmap kernel (MipBlend, core/image/mip_pyramid.h):
// which levels a pixel samples, against the bilinear warp of the level itself, and what the
// default blend over the middle half of each octave loses against the trilinear blend,
// against a supersampled picture.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>

#include "image/mip_pyramid.h"
#include "image/warp.h"
#include "warp_reference.h"

namespace oflab {
namespace {

Mat3 scaling(double sx, double sy) {
  return mat3_from_rows({sx, 0.0, 0.0}, {0.0, sy, 0.0}, {0.0, 0.0, 1.0});
}

// The index a pixel samples: the bias of 1/4 level, then for the middle-half blend the weight
// 2 frac - 1/2 clamped to [0, 1], in 1/256, against that formula in double for every index
// of the first levels; a weight of 1 is the next level alone.
TEST(MipSampledIndex, IsTheBiasedLevelWithTheMiddleHalfWeight) {
  for (int index = 0; index < 256 * 6; ++index) {
    const double level = std::max(index / 256.0 - 0.25, 0.0);
    EXPECT_EQ(mip_sampled_index(index, MipBlend::kTrilinear), std::lround(256.0 * level));
    const double lower = std::floor(level);
    const double weight = std::clamp(2.0 * (level - lower) - 0.5, 0.0, 1.0);
    EXPECT_EQ(mip_sampled_index(index, MipBlend::kMiddleHalf),
              std::lround(256.0 * (lower + weight)))
        << index;
  }
}

// The blend over the middle half of each octave (MipBlend::kMiddleHalf): a pure shrink by
// 2^-F whose sampled level L = F - 1/4 (the bias) has a fraction under 1/4 (F = 1.3: L = 1.05)
// or over 3/4 (F = 2.1: L = 1.85) samples one level alone, the bilinear warp of level 1 or 2
// (both kernels; a diagonal matrix scaled by powers of two is exact in binary, so the
// level's warp samples the kernel's positions); at F = 1.75 (L = 1.5) it blends both with
// weight 1/2 as the trilinear blend does. The control: the trilinear blend of F = 1.3 and
// 2.1 is not a level alone.
TEST(MipmapWarp, TheMiddleHalfBlendSamplesOneLevelInTheOuterQuartersOfAnOctave) {
  std::mt19937 rng(15);
  const Layer source = make_layer(testing::random_image(rng, 256, 192));
  MipPyramid pyramid;
  build_mip_pyramid(source.image, pyramid);
  const int w = 80, h = 60;
  for (WarpKernel kernel : {WarpKernel::kAffine, WarpKernel::kPerspective}) {
    for (const auto& [level, alone] : {std::pair{1.3, 1}, std::pair{2.1, 2}, std::pair{1.75, 0}}) {
      const double s = std::exp2(-level);
      Image middle(w, h, testing::kSentinel), trilinear(w, h, testing::kSentinel);
      WarpOptions options{Sampling::kMipmap, kernel, kDefaultHorizonEpsilon, &pyramid};
      warp_layer_into(source, scaling(s, s), middle, 0, 0, options);
      options.mip_blend = MipBlend::kTrilinear;
      warp_layer_into(source, scaling(s, s), trilinear, 0, 0, options);
      if (alone == 0) {
        EXPECT_EQ(middle.pixels(), trilinear.pixels()) << "F = " << level;
        continue;
      }
      const double k = std::ldexp(1.0, alone);
      Image single(w, h, testing::kSentinel);
      warp_layer_into(make_layer(pyramid.level(alone)), scaling(s * k, s * k), single, 0, 0,
                      {Sampling::kBilinear, kernel});
      EXPECT_EQ(middle.pixels(), single.pixels()) << "F = " << level;
      EXPECT_NE(trilinear.pixels(), single.pixels()) << "F = " << level;
    }
  }
}

// What the narrower blend costs in quality: a 640 x 480 texture of random opaque texels (white
// noise: all of its energy at the frequencies a level too fine aliases and a level too coarse
// blurs, the worst case for sampling one level where the trilinear blend takes two), tilted
// away (levels about 0.7 to 3 across the output), sampled by each blend and by bilinear, each
// against the supersampled picture (the bilinear warp at 4 x 4 the output's pixels,
// box-reduced: 16 samples per pixel). Blending over the middle half of each octave stays
// within 1 dB of the trilinear blend (26.7 against 27.4 dB today) and far above bilinear
// (19.0 dB); the control is the gap to bilinear, and the two blends differ.
TEST(MipmapWarp, TheMiddleHalfBlendLosesUnderADecibelOnNoise) {
  std::mt19937 rng(16);
  Image texels = testing::random_image(rng, 640, 480);
  for (Pixel& p : texels.pixels()) p.a = 255;  // opaque: the colours are then premultiplied
  const Layer source = make_layer(std::move(texels));
  MipPyramid pyramid;
  build_mip_pyramid(source.image, pyramid);
  Mat3 tilt(1.0);
  entry(tilt, 2, 0) = 1.2 / 640.0;
  const Mat3 m = scaling(0.6, 0.6) * tilt;
  const int w = 160, h = 200;
  auto warped = [&](Sampling sampling, MipBlend blend, int factor) {
    Image out(w * factor, h * factor, Pixel{});
    WarpOptions options{sampling, WarpKernel::kPerspective, kDefaultHorizonEpsilon, &pyramid};
    options.mip_blend = blend;
    warp_layer_into(source, scaling(factor, factor) * m, out, 0, 0, options);
    return out;
  };
  const Image exact = box_reduce(warped(Sampling::kBilinear, kDefaultMipBlend, 4), 4);
  auto psnr = [&](const Image& image) {
    double sum = 0.0;
    std::int64_t n = 0;
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        const Pixel a = image.at(x, y), b = exact.at(x, y);
        if (a.a != 255 || b.a != 255) continue;  // inside the warped layer only
        for (int c : {int(a.r) - b.r, int(a.g) - b.g, int(a.b) - b.b}) sum += c * c;
        n += 3;
      }
    }
    EXPECT_GT(n, 3 * w * h / 2);
    return 10.0 * std::log10(255.0 * 255.0 * n / sum);
  };
  const Image middle = warped(Sampling::kMipmap, MipBlend::kMiddleHalf, 1);
  const Image trilinear = warped(Sampling::kMipmap, MipBlend::kTrilinear, 1);
  const double p_middle = psnr(middle), p_trilinear = psnr(trilinear);
  const double p_bilinear = psnr(warped(Sampling::kBilinear, kDefaultMipBlend, 1));
  EXPECT_GE(p_middle, p_trilinear - 1.0) << p_middle << " " << p_trilinear << " " << p_bilinear;
  EXPECT_GE(p_middle - p_bilinear, 3.0) << p_middle << " " << p_bilinear;
  EXPECT_NE(middle.pixels(), trilinear.pixels());
}

}  // namespace
}  // namespace oflab
