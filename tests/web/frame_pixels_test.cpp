// web/frame_pixels.h against independent computations: the "over" blend done in straight
// alpha with doubles, the largest difference and the heat map by a brute-force search, the
// display sampling by the pixel under each display pixel's centre.
#include "frame_pixels.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace oflab {
namespace {

Image random_premultiplied(int width, int height, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> byte(0, 255);
  Image image(width, height);
  for (Pixel& p : image.pixels()) {
    const int a = byte(rng);
    // Premultiplied: no colour above alpha.
    p = Pixel{static_cast<std::uint8_t>(byte(rng) * a / 255),
              static_cast<std::uint8_t>(byte(rng) * a / 255),
              static_cast<std::uint8_t>(byte(rng) * a / 255), static_cast<std::uint8_t>(a)};
  }
  return image;
}

TEST(FramePixels, DisplaySamplingPicksThePixelUnderEachCentre) {
  const DisplaySampling s = display_sampling(640, 480, 300, 225);
  ASSERT_EQ(s.columns.size(), 300u);
  ASSERT_EQ(s.rows.size(), 225u);
  for (std::size_t i = 0; i < s.columns.size(); ++i) {
    EXPECT_EQ(s.columns[i], static_cast<int>(std::floor((i + 0.5) * 640.0 / 300.0))) << i;
  }
  EXPECT_EQ(s.rows.front(), 1);  // the centre of row 0 is at 0.5 * 480 / 225 = 1.07
  EXPECT_EQ(s.rows.back(), 478);
  const DisplaySampling same = display_sampling(4, 3, 4, 3);
  EXPECT_EQ(same.columns, (std::vector<int>{0, 1, 2, 3}));
  EXPECT_EQ(same.rows, (std::vector<int>{0, 1, 2}));
}

TEST(FramePixels, FlattenIsTheStraightAlphaBlendOverTheBackground) {
  const Image frame = random_premultiplied(37, 23, 1);
  const std::uint8_t background[3] = {24, 27, 31};
  std::vector<std::uint8_t> out;
  flatten_into(frame, display_sampling(37, 23, 37, 23), background, out);
  ASSERT_EQ(out.size(), 37u * 23u * 4u);
  for (int y = 0; y < 23; ++y) {
    for (int x = 0; x < 37; ++x) {
      const Pixel p = frame.at(x, y);
      const double alpha = p.a / 255.0;
      const std::uint8_t colour[3] = {p.r, p.g, p.b};
      for (int c = 0; c < 3; ++c) {
        // colour = alpha * straight + (1 - alpha) * background, straight = colour / alpha.
        const double expected = colour[c] + (1.0 - alpha) * background[c];
        EXPECT_NEAR(out[4 * (y * 37 + x) + c], expected, 0.51) << x << "," << y;
      }
      EXPECT_EQ(out[4 * (y * 37 + x) + 3], 255);
    }
  }
}

TEST(FramePixels, LargestDifferenceIsTheLargestChannelDifference) {
  const Image a = random_premultiplied(50, 40, 2);
  Image b = a;
  EXPECT_EQ(largest_difference(a, b), 0);
  b.at(13, 7).g = static_cast<std::uint8_t>(a.at(13, 7).g > 100 ? a.at(13, 7).g - 100 : 200);
  const int expected = std::abs(static_cast<int>(a.at(13, 7).g) - static_cast<int>(b.at(13, 7).g));
  EXPECT_EQ(largest_difference(a, b), expected);
  EXPECT_THROW(largest_difference(a, Image(3, 3)), std::invalid_argument);
}

TEST(FramePixels, HeatMapColoursEachPixelByItsDifference) {
  const Image a = random_premultiplied(16, 8, 3);
  const Image b = random_premultiplied(16, 8, 4);
  std::vector<std::uint8_t> out;
  difference_heat_map_into(a, b, 64, display_sampling(16, 8, 16, 8), out);
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 16; ++x) {
      const Pixel p = a.at(x, y);
      const Pixel q = b.at(x, y);
      int d = 0;
      for (const auto& [u, v] : {std::pair{p.r, q.r}, {p.g, q.g}, {p.b, q.b}, {p.a, q.a}}) {
        d = std::max(d, std::abs(u - v));
      }
      std::uint8_t rgb[3];
      viridis(d / 64.0, rgb);
      for (int c = 0; c < 3; ++c) EXPECT_EQ(out[4 * (y * 16 + x) + c], rgb[c]) << x << "," << y;
    }
  }
  EXPECT_THROW(difference_heat_map_into(a, b, 0, display_sampling(16, 8, 16, 8), out),
               std::invalid_argument);
}

TEST(FramePixels, ViridisRunsFromDarkBlueToYellowAndClamps) {
  std::uint8_t low[3], high[3], below[3], above[3], nan[3];
  viridis(0.0, low);
  viridis(1.0, high);
  viridis(-3.0, below);
  viridis(7.0, above);
  viridis(std::nan(""), nan);
  EXPECT_EQ(std::vector<int>(low, low + 3), (std::vector<int>{68, 1, 84}));
  EXPECT_EQ(std::vector<int>(high, high + 3), (std::vector<int>{253, 231, 37}));
  EXPECT_EQ(std::vector<int>(below, below + 3), std::vector<int>(low, low + 3));
  EXPECT_EQ(std::vector<int>(above, above + 3), std::vector<int>(high, high + 3));
  EXPECT_EQ(std::vector<int>(nan, nan + 3), std::vector<int>(low, low + 3));
  // Lightness (the sum of the channels) grows along the ramp, so more difference is brighter.
  int previous = -1;
  for (int i = 0; i <= 64; ++i) {
    std::uint8_t rgb[3];
    viridis(i / 64.0, rgb);
    const int sum = rgb[0] + rgb[1] + rgb[2];
    EXPECT_GE(sum, previous) << i;
    previous = sum;
  }
}

}  // namespace
}  // namespace oflab
