// The depth span's AVX2 loop against its pixel-by-pixel loop (the reference): the same
// depths, pixels and count of first stores on random faces over random depth buffers, with
// ties, NaNs and spans of every length and start; and on a hand case, what the loop means.
#include "content/depth_span.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace oflab {
namespace {

struct Row {
  std::vector<float> z;
  std::vector<Pixel> pixels;
};

TEST(DepthSpan, TheWideLoopDrawsWhatThePixelLoopDraws) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const int width = 96;
  int drawn = 0, ties = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    Row row;
    for (int x = 0; x < width; ++x) {
      const double pick = unit(random);
      row.z.push_back(pick < 0.3 ? 0.0f : static_cast<float>(0.1 + 0.2 * unit(random)));
      const auto a = static_cast<std::uint8_t>(unit(random) < 0.5 ? 0 : 255);
      row.pixels.push_back(Pixel{a, 0, 0, a});
    }
    const DepthRow plane{(unit(random) - 0.5) * 0.01, 0.1 + 0.2 * unit(random),
                         (unit(random) - 0.5) * 0.1};
    if (trial % 5 == 0) {  // ties: some of the buffer holds the face's own 1/Z
      for (int x = 0; x < width; x += 3) {
        row.z[x] = static_cast<float>(plane.c0 + plane.a * x + plane.by);
      }
    }
    if (trial % 7 == 0) row.z[trial % width] = std::numeric_limits<float>::quiet_NaN();
    const int begin = static_cast<int>(unit(random) * 20), end = begin + trial % (width - 20);
    const Pixel colour{10, 20, 30, 255};
    Row wide = row, narrow = row;
    const std::int64_t wide_count =
        draw_depth_span(plane, colour, begin, end, wide.z.data(), wide.pixels.data(), true);
    const std::int64_t narrow_count =
        draw_depth_span(plane, colour, begin, end, narrow.z.data(), narrow.pixels.data(), false);
    ASSERT_EQ(wide_count, narrow_count) << "trial " << trial;
    ASSERT_EQ(0, std::memcmp(wide.z.data(), narrow.z.data(), width * sizeof(float)))
        << "trial " << trial;
    ASSERT_TRUE(wide.pixels == narrow.pixels) << "trial " << trial;
    for (int x = begin; x < end; ++x) {
      drawn += narrow.pixels[x] == colour;
      ties += row.z[x] == static_cast<float>(plane.c0 + plane.a * x + plane.by);
    }
  }
  EXPECT_GT(drawn, 10000);  // the cases draw, and tie, often
  EXPECT_GT(ties, 1000);
}

// What the loop means, by hand: a nearer face (larger 1/Z) is drawn, an equal or farther one
// is not, and only stores on transparent pixels count.
TEST(DepthSpan, ANearerFaceIsDrawnAndATieIsNot) {
  for (bool wide : {false, true}) {
    std::vector<float> z(16, 0.5f);
    std::vector<Pixel> pixels(16, Pixel{});
    z[2] = 0.25f;                         // farther: drawn over
    z[3] = 1.0f;                          // nearer: kept
    pixels[4] = Pixel{1, 1, 1, 255};      // drawn over, not a first store
    const DepthRow plane{0.0, 0.5, 0.0};  // 1/Z = 0.5 everywhere: a tie elsewhere
    std::vector<float> farther = z;
    for (float& v : farther) v = v == 0.5f ? 0.4f : v;
    const Pixel colour{9, 9, 9, 255};
    EXPECT_EQ(draw_depth_span(plane, colour, 0, 16, z.data(), pixels.data(), wide), 1);
    EXPECT_EQ(pixels[2], colour);
    EXPECT_NE(pixels[3], colour);
    EXPECT_EQ(z[3], 1.0f);
    EXPECT_EQ(pixels[5], Pixel{});  // the tie
    std::vector<Pixel> fresh(16, Pixel{});
    fresh[4] = Pixel{1, 1, 1, 255};
    EXPECT_EQ(draw_depth_span(plane, colour, 0, 16, farther.data(), fresh.data(), wide), 14);
  }
}

}  // namespace
}  // namespace oflab
