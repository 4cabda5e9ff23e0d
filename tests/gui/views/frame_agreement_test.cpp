// The comparison's difference map and agreement figures of one frame against itself (the exact
// panel showing a compared re-render's frame) skip their pass over the pixels: the results
// must be those of the same frame against a copy of it, where the pass runs.
#include <gtest/gtest.h>

#include <cmath>

#include "adapters/frame_images.h"

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

}  // namespace
}  // namespace oflab::test
