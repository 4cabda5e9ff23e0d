// The comparison's difference map and agreement figures of one frame against itself (the exact
// panel showing a compared re-render's frame) skip their pass over the pixels: the results
// must be those of the same frame against a copy of it, where the pass runs. The one pass that
// gives both (difference_map_and_agreement) gives what the two separate passes give.
#include <gtest/gtest.h>

#include <cmath>

#include "adapters/frame_images.h"
#include "display/palette.h"
#include "runs/frame_maps.h"

namespace oflab::test {
namespace {

// A frame half covered (alpha 255 in the left half, 0 in the right), with varied colours.
Image half_covered_frame(int width, int height) {
  Image image(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const bool covered = x < width / 2;
      image.row(y)[x] =
          covered ? Pixel{std::uint8_t(x * 7), std::uint8_t(y * 5), std::uint8_t(x + y), 255}
                  : Pixel{};
    }
  }
  return image;
}

TEST(FrameAgreement, AFrameAgainstItselfGivesWhatItGivesAgainstACopy) {
  const Image frame = half_covered_frame(64, 40);
  const Image copy = frame;
  const FrameAgreement self = frame_agreement(frame, frame);
  const FrameAgreement against_copy = frame_agreement(frame, copy);
  EXPECT_EQ(self.mask_iou, against_copy.mask_iou);
  EXPECT_TRUE(std::isinf(self.psnr_db));
  EXPECT_TRUE(std::isinf(against_copy.psnr_db));
  // Empty frames: IoU 1 both ways.
  const Image empty(16, 16);
  const Image empty_copy = empty;
  EXPECT_EQ(frame_agreement(empty, empty).mask_iou, frame_agreement(empty, empty_copy).mask_iou);
  // The control: one changed pixel makes the figures finite.
  Image changed = frame;
  changed.row(3)[4].r = std::uint8_t(changed.row(3)[4].r + 40);
  EXPECT_TRUE(std::isfinite(frame_agreement(frame, changed).psnr_db));
}

TEST(FrameAgreement, AFramesDifferenceMapAgainstItselfIsTheMapAgainstACopy) {
  const Image frame = half_covered_frame(64, 40);
  const Image copy = frame;
  QImage self, against_copy;
  difference_map_into(frame, frame, 64, self);
  difference_map_into(frame, copy, 64, against_copy);
  ASSERT_EQ(self.size(), against_copy.size());
  EXPECT_TRUE(self == against_copy);
  // The control: a changed pixel shows in the map.
  Image changed = frame;
  changed.row(3)[4].g = std::uint8_t(changed.row(3)[4].g + 60);
  QImage different;
  difference_map_into(frame, changed, 64, different);
  EXPECT_FALSE(different == self);
  EXPECT_NE(different.pixel(4, 3), self.pixel(4, 3));
}

TEST(FrameAgreement, FiguresAreTheMaskIouAndPsnrCountedPixelByPixel) {
  const Image a = half_covered_frame(70, 30);
  Image b = half_covered_frame(70, 30);
  for (int y = 0; y < b.height(); ++y) {
    for (int x = 20; x < 50; ++x) {  // shifts the covered part and changes some colours
      Pixel& p = b.row(y)[x];
      p = x < 45 ? Pixel{std::uint8_t(p.r + x % 9), std::uint8_t(p.g), std::uint8_t(y), 255}
                 : Pixel{};
    }
  }
  // Counted here one pixel at a time, in doubles.
  double both = 0, either = 0, squared = 0;
  for (int y = 0; y < a.height(); ++y) {
    for (int x = 0; x < a.width(); ++x) {
      const Pixel p = a.row(y)[x], q = b.row(y)[x];
      const bool ca = p.a > 127, cb = q.a > 127;
      if (ca || cb) either += 1;
      if (!(ca && cb)) continue;
      both += 1;
      squared += std::pow(p.r - q.r, 2) + std::pow(p.g - q.g, 2) + std::pow(p.b - q.b, 2);
    }
  }
  const FrameAgreement f = frame_agreement(a, b);
  EXPECT_DOUBLE_EQ(f.mask_iou, both / either);
  EXPECT_NEAR(f.psnr_db, 10.0 * std::log10(255.0 * 255.0 / (squared / (3.0 * both))), 1e-12);
  EXPECT_LT(f.mask_iou, 1.0);
}

TEST(FrameAgreement, TheOnePassMapAndFiguresAreThoseOfTheTwoPasses) {
  const Image a = half_covered_frame(300, 200);
  Image b = a;
  for (int y = 60; y < 140; ++y) {  // rows that differ (colours, coverage); the others are equal
    for (int x = 100; x < 200; ++x) {
      Pixel& p = b.row(y)[x];
      p = x < 170 ? Pixel{std::uint8_t(p.r + x % 13), std::uint8_t(p.g ^ 0x5a), p.b, 255} : Pixel{};
    }
  }
  QImage map, two_pass_map;
  const FrameAgreement one_pass = difference_map_and_agreement(a, b, 64, map);
  difference_map_into(a, b, 64, two_pass_map);
  const FrameAgreement two_pass = frame_agreement(a, b);
  EXPECT_TRUE(map == two_pass_map);
  EXPECT_EQ(one_pass.mask_iou, two_pass.mask_iou);
  EXPECT_EQ(one_pass.psnr_db, two_pass.psnr_db);
  // Controls: the frames do differ (finite PSNR, IoU below 1), and against itself the pass is
  // skipped with the same results as the two passes'.
  EXPECT_TRUE(std::isfinite(one_pass.psnr_db));
  EXPECT_LT(one_pass.mask_iou, 1.0);
  QImage self_map, self_two_pass;
  const FrameAgreement self = difference_map_and_agreement(a, a, 64, self_map);
  difference_map_into(a, a, 64, self_two_pass);
  EXPECT_TRUE(self_map == self_two_pass);
  EXPECT_TRUE(std::isinf(self.psnr_db));
  EXPECT_FALSE(self_map == map);
}

TEST(FrameAgreement, TheMapIsEachPixelsLargestChannelDifferenceColoured) {
  // 301 pixels wide (not a multiple of the four pixels taken at a time), every channel varied.
  const Image a = half_covered_frame(301, 23);
  Image b = a;
  for (int y = 0; y < b.height(); ++y) {
    if (y % 5 == 0) continue;  // rows left the same
    for (int x = 0; x < b.width(); ++x) {
      Pixel& p = b.row(y)[x];
      p = Pixel{std::uint8_t(p.r + 3 * x), std::uint8_t(p.g - y), std::uint8_t(p.b ^ (x * y)),
                std::uint8_t(x % 7 == 0 ? 90 : p.a)};
    }
  }
  // The reference: analysis's per-pixel difference map, coloured one pixel at a time.
  const std::vector<std::uint8_t> largest = channel_difference_map(a, b);
  QImage one_pass, two_pass;
  difference_map_and_agreement(a, b, 100, one_pass);
  difference_map_into(a, b, 100, two_pass);
  int differing = 0;
  for (int y = 0; y < a.height(); ++y) {
    for (int x = 0; x < a.width(); ++x) {
      const std::uint8_t d = largest[size_t(y) * size_t(a.width()) + size_t(x)];
      const Rgb8 c = magnitude_colour(d / 100.0);
      ASSERT_EQ(one_pass.pixel(x, y), qRgb(c.r, c.g, c.b)) << x << ", " << y;
      ASSERT_EQ(two_pass.pixel(x, y), qRgb(c.r, c.g, c.b)) << x << ", " << y;
      differing += d > 0;
    }
  }
  EXPECT_GT(differing, a.width() * a.height() / 2);  // control: most pixels differ
}

TEST(FrameAgreement, RowsWiderThanA32BitSumHoldAreCountedWhole) {
  // 12000 pixels of the largest colour difference: 12000 x 3 x 255^2 is past 2^31, so the row's
  // sum of squares must not wrap. Every pixel differs by 255 in each channel: PSNR 0 dB.
  const int width = 12000;
  Image white(width, 2), black(width, 2);
  for (int y = 0; y < 2; ++y) {
    for (int x = 0; x < width; ++x) {
      white.row(y)[x] = Pixel{255, 255, 255, 255};
      black.row(y)[x] = Pixel{0, 0, 0, 255};
    }
  }
  QImage map;
  const FrameAgreement one_pass = difference_map_and_agreement(white, black, 128, map);
  const FrameAgreement two_pass = frame_agreement(white, black);
  EXPECT_EQ(one_pass.mask_iou, 1.0);
  EXPECT_NEAR(one_pass.psnr_db, 0.0, 1e-12);
  EXPECT_EQ(two_pass.psnr_db, one_pass.psnr_db);
  // Control: half the difference gives 20 log10(255 / 128) dB, not 0.
  Image grey = black;
  for (int x = 0; x < width; ++x) grey.row(1)[x] = Pixel{128, 128, 128, 255};
  EXPECT_NEAR(frame_agreement(white, grey).psnr_db,
              10.0 * std::log10(255.0 * 255.0 / ((255.0 * 255.0 + 127.0 * 127.0) / 2.0)), 1e-9);
}

}  // namespace
}  // namespace oflab::test
