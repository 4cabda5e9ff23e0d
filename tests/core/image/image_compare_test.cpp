// SSIM (core/image/image_compare.h) against an independent computation: the 11 x 11 window's
// weights built in two dimensions and every statistic summed directly at each position, and the
// closed form of two flat images.
#include "image/image_compare.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace oflab {
namespace {

// Wang et al.'s definition summed directly: for each position where the window fits, the
// weighted means, variances and covariance of luma under the 2-D Gaussian.
double direct_ssim(const Image& a, const Image& b) {
  const int r = 5;
  double weights[11][11], total = 0.0;
  for (int j = -r; j <= r; ++j) {
    for (int i = -r; i <= r; ++i) {
      weights[j + r][i + r] = std::exp(-(i * i + j * j) / (2.0 * 1.5 * 1.5));
      total += weights[j + r][i + r];
    }
  }
  const auto y = [](const Image& im, int x, int v) {
    const Pixel p = im.at(x, v);
    return 0.299 * p.r + 0.587 * p.g + 0.114 * p.b;
  };
  const double c1 = 6.5025, c2 = 58.5225;  // (0.01 x 255)^2, (0.03 x 255)^2
  double sum = 0.0;
  int n = 0;
  for (int cy = r; cy < a.height() - r; ++cy) {
    for (int cx = r; cx < a.width() - r; ++cx) {
      double mx = 0, my = 0;
      for (int j = -r; j <= r; ++j) {
        for (int i = -r; i <= r; ++i) {
          const double w = weights[j + r][i + r] / total;
          mx += w * y(a, cx + i, cy + j);
          my += w * y(b, cx + i, cy + j);
        }
      }
      double vx = 0, vy = 0, cov = 0;
      for (int j = -r; j <= r; ++j) {
        for (int i = -r; i <= r; ++i) {
          const double w = weights[j + r][i + r] / total;
          const double dx = y(a, cx + i, cy + j) - mx, dy = y(b, cx + i, cy + j) - my;
          vx += w * dx * dx;
          vy += w * dy * dy;
          cov += w * dx * dy;
        }
      }
      sum += (2 * mx * my + c1) * (2 * cov + c2) / ((mx * mx + my * my + c1) * (vx + vy + c2));
      ++n;
    }
  }
  return sum / n;
}

Image random_image(std::mt19937& rng, int w, int h) {
  Image im(w, h);
  for (Pixel& p : im.pixels()) {
    p = Pixel{static_cast<std::uint8_t>(rng() % 256), static_cast<std::uint8_t>(rng() % 256),
              static_cast<std::uint8_t>(rng() % 256), 255};
  }
  return im;
}

TEST(Ssim, EqualsTheDirectSumOfWangEtAlsDefinition) {
  std::mt19937 rng(3);
  for (const auto& [w, h] : {std::pair{16, 13}, std::pair{11, 11}, std::pair{24, 12}}) {
    const Image a = random_image(rng, w, h);
    Image b = a;
    for (Pixel& p : b.pixels()) {  // a noisy, darker copy: partly similar
      p.r = static_cast<std::uint8_t>(std::min(255, p.r / 2 + static_cast<int>(rng() % 40)));
      p.g = static_cast<std::uint8_t>(p.g * 3 / 4);
    }
    const double s = mean_ssim(a, b);
    EXPECT_NEAR(s, direct_ssim(a, b), 1e-12) << w << "x" << h;
    EXPECT_GT(s, 0.05);
    EXPECT_LT(s, 0.95);
    EXPECT_NEAR(mean_ssim(a, a), 1.0, 1e-12);
  }
}

TEST(Ssim, TwoFlatImagesScoreTheLuminanceTermAlone) {
  Image a(12, 12), b(12, 12);
  for (Pixel& p : a.pixels()) p = Pixel{100, 100, 100, 255};
  for (Pixel& p : b.pixels()) p = Pixel{140, 140, 140, 255};
  const double c1 = (0.01 * 255) * (0.01 * 255);
  // No variance: the structure term is (0 + C2) / (0 + C2) = 1.
  EXPECT_NEAR(mean_ssim(a, b), (2 * 100.0 * 140.0 + c1) / (100.0 * 100.0 + 140.0 * 140.0 + c1),
              1e-9);
  EXPECT_THROW(mean_ssim(Image(10, 12), Image(10, 12)), std::invalid_argument);
  EXPECT_THROW(mean_ssim(a, Image(12, 13)), std::invalid_argument);
}

}  // namespace
}  // namespace oflab
