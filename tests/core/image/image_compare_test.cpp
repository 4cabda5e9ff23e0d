// SSIM (core/image/image_compare.h) against an independent computation: the 11 x 11 window's
// weights built in two dimensions and every statistic summed directly at each position, and the
// closed form of two flat images. PSNR against its definition summed pixel by pixel in double.
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

// PSNR's definition pixel by pixel in double: the four channels' squared differences over the
// pixels where either image is not fully transparent.
double direct_psnr(const Image& a, const Image& b) {
  double sum = 0.0, count = 0.0;
  for (int y = 0; y < a.height(); ++y) {
    for (int x = 0; x < a.width(); ++x) {
      const Pixel p = a.at(x, y), q = b.at(x, y);
      if (p.a == 0 && q.a == 0) continue;
      for (const auto c : {&Pixel::r, &Pixel::g, &Pixel::b, &Pixel::a}) {
        const double d = double(p.*c) - double(q.*c);
        sum += d * d;
        count += 1.0;
      }
    }
  }
  return count == 0.0 || sum == 0.0 ? kIdenticalPsnrDb
                                    : 10.0 * std::log10(255.0 * 255.0 * count / sum);
}

TEST(Psnr, EqualsTheDefinitionSummedPixelByPixel) {
  std::mt19937 rng(5);
  for (const auto& [w, h] : {std::pair{37, 29}, std::pair{64, 48}, std::pair{1, 1}}) {
    Image a = random_image(rng, w, h);
    Image b = a;
    int k = 0;
    for (Pixel& p : b.pixels()) {  // every third pixel changed, every fifth transparent in both
      if (k % 3 == 0) p.r = static_cast<std::uint8_t>(rng() % 256);
      if (k % 5 == 0) {
        p = Pixel{static_cast<std::uint8_t>(rng() % 256), 7, 9, 0};  // colour, no coverage
        a.pixels()[std::size_t(k)].a = 0;
      }
      ++k;
    }
    EXPECT_DOUBLE_EQ(psnr_db(a, b), direct_psnr(a, b)) << w << "x" << h;
    // Control: covering the transparent pixels brings their colours into the sum.
    Image c = b;
    for (Pixel& p : c.pixels()) p.a = std::max<std::uint8_t>(p.a, 1);
    if (w > 1) {
      EXPECT_NE(psnr_db(a, c), psnr_db(a, b)) << w << "x" << h;
    }
    EXPECT_EQ(psnr_db(a, a), kIdenticalPsnrDb);
    EXPECT_EQ(psnr_db(a, Image(a)), kIdenticalPsnrDb);
  }
  EXPECT_EQ(psnr_db(Image(4, 4), Image(4, 4)), kIdenticalPsnrDb);  // both empty
  EXPECT_THROW(psnr_db(Image(4, 4), Image(4, 5)), std::invalid_argument);
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
