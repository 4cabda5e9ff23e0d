// RGBA8 premultiplied images and the alpha conversions, checked exhaustively against
// the formulas in double precision.
#include "image/image.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "image/pixel_math.h"

namespace oflab {
namespace {

TEST(Image, Div255RoundIsExactOverItsWholeRange) {
  for (unsigned v = 0; v <= 255u * 255u; ++v) {
    ASSERT_EQ(div255_round(v), static_cast<unsigned>(std::floor(v / 255.0 + 0.5))) << v;
  }
}

TEST(Image, PremultiplyRoundsEveryChannelValueAndAlphaPair) {
  for (int a = 0; a < 256; ++a) {
    for (int c = 0; c < 256; ++c) {
      const auto v = static_cast<std::uint8_t>(c);
      const Pixel p = premultiply(Pixel{v, v, v, static_cast<std::uint8_t>(a)});
      const auto expected = static_cast<int>(std::floor(c * a / 255.0 + 0.5));
      ASSERT_EQ(p.r, expected) << c << " " << a;
      ASSERT_LE(p.r, p.a);
    }
  }
}

TEST(Image, UnpremultiplyInvertsPremultiplyForOpaqueAndIsCloseOtherwise) {
  for (int a = 1; a < 256; ++a) {
    for (int c = 0; c < 256; ++c) {
      const auto v = static_cast<std::uint8_t>(c);
      const Pixel back = unpremultiply(premultiply(Pixel{v, 0, 255, static_cast<std::uint8_t>(a)}));
      // Premultiplying loses up to 255 / (2a) of precision.
      ASSERT_LE(std::abs(back.r - c), 255.0 / (2.0 * a) + 0.5) << c << " " << a;
      if (a == 255) {
        ASSERT_EQ(back.r, c);
      }
    }
  }
  EXPECT_EQ(unpremultiply(Pixel{0, 0, 0, 0}), Pixel{});
  EXPECT_EQ(unpremultiply(Pixel{200, 0, 0, 100}).r, 255);  // malformed input saturates
}

TEST(Image, ConstructionChecksTheSizeAndFills) {
  const Image image(3, 2, Pixel{1, 2, 3, 4});
  EXPECT_EQ(image.pixel_count(), 6u);
  EXPECT_EQ(image.at(2, 1), (Pixel{1, 2, 3, 4}));
  EXPECT_TRUE(Image(0, 7).empty());
  EXPECT_EQ(Image(0, 7).pixel_count(), 0u);
  EXPECT_THROW(Image(-1, 3), std::invalid_argument);
  EXPECT_THROW(Image(3, kMaxImageDimension + 1), std::invalid_argument);
}

// A copy into an image in use is the source's size and pixels; when the destination's storage
// is too small it grows with headroom, so that the next, slightly larger copy keeps it (the
// layer copied each frame as it grows). An empty destination, and a self-copy, are plain.
TEST(Image, CopiesIntoAGrowingImageKeepItsStorage) {
  const auto ramp = [](int w, int h) {
    Image image(w, h);
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        image.at(x, y) = Pixel{static_cast<std::uint8_t>(x), static_cast<std::uint8_t>(y), 7, 255};
      }
    }
    return image;
  };
  Image kept(10, 10);
  const Image first = ramp(100, 50);
  kept = first;  // grows: 5000 pixels with room for 6250
  const Pixel* storage = kept.pixels().data();
  const Image larger = ramp(110, 55);  // 6050 pixels
  kept = larger;
  EXPECT_EQ(kept.width(), 110);
  EXPECT_EQ(kept.height(), 55);
  EXPECT_TRUE(kept.pixels() == larger.pixels());
  EXPECT_EQ(kept.pixels().data(), storage);  // no reallocation
  const Image smaller = ramp(20, 30);
  kept = smaller;
  EXPECT_TRUE(kept.pixels() == smaller.pixels());
  EXPECT_EQ(kept.width(), 20);
  kept = kept;  // self-copy
  EXPECT_TRUE(kept.pixels() == smaller.pixels());
  Image fresh;
  fresh = larger;
  EXPECT_EQ(fresh.pixels().capacity(), larger.pixels().size());  // exactly what it needs
  EXPECT_TRUE(fresh.pixels() == larger.pixels());
}

// A layer's image reshaped frame after frame: grown past the storage in use (after a shrink,
// which keeps it), it takes a quarter of headroom, so the next growths stay in place.
TEST(Image, AReshapedImageGrowingPastItsStorageGetsHeadroom) {
  Image image(100, 50);    // exactly 5000 pixels
  image.reshape(10, 10);   // the storage stays
  image.reshape(100, 60);  // 6000 pixels: room for 7500
  EXPECT_GE(image.pixels().capacity(), 7500u);
  const Pixel* storage = image.pixels().data();
  image.reshape(110, 65);                     // 7150 pixels
  EXPECT_EQ(image.pixels().data(), storage);  // no reallocation
  EXPECT_EQ(image.width(), 110);
  EXPECT_EQ(image.height(), 65);
  EXPECT_EQ(image.pixels().size(), 7150u);
  Image fresh;
  fresh.reshape(30, 20);
  EXPECT_EQ(fresh.pixels().capacity(), 600u);  // an empty image takes exactly what it needs
}

TEST(Image, StraightBytesRoundTripThroughPremultipliedStorage) {
  const std::vector<std::uint8_t> bytes = {255, 128, 0, 255, 100, 50, 25, 128};
  const Image image = image_from_straight_rgba(2, 1, bytes);
  EXPECT_EQ(image.at(0, 0), (Pixel{255, 128, 0, 255}));
  EXPECT_EQ(image.at(1, 0), (Pixel{50, 25, 13, 128}));
  const std::vector<std::uint8_t> back = straight_rgba_from_image(image);
  for (std::size_t i = 0; i < bytes.size(); ++i) EXPECT_NEAR(back[i], bytes[i], 1.0);
  EXPECT_THROW(image_from_straight_rgba(2, 2, bytes), std::invalid_argument);
  Image straight(1, 1, Pixel{200, 100, 50, 51});
  premultiply_in_place(straight);
  EXPECT_EQ(straight.at(0, 0), (Pixel{40, 20, 10, 51}));
}

}  // namespace
}  // namespace oflab
