// Shrinking without shimmering (experiments_sampling.h): the supersampled reference against
// the exact coverage of a frontal rectangle, and the headline on small frames: mipmap beats
// bilinear by at least 3 dB on the minified frames of the receding plane.
#include "experiments/experiments_sampling.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "flow/camera.h"
#include "formats/datasets.h"
#include "formats/image_io.h"
#include "generators/fabric_texture.h"

namespace oflab {
namespace {

// A frontal rectangle projects to an axis-aligned rectangle; each pixel's alpha in the 16-sample
// render is the fraction of its 4 x 4 sample points, (x + (i + 1/2) / 4, y + (j + 1/2) / 4),
// inside it (a warp writes the pixels whose centres are inside), and the frame's total alpha
// is the rectangle's area.
TEST(SamplingExperiment, SupersampledFrameCoversTheExactProjection) {
  const Camera camera = make_camera(40.0, 48, 40);
  const Layer texture = make_layer(Image(8, 8, Pixel{255, 255, 255, 255}));
  PlanePose pose;
  pose.point = Vec3(0.13, -0.07, 2.0);
  pose.normal = Vec3(0.0, 0.0, 1.0);
  pose.up = Vec3(0.0, -1.0, 0.0);
  pose.size = Vec2(1.3, 0.9);
  const Image frame = supersampled_exact_frame(camera, texture, pose);
  ASSERT_EQ(frame.width(), 48);
  // The rectangle's image: centre f * X / Z + cx, half sizes f * size / (2 Z).
  const double x0 = 40.0 * (0.13 - 0.65) / 2.0 + 24.0, x1 = 40.0 * (0.13 + 0.65) / 2.0 + 24.0;
  const double y0 = 40.0 * (-0.07 - 0.45) / 2.0 + 20.0, y1 = 40.0 * (-0.07 + 0.45) / 2.0 + 20.0;
  int partial = 0;
  double total = 0.0;
  for (int y = 0; y < 40; ++y) {
    for (int x = 0; x < 48; ++x) {
      int inside = 0;
      for (int j = 0; j < 4; ++j) {
        for (int i = 0; i < 4; ++i) {
          const double sx = x + (i + 0.5) / 4.0, sy = y + (j + 0.5) / 4.0;
          inside += sx >= x0 && sx < x1 && sy >= y0 && sy < y1;
        }
      }
      partial += inside > 0 && inside < 16;
      total += frame.at(x, y).a / 255.0;
      ASSERT_NEAR(frame.at(x, y).a, 255.0 * inside / 16.0, 1.0) << x << "," << y;
    }
  }
  EXPECT_GT(partial, 20);  // the edges are fractional: the box filter is there
  EXPECT_NEAR(total, (x1 - x0) * (y1 - y0), 0.01 * (x1 - x0) * (y1 - y0));
}

TEST(SamplingExperiment, TheCommittedFabricIsTheGeneratorsOutput) {
  const Image generated = make_fabric_texture();
  const std::string path = datasets_dir() + "/textures/fabric.png";
  if (std::getenv("OFLAB_WRITE_FABRIC")) write_png(path, generated, Overwrite::kReplace);
  const Image committed = read_image(path);
  EXPECT_EQ(committed.pixels(), generated.pixels());
  for (const Pixel& p : committed.pixels()) ASSERT_EQ(p.a, 255);
}

// The headline on 160 x 120 frames: the exact policy follows the plane without geometric
// error, so the PSNR against the 16-sample render measures sampling alone.
TEST(SamplingExperiment, MipmapBeatsBilinearByThreeDecibelsOnMinifiedFrames) {
  const SamplingComparison c =
      compare_samplings(make_layer(make_fabric_texture()), sampling_spec(true));
  EXPECT_EQ(c.frames, 60);
  EXPECT_GE(c.minified_frames, 20);
  const double nearest = c.run(Sampling::kNearest).minified_psnr_db;
  const double bilinear = c.run(Sampling::kBilinear).minified_psnr_db;
  const double mipmap = c.run(Sampling::kMipmap).minified_psnr_db;
  EXPECT_GE(mipmap - bilinear, 3.0) << nearest << " " << bilinear << " " << mipmap;
  EXPECT_GT(bilinear, nearest);  // the control: bilinear filters a little, nearest none
  // Re-rendered frames are not minified, and a reused one is no larger than the render.
  for (const SamplingFrame& f : c.run(Sampling::kMipmap).frames) {
    if (f.level == Level::kRerender) {
      EXPECT_TRUE(std::isnan(f.minification));
    }
  }
}

}  // namespace
}  // namespace oflab
