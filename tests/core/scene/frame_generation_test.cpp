// Frame generation by extrapolation along motion vectors (core/scene/frame_generation.h) and
// push-pull inpainting (core/image/push_pull.h) against independent computations: the exact
// projection of moving points, the disoccluded pixels found by rays in world coordinates, a
// top-down quadtree definition of push-pull, and the error read back from the image itself.
#include "scene/frame_generation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>

#include "image/push_pull.h"
#include "image/thread_pool.h"
#include "scene/scene_animator.h"
#include "scene_cases.h"

namespace oflab {
namespace {

using testing::cube_past_cube;
using testing::open_cube;
using testing::project_world;
using testing::scene_with;
using testing::sliding_past;
using testing::world_point_at;

const Camera kCamera = make_camera(150.0, 160, 120);
constexpr double kNear = 0.05;

TEST(FrameGeneration, ExtrapolationIsExactForASteadySidewaysSlideAndWrongInATurn) {
  const Scene scene = cube_past_cube();
  const auto check = [&](const std::vector<ViewerFrame>& f, double* worst) {
    const DepthFrame depth = render_depth(scene, kCamera, f[1].pose, kNear);
    const RigidStep3 back = viewer_step(f[1].pose, f[0].pose);
    *worst = 0.0;
    for (int k = 1; k <= 3; ++k) {
      for (int s = 0; s < kCamera.width * kCamera.height; s += 7) {
        const int p = depth.polygon[s];
        if (p < 0) continue;
        const double u = s % kCamera.width + 0.5, v = s / kCamera.width + 0.5;
        Vec2 moved;
        double w = 0.0;
        ASSERT_TRUE(extrapolate_point(kCamera, back, depth.planes[p], u, v, k, kNear, moved, w));
        const Vec3 hit = world_point_at(kCamera, scene.polygons[p], f[1].pose, u, v);
        *worst = std::max(*worst, glm::length(moved - project_world(kCamera, f[1 + k].pose, hit)));
      }
    }
  };
  double slide = 0.0, turn = 0.0;
  check(sliding_past(5, Vec3(0.05, 0, 0), Vec3(0.0)), &slide);
  check(sliding_past(5, Vec3(0.05, 0, -0.1), Vec3(0, 0.03, 0)), &turn);
  EXPECT_LT(slide, 1e-9);  // p(t) = f (X - t) / Z is linear in t
  EXPECT_GT(turn, 0.5);    // a turn and a push in: the vectors of the last step are wrong
}

// The pixels seen now that the render did not see (outside its view, or behind another of
// its surfaces: another polygon nearer at the pixel the point falls in), found by rays in
// world coordinates.
std::vector<char> disoccluded(const Scene& scene, const ViewerPose& then, const ViewerPose& now) {
  const DepthFrame seen_now = render_depth(scene, kCamera, now, kNear);
  const DepthFrame seen_then = render_depth(scene, kCamera, then, kNear);
  std::vector<char> out(seen_now.polygon.size(), 0);
  for (std::size_t d = 0; d < out.size(); ++d) {
    const int p = seen_now.polygon[d];
    if (p < 0) continue;
    const Vec3 x = world_point_at(kCamera, scene.polygons[p], now, d % kCamera.width + 0.5,
                                  d / kCamera.width + 0.5);
    const Vec2 q = project_world(kCamera, then, x);
    const int i = static_cast<int>(std::floor(q.x)), j = static_cast<int>(std::floor(q.y));
    if (i < 0 || j < 0 || i >= kCamera.width || j >= kCamera.height) {
      out[d] = 1;
      continue;
    }
    const std::size_t s = static_cast<std::size_t>(j) * kCamera.width + i;
    out[d] = seen_then.polygon[s] != p && seen_then.inverse_depth[s] > 1.0 / to_view(then, x).z;
  }
  return out;
}

TEST(FrameGeneration, TheMaskCoversACubesDisocclusionAndInpaintingLeavesNoEmptyPixel) {
  const Scene scene = cube_past_cube();
  const auto f = sliding_past(4, Vec3(0.3, 0, 0), Vec3(0.0));  // 6 px a frame past the far cube
  const Image rendered = testing::ray_cast_scene(scene, kCamera, f[1].pose, kNear);
  const DepthFrame depth = render_depth(scene, kCamera, f[1].pose, kNear);
  const RigidStep3 back = viewer_step(f[1].pose, f[0].pose);
  for (int k = 1; k <= 2; ++k) {
    const std::vector<char> truth = disoccluded(scene, f[1].pose, f[1 + k].pose);
    const long uncovered = std::count(truth.begin(), truth.end(), 1);
    ASSERT_GT(uncovered, 40 * k) << "the near cube uncovers the far one";
    const GeneratedFrame raw =
        extrapolate_by_motion(rendered, depth, kCamera, back, k, false, kNear);
    GeneratedFrame filled = extrapolate_by_motion(rendered, depth, kCamera, back, k, true, kNear);
    long caught = 0;
    for (std::size_t d = 0; d < truth.size(); ++d) caught += truth[d] && raw.mask[d];
    EXPECT_GE(static_cast<double>(caught) / uncovered, 0.95) << "k = " << k;
    EXPECT_EQ(filled.mask, raw.mask);
    EXPECT_EQ(filled.inpainted_pixels, std::count(raw.unreached.begin(), raw.unreached.end(), 1));
    // No empty pixel where the view now shows a surface: the raw frame leaves them empty
    // (the negative control), the inpainted one fills every one. Revealed empty background is
    // filled too, from the transparent background around it.
    const DepthFrame seen_now = render_depth(scene, kCamera, f[1 + k].pose, kNear);
    measure_generated_frame(depth, kCamera, viewer_step(f[1].pose, f[1 + k].pose), seen_now,
                            filled);
    long empty_raw = 0, empty_filled = 0, false_alarms = 0;
    for (std::size_t d = 0; d < truth.size(); ++d) {
      false_alarms += raw.mask[d] && !truth[d] && seen_now.polygon[d] >= 0;
      if (!raw.unreached[d]) {
        ASSERT_EQ(filled.image.pixels()[d], raw.image.pixels()[d]) << "inpainting kept away";
        continue;
      }
      if (seen_now.polygon[d] < 0) continue;
      empty_raw += raw.image.pixels()[d].a == 0;
      empty_filled += filled.image.pixels()[d].a == 0;
    }
    EXPECT_GT(filled.hole_pixels, 20 * k);
    EXPECT_EQ(empty_raw, filled.hole_pixels);
    EXPECT_EQ(empty_filled, 0);
    // The mask is where the disocclusion is, not the whole picture: what it flags beyond it
    // (a one-pixel ring, and the splats' overshoot) stays below the disocclusion itself.
    EXPECT_LT(false_alarms, uncovered) << "k = " << k;
  }
}

// The splats of the header's "Splats", painted by their definition: one pass over the source
// pixels in order, every footprint corner and centre moved by extrapolate_point, the inside
// test of the four edges' cross products, the distance as the length of the offset. The
// generated frame's image and sources, and the writes counted.
struct OnePass {
  std::vector<Pixel> image;
  std::vector<int> source;
  std::int64_t written = 0;
};

OnePass paint_in_one_pass(const Image& rendered, const DepthFrame& depth, const Camera& camera,
                          const RigidStep3& back, int k) {
  const std::size_t n = rendered.pixel_count();
  OnePass out{Image(camera.width, camera.height).pixels(), std::vector<int>(n, -1), 0};
  std::vector<double> shown_w(n, -1.0), dist(n, 0.0);
  std::vector<int> polygon(n, -1);
  const double du[4] = {-0.5, 1.5, 1.5, -0.5}, dv[4] = {-0.5, -0.5, 1.5, 1.5};
  for (int j = 0; j < camera.height; ++j) {
    for (int i = 0; i < camera.width; ++i) {
      const std::size_t s = static_cast<std::size_t>(j) * camera.width + i;
      const int p = depth.polygon[s];
      const Vec3 m = p >= 0 ? depth.planes[p] : Vec3(0.0);
      Vec2 centre, q[4];
      double w = 0.0, unused = 0.0;
      bool ok = extrapolate_point(camera, back, m, i + 0.5, j + 0.5, k, kNear, centre, w);
      for (int c = 0; c < 4 && ok; ++c) {
        ok = extrapolate_point(camera, back, m, i + du[c], j + dv[c], k, kNear, q[c], unused);
      }
      if (!ok) continue;
      double x0 = q[0].x, x1 = q[0].x, y0 = q[0].y, y1 = q[0].y;
      for (const Vec2& c : q) {
        x0 = std::min(x0, c.x), x1 = std::max(x1, c.x), y0 = std::min(y0, c.y);
        y1 = std::max(y1, c.y);
      }
      const int xb = std::max(0, static_cast<int>(std::ceil(x0 - 0.5)));
      const int xe = std::min(camera.width - 1, static_cast<int>(std::floor(x1 - 0.5)));
      const int yb = std::max(0, static_cast<int>(std::ceil(y0 - 0.5)));
      const int ye = std::min(camera.height - 1, static_cast<int>(std::floor(y1 - 0.5)));
      if (xe < xb || ye < yb || double(xe - xb + 1) * (ye - yb + 1) > 4096.0) continue;
      for (int y = yb; y <= ye; ++y) {
        for (int x = xb; x <= xe; ++x) {
          const Vec2 c(x + 0.5, y + 0.5);
          bool positive = true, negative = true;
          for (int e = 0; e < 4; ++e) {
            const Vec2 edge = q[(e + 1) % 4] - q[e];
            const double cross = edge.x * (c.y - q[e].y) - edge.y * (c.x - q[e].x);
            positive = positive && cross >= -1e-9;
            negative = negative && cross <= 1e-9;
          }
          if (!positive && !negative) continue;
          const std::size_t d = static_cast<std::size_t>(y) * camera.width + x;
          const bool same = out.source[d] >= 0 && polygon[d] == p;
          if (!same && w <= shown_w[d]) continue;
          const double e = glm::length(c - centre);
          if (same && e >= dist[d]) continue;
          shown_w[d] = w, dist[d] = e, polygon[d] = p;
          out.image[d] = rendered.pixels()[s];
          out.source[d] = static_cast<int>(s);
          ++out.written;
        }
      }
    }
  }
  return out;
}

// The generated frame of render f[1] two frames ahead, on 1 and 3 threads, with and without
// inpainting, against paint_in_one_pass; `still` says whether the step has no rotation (the
// background's splats then stay where they are, the aligned path).
void expect_bands_paint_the_one_pass_frame(const std::vector<ViewerFrame>& f, bool still) {
  const Camera camera = make_camera(600.0, 640, 480);  // cut into many bands
  ASSERT_GT(band_count(camera.height, 4), 1);
  const Scene scene = cube_past_cube();
  const Image rendered = testing::ray_cast_scene(scene, camera, f[1].pose, kNear);
  const DepthFrame depth = render_depth(scene, camera, f[1].pose, kNear);
  const RigidStep3 back = viewer_step(f[1].pose, f[0].pose);
  ASSERT_EQ(back.rotation == Mat3(1.0), still);
  const DepthFrame now = render_depth(scene, camera, f[3].pose, kNear);
  const auto generate = [&](const RigidStep3& step, int threads, bool inpaint) {
    set_worker_threads(threads);
    GeneratedFrame g = extrapolate_by_motion(rendered, depth, camera, step, 2, inpaint, kNear);
    measure_generated_frame(depth, camera, viewer_step(f[1].pose, f[3].pose), now, g);
    set_worker_threads(1);
    return g;
  };
  const OnePass reference = paint_in_one_pass(rendered, depth, camera, back, 2);
  const GeneratedFrame one = generate(back, 1, false), three = generate(back, 3, false);
  EXPECT_TRUE(one.image.pixels() == reference.image);
  EXPECT_EQ(one.source, reference.source);
  EXPECT_EQ(one.pixels_written, reference.written);
  // The mask: each unreached pixel grown by 3 x 3.
  std::vector<char> grown(one.unreached.size(), 0);
  for (int y = 0; y < camera.height; ++y) {
    for (int x = 0; x < camera.width; ++x) {
      if (reference.source[static_cast<std::size_t>(y) * camera.width + x] >= 0) continue;
      for (int v = std::max(0, y - 1); v <= std::min(camera.height - 1, y + 1); ++v) {
        for (int u = std::max(0, x - 1); u <= std::min(camera.width - 1, x + 1); ++u) {
          grown[static_cast<std::size_t>(v) * camera.width + u] = 1;
        }
      }
    }
  }
  EXPECT_EQ(one.mask, grown);
  ASSERT_GT(one.hole_pixels, 0);
  const GeneratedFrame filled_one = generate(back, 1, true), filled = generate(back, 3, true);
  for (const GeneratedFrame* g : {&three, &filled}) {
    const GeneratedFrame& single = g == &three ? one : filled_one;
    EXPECT_TRUE(g->image.pixels() == single.image.pixels());
    EXPECT_EQ(g->source, single.source);
    EXPECT_EQ(g->unreached, single.unreached);
    EXPECT_EQ(g->mask, single.mask);
    EXPECT_EQ(g->hole_pixels, single.hole_pixels);
    EXPECT_EQ(g->mask_pixels, single.mask_pixels);
    EXPECT_EQ(g->inpainted_pixels, single.inpainted_pixels);
    EXPECT_EQ(g->pixels_written, single.pixels_written);
    EXPECT_EQ(g->max_error_px, single.max_error_px);
    EXPECT_EQ(g->mean_error_px, single.mean_error_px);
  }
  EXPECT_GT(filled.inpainted_pixels, 0);
  // Negative control: another motion gives another frame, and the comparisons see it.
  const RigidStep3 other = viewer_step(f[1].pose, f[2].pose);
  EXPECT_FALSE(generate(other, 3, false).image.pixels() == one.image.pixels());
  EXPECT_FALSE(paint_in_one_pass(rendered, depth, camera, other, 2).image == one.image.pixels());
}

TEST(FrameGeneration, BandsPaintTheOnePassFrameOnOneAndThreeThreads) {
  {
    SCOPED_TRACE("a slide");
    const ViewerPose ahead = look_at(Vec3(-0.3, 0.2, 3.5), Vec3(-0.3, 0.2, -1), Vec3(0, 1, 0));
    expect_bands_paint_the_one_pass_frame(
        expand_viewer_segments(ahead, {ViewerSegment{5, Vec3(0.3, 0.02, -0.05), Vec3(0.0)}}), true);
  }
  SCOPED_TRACE("a turn");
  expect_bands_paint_the_one_pass_frame(
      sliding_past(5, Vec3(0.3, 0.02, -0.05), Vec3(0, 0.02, 0.01)), false);
}

// Push-pull by its top-down definition: the colour of block (l, bx, by) is its pixel's at
// level 0, else the mean of its children's colours over the children with a valid pixel; a
// hole takes the colour of the smallest block around it that has one.
struct Quadtree {
  const Image& image;
  const std::vector<char>& hole;
  bool any(int l, int bx, int by) const {
    for (int y = by << l; y < std::min(image.height(), (by + 1) << l); ++y) {
      for (int x = bx << l; x < std::min(image.width(), (bx + 1) << l); ++x) {
        if (!hole[static_cast<std::size_t>(y) * image.width() + x]) return true;
      }
    }
    return false;
  }
  std::array<double, 4> colour(int l, int bx, int by) const {
    if (l == 0) {
      const Pixel p = image.at(bx, by);
      return {double(p.r), double(p.g), double(p.b), double(p.a)};
    }
    std::array<double, 4> sum{0, 0, 0, 0};
    int n = 0;
    for (int j = 0; j < 2; ++j) {
      for (int i = 0; i < 2; ++i) {
        const int cx = 2 * bx + i, cy = 2 * by + j;
        if ((cx << (l - 1)) >= image.width() || (cy << (l - 1)) >= image.height()) continue;
        if (!any(l - 1, cx, cy)) continue;
        const auto c = colour(l - 1, cx, cy);
        for (int k = 0; k < 4; ++k) sum[k] += c[k];
        ++n;
      }
    }
    for (double& v : sum) v /= n;
    return sum;
  }
};

TEST(PushPull, HolesTakeTheQuadtreeMeanOfTheSmallestBlockWithValidPixels) {
  std::mt19937 rng(7);
  for (const auto& [w, h] : {std::pair{8, 8}, std::pair{7, 5}, std::pair{16, 3}}) {
    Image image(w, h);
    std::vector<char> hole(image.pixel_count(), 0);
    for (std::size_t k = 0; k < hole.size(); ++k) {
      const std::uint8_t a = static_cast<std::uint8_t>(rng() % 256);
      image.pixels()[k] = Pixel{static_cast<std::uint8_t>(rng() % (a + 1)),
                                static_cast<std::uint8_t>(rng() % (a + 1)),
                                static_cast<std::uint8_t>(rng() % (a + 1)), a};
      hole[k] = rng() % 3 == 0;
    }
    for (int y = 0; y < std::min(h, 3); ++y) {
      for (int x = 0; x < 3; ++x) hole[static_cast<std::size_t>(y) * w + x] = 1;  // a block
    }
    const Image before = image;
    const Quadtree tree{before, hole};
    const long holes = std::count(hole.begin(), hole.end(), 1);
    EXPECT_EQ(push_pull_inpaint(image, hole), holes);
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        const Pixel got = image.at(x, y);
        if (!hole[static_cast<std::size_t>(y) * w + x]) {
          EXPECT_EQ(got, before.at(x, y));
          continue;
        }
        int l = 1;
        while (!tree.any(l, x >> l, y >> l)) ++l;
        const auto want = tree.colour(l, x >> l, y >> l);
        EXPECT_NEAR(got.r, want[0], 0.5 + 1e-9) << x << "," << y;
        EXPECT_NEAR(got.g, want[1], 0.5 + 1e-9);
        EXPECT_NEAR(got.b, want[2], 0.5 + 1e-9);
        EXPECT_NEAR(got.a, want[3], 0.5 + 1e-9);
      }
    }
  }
  Image none(4, 4);
  EXPECT_EQ(push_pull_inpaint(none, std::vector<char>(16, 1)), 0);  // nothing to pull from
}

TEST(FrameGeneration, MeasuredErrorNeverUnderReportsTheErrorReadFromTheImage) {
  const Scene scene = testing::with_coded_textures(cube_past_cube());
  SceneSettings settings;
  settings.engine.policy = &reuse_policy("mv-no-inpaint");
  settings.engine.cadence = 3;
  const std::vector<std::vector<ViewerFrame>> scripts = testing::three_motions_past();
  double largest = 0.0;
  int generated = 0;
  for (const auto& frames : scripts) {
    SceneEngine engine(scene, kCamera, settings);
    for (std::size_t i = 0; i < frames.size(); ++i) {
      const AnimationFrame r =
          i == 0 ? engine.start(frames[0].pose)
                 : engine.advance(frames[i - 1].pose, frames[i - 1].motion, frames[i].pose);
      const double seen =
          testing::coded_image_error(scene, kCamera, engine.frame(), frames[i].pose);
      EXPECT_GE(r.max_measured_error_px, seen - 0.25) << "frame " << i;
      if (i % 3 != 0) {
        ++generated;
        largest = std::max(largest, seen);
      } else {
        EXPECT_LT(seen, 0.75) << "a rendered frame, frame " << i;
      }
    }
  }
  EXPECT_GE(generated, 18);
  EXPECT_GT(largest, 1.0);  // the check has teeth: extrapolation is off by pixels somewhere
}

}  // namespace
}  // namespace oflab
