// web/frame_pixels.h against independent computations: the "over" blend done in straight
// alpha with doubles, the largest difference and the heat map by a brute-force search, the
// display sampling by the pixel under each display pixel's centre.
#include "frame_pixels.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "display/palette.h"

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

TEST(FramePixels, RegionSamplingPicksThePixelUnderEachCentreOrNone) {
  // Display pixels 2.5 frame pixels wide from (-3, 1.25): centres at -1.75, 0.75, 3.25, ...
  const DisplaySampling s = region_sampling(8, 4, -3.0, 1.25, 2.5, 5, 3);
  EXPECT_EQ(s.columns, (std::vector<int>{-1, 0, 3, 5, -1}));  // 8.25 is beyond column 7
  EXPECT_EQ(s.rows, (std::vector<int>{2, -1, -1}));           // 4.75, 7.25: below the frame
  // The whole frame at its own size is the display sampling (the flow view's test size).
  const DisplaySampling same = region_sampling(640, 480, 0.0, 0.0, 1.0, 640, 480);
  const DisplaySampling whole = display_sampling(640, 480, 640, 480);
  EXPECT_EQ(same.columns, whole.columns);
  EXPECT_EQ(same.rows, whole.rows);
}

TEST(FramePixels, ShiftSamplingMovesIndicesOntoAPlacedImage) {
  // Frame columns -1, 0, 3, 5, 9 and rows 2, 7 onto a 4 x 5 image placed at (2, 3).
  DisplaySampling s{{-1, 0, 3, 5, 9}, {2, 7}};
  shift_sampling(s, 2, 3, 4, 5);
  EXPECT_EQ(s.columns, (std::vector<int>{-1, -1, 1, 3, -1}));
  EXPECT_EQ(s.rows, (std::vector<int>{-1, 4}));
}

TEST(FramePixels, FlattenFadesTowardsTheBackgroundAndShowsItOffTheFrame) {
  const Image frame = random_premultiplied(16, 9, 2);
  const std::uint8_t background[3] = {17, 19, 21};
  const DisplaySampling sampling = region_sampling(16, 9, -2.0, 0.0, 1.0, 20, 9);
  std::vector<std::uint8_t> full, faded;
  flatten_into(frame, sampling, background, full);
  flatten_into(frame, sampling, background, faded, 0.45);
  for (int y = 0; y < 9; ++y) {
    for (int x = 0; x < 20; ++x) {
      const std::size_t i = 4 * (std::size_t(y) * 20 + x);
      for (int c = 0; c < 3; ++c) {
        const bool off = x < 2 || x >= 18;  // display columns off the frame: the background
        if (off) EXPECT_EQ(full[i + c], background[c]) << x << "," << y;
        const double expected = background[c] + 0.45 * (full[i + c] - background[c]);
        EXPECT_NEAR(faded[i + c], expected, 0.51) << x << "," << y;
      }
      EXPECT_EQ(faded[i + 3], 255);
    }
  }
  // Control: the fade changes the frame's pixels.
  EXPECT_NE(full, faded);
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
      const Rgb8 c = magnitude_colour(d / 64.0);
      const std::uint8_t rgb[3] = {c.r, c.g, c.b};
      for (int k = 0; k < 3; ++k) EXPECT_EQ(out[4 * (y * 16 + x) + k], rgb[k]) << x << "," << y;
    }
  }
  EXPECT_THROW(difference_heat_map_into(a, b, 0, display_sampling(16, 8, 16, 8), out),
               std::invalid_argument);
  // A framed panel reaching past the frame (region_sampling's -1): there both frames show the
  // background, the colour of no difference; inside, the pixels as above.
  std::vector<std::uint8_t> framed;
  difference_heat_map_into(a, b, 64, region_sampling(16, 8, -2.0, -1.0, 1.0, 20, 10), framed);
  const Rgb8 none = magnitude_colour(0.0);
  for (int y = 0; y < 10; ++y) {
    for (int x = 0; x < 20; ++x) {
      const bool off = x < 2 || x >= 18 || y < 1 || y >= 9;
      const std::size_t i = 4 * (std::size_t(y) * 20 + x);
      if (off) {
        EXPECT_EQ(framed[i], none.r) << x << "," << y;
        EXPECT_EQ(framed[i + 2], none.b) << x << "," << y;
      } else {
        EXPECT_EQ(framed[i], out[4 * ((y - 1) * 16 + x - 2)]) << x << "," << y;
      }
    }
  }
}

// The one ramp of every front-end (session/display/palette.h), as the page's heat maps use it.
TEST(FramePixels, TheHeatRampRunsFromDarkBlueToYellowAndClamps) {
  const auto rgb = [](double t) {
    const Rgb8 c = magnitude_colour(t);
    return std::vector<int>{c.r, c.g, c.b};
  };
  EXPECT_EQ(rgb(0.0), (std::vector<int>{68, 1, 84}));
  EXPECT_EQ(rgb(1.0), (std::vector<int>{253, 231, 37}));
  EXPECT_EQ(rgb(-3.0), rgb(0.0));
  EXPECT_EQ(rgb(7.0), rgb(1.0));
  EXPECT_EQ(rgb(std::nan("")), rgb(0.0));
  // Lightness (the sum of the channels) grows along the ramp, so more difference is brighter.
  int previous = -1;
  for (int i = 0; i <= 64; ++i) {
    const std::vector<int> c = rgb(i / 64.0);
    EXPECT_GE(c[0] + c[1] + c[2], previous) << i;
    previous = c[0] + c[1] + c[2];
  }
}

}  // namespace
}  // namespace oflab
