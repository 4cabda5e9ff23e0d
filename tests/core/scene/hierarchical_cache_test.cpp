// The hierarchical image cache's frame (core/scene/hierarchical_cache.h) against independent
// counts: the image size of its angle at a vertex against rays sampled around the vertex's
// ray, the per-vertex estimate against the measured error off the optical axis, the pixels a
// warp writes against the frame's pixel centres inside the node's image, and its holes
// against the exact frame of a content transparent inside its polygon.
#include "scene/hierarchical_cache.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "image/thread_pool.h"
#include "scene/depth_reprojection.h"
#include "scene_cases.h"

namespace oflab {
namespace {

using testing::scene_with;
using testing::square;

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegree = kPi / 180.0;

// Pixels at least half opaque in `image`.
long opaque_pixels(const Image& image) {
  long n = 0;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) n += image.at(x, y).a >= 128;
  }
  return n;
}

TEST(HierarchicalCacheErrors, AngleInPixelsIsTheFarthestProjectionOfTheRaysAtThatAngle) {
  const Camera camera = make_camera(700.0, 1280, 720);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 40; ++trial) {
    const Vec3 p(3.0 * u(rng), 2.0 * u(rng), 2.5 + u(rng));
    const double angle = (0.55 + 0.5 * u(rng)) * kDegree;
    // Rays at exactly `angle` from the ray to p, all around it, projected.
    const Vec3 d = glm::normalize(p);
    const Vec3 a =
        glm::normalize(glm::cross(d, std::abs(d.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0)));
    const Vec3 b = glm::cross(d, a);
    const Vec2 at = project_centred(camera, p);
    double farthest = 0.0;
    constexpr int kRays = 20000;
    for (int k = 0; k < kRays; ++k) {
      const double t = 2.0 * kPi * k / kRays;
      const Vec3 r = std::cos(angle) * d + std::sin(angle) * (std::cos(t) * a + std::sin(t) * b);
      farthest = std::max(farthest, double(glm::length(project_centred(camera, r) - at)));
    }
    const double size = angle_in_pixels(camera, p, angle);
    EXPECT_NEAR(size, farthest, 1e-6 * size) << "trial " << trial;
  }
  // On the axis it is f tan(angle); 48 degrees off it more than twice that (1 / cos^2 = 2.23).
  const double centre = 700.0 * std::tan(0.2 * kDegree);
  EXPECT_NEAR(angle_in_pixels(camera, Vec3(0, 0, 5), 0.2 * kDegree), centre, 1e-9);
  const double off = angle_in_pixels(camera, Vec3(std::tan(48.0 * kDegree), 0, 1), 0.2 * kDegree);
  EXPECT_GT(off, 2.2 * centre);
  EXPECT_LT(off, 2.3 * centre);
  // A ray within the angle of the image plane's horizon: unbounded.
  EXPECT_EQ(angle_in_pixels(camera, Vec3(1, 0, 1e-3), 0.2 * kDegree),
            std::numeric_limits<double>::infinity());
}

// One node of two parallel squares, 45 degrees off the axis, reused while the viewer moves
// sideways: the vertices' angles stay within the threshold (the box's corners are theirs), so
// the per-vertex estimate bounds the measured error; the threshold's size at the image centre
// does not.
TEST(HierarchicalCacheErrors, ThePerVertexEstimateBoundsTheErrorOffTheAxis) {
  const Scene scene =
      scene_with({square("far", Vec3(-4.0, 0, -5.5), Vec3(0, 0, 1), Vec3(0, 1, 0), 1.0),
                  square("near", Vec3(-4.0, 0, -4.0), Vec3(0, 0, 1), Vec3(0, 1, 0), 1.0)});
  const Camera camera = make_camera(250.0, 700, 200);
  const BspTree tree(scene.polygons);
  CacheSettings settings;
  settings.angle_deg = 0.5;
  settings.safety_radius = 1.0;  // the angle alone decides
  CacheContext context;
  context.guard_band = 2.0;
  HierarchicalCache cache(scene, camera, tree, settings, context);
  ASSERT_EQ(cache.nodes().size(), 1u);
  const std::vector<char> culled(2, 0);
  std::vector<Level> levels(2);
  Image frame(camera.width, camera.height);
  int reused = 0;
  double worst_over_centre = 0.0;
  for (int k = 0; k < 30; ++k) {
    const Vec3 eye(0.03 * k, 0.0, 0.0);
    AnimationFrame report;
    cache.frame(look_at(eye, eye + Vec3(0, 0, -1), Vec3(0, 1, 0)), culled, frame, levels, report);
    ASSERT_EQ(report.layer_reports.size(), 1u);
    const FrameReport& r = report.layer_reports[0];
    if (r.level != Level::kPerspective) continue;
    ++reused;
    EXPECT_LE(r.measured_error_px, r.estimated_error_px) << "frame " << k;
    worst_over_centre =
        std::max(worst_over_centre, r.measured_error_px / report.cache.threshold_px);
  }
  EXPECT_GT(reused, 10);
  // Control: the error passes the threshold's size at the image centre (the old estimate).
  EXPECT_GT(worst_over_centre, 1.0);
}

// A square reaching past the frame's right edge (within the guard band): reused by a still
// viewer, its warp writes exactly the frame's pixel centres inside its image's region (the
// projected box), none beyond the frame.
TEST(HierarchicalCacheEngine, AWarpWritesOnlyThePixelsInTheFrame) {
  const Scene scene =
      scene_with({square("wide", Vec3(0.93, 0.02, 0), Vec3(0, 0, 1), Vec3(0, 1, 0), 1.0)});
  const Camera camera = make_camera(300.0, 160, 120);
  const BspTree tree(scene.polygons);
  HierarchicalCache cache(scene, camera, tree, CacheSettings{}, CacheContext{});
  const ViewerPose view = look_at(Vec3(0, 0, 4.1), Vec3(0, 0, 0), Vec3(0, 1, 0));
  const std::vector<char> culled(1, 0);
  std::vector<Level> levels(1);
  Image frame(camera.width, camera.height);
  AnimationFrame first, second;
  cache.frame(view, culled, frame, levels, first);
  cache.frame(view, culled, frame, levels, second);
  ASSERT_EQ(second.cache.rendered, 0);
  // The region: the square's corners projected (a rectangle), pixel centres counted inside.
  double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
  for (const Vec3& c : cache.nodes()[0].corners()) {
    const Vec2 q = centred_to_pixel(camera, project_centred(camera, to_view(view, c)));
    x0 = std::min(x0, q.x), x1 = std::max(x1, q.x), y0 = std::min(y0, q.y), y1 = std::max(y1, q.y);
  }
  long in_frame = 0, anywhere = 0;
  for (int y = -200; y < 400; ++y) {
    for (int x = -200; x < 400; ++x) {
      const bool inside = x + 0.5 >= x0 && x + 0.5 < x1 && y + 0.5 >= y0 && y + 0.5 < y1;
      anywhere += inside;
      in_frame += inside && x < camera.width && y < camera.height && x >= 0 && y >= 0;
    }
  }
  ASSERT_GT(anywhere, in_frame + 500);  // the region does reach beyond the frame
  EXPECT_EQ(second.pixels_written, in_frame);
  EXPECT_EQ(second.layer_reports.at(0).pixels_written, in_frame);
  EXPECT_DOUBLE_EQ(second.model_work, in_frame * kPerspectiveWarpCost);
}

// A texture transparent on its left half: the depth sees the polygon there, the exact frame
// does not. Every hole the cache reports is a pixel the exact frame covers and the shown frame
// does not, frame by frame, with the viewer moving so that node images drift.
TEST(HierarchicalCacheEngine, HolesAreWhereTheExactFrameIsOpaqueAndNoNodeImageIs) {
  Scene scene =
      scene_with({square("far", Vec3(0, 0, -1.5), Vec3(0, 0, 1), Vec3(0, 1, 0), 2.0),
                  square("near", Vec3(0.4, 0.1, 0.0), Vec3(0, 0, 1), Vec3(0, 1, 0), 0.8)});
  Image& texture = scene.textures[0];
  for (int y = 0; y < texture.height(); ++y) {
    for (int x = 0; x < texture.width() / 2; ++x) texture.at(x, y) = Pixel{};
  }
  const Camera camera = make_camera(300.0, 200, 150);
  const BspTree tree(scene.polygons);
  CacheSettings settings;
  settings.angle_deg = 3.0;  // loose: the node images drift by pixels before a render
  settings.max_node_polygons = 2;
  settings.safety_radius = 10.0;
  const std::vector<char> culled(2, 0);
  std::vector<Level> levels(2);
  HierarchicalCache cache(scene, camera, tree, settings, CacheContext{});
  long holes = 0, reused = 0;
  for (int k = 0; k < 12; ++k) {
    const ViewerPose view = look_at(Vec3(0.03 * k, 0.1, 4.0), Vec3(0.0, 0.0, 0.0), Vec3(0, 1, 0));
    Image shown(camera.width, camera.height), exact(camera.width, camera.height);
    AnimationFrame report, fresh_report;
    cache.frame(view, culled, shown, levels, report);
    HierarchicalCache fresh(scene, camera, tree, settings, CacheContext{});
    fresh.frame(view, culled, exact, levels, fresh_report);
    EXPECT_EQ(fresh_report.hole_pixels, 0) << "frame " << k;
    if (k == 0) {
      // Control: the depth counts the transparent half as surface.
      const long depth = render_depth(scene, camera, view, 0.05).covered();
      EXPECT_GT(depth, opaque_pixels(exact) + 2000);
    }
    long expected = 0;
    for (int y = 0; y < camera.height; ++y) {
      for (int x = 0; x < camera.width; ++x) {
        expected += exact.at(x, y).a >= 128 && shown.at(x, y).a < 128;
      }
    }
    EXPECT_EQ(report.hole_pixels, expected) << "frame " << k;
    holes += report.hole_pixels;
    reused += report.cache.rendered == 0;
  }
  EXPECT_GT(reused, 5);
  EXPECT_GT(holes, 0);  // the drifting images do leave holes: the equality is not 0 == 0
}

// The per-pixel error pass runs in bands of rows on the worker threads, its errors summed in
// raster order: the frames and every figure of the reports are the same on 1 thread and on
// 3, over frames where reused node images drift (so the figures are not all zero).
TEST(HierarchicalCacheEngine, TheSameOnOneAndThreeThreads) {
  const Scene scene =
      scene_with({square("far", Vec3(0, 0, -1.5), Vec3(0, 0, 1), Vec3(0, 1, 0), 2.0),
                  square("near", Vec3(0.4, 0.1, 0.0), Vec3(0, 0.3, 1), Vec3(0, 1, 0), 0.8)});
  const Camera camera = make_camera(400.0, 320, 240);
  ASSERT_GT(band_count(camera.height, 32), 2);
  const BspTree tree(scene.polygons);
  CacheSettings settings;
  settings.angle_deg = 3.0;
  settings.max_node_polygons = 1;
  const std::vector<char> culled(2, 0);
  std::vector<Level> levels(2);
  const auto play = [&](int threads) {
    set_worker_threads(threads);
    HierarchicalCache cache(scene, camera, tree, settings, CacheContext{});
    std::vector<std::pair<Image, NodeCacheFrame>> frames;
    for (int k = 0; k < 10; ++k) {
      const ViewerPose view = look_at(Vec3(0.04 * k, 0.1, 4.0), Vec3(0, 0, 0), Vec3(0, 1, 0));
      Image shown(camera.width, camera.height);
      AnimationFrame report;
      cache.frame(view, culled, shown, levels, report);
      frames.emplace_back(shown, report.cache);
    }
    set_worker_threads(1);
    return frames;
  };
  const auto one = play(1), three = play(3);
  double largest = 0.0;
  for (size_t k = 0; k < one.size(); ++k) {
    EXPECT_EQ(one[k].first.pixels(), three[k].first.pixels()) << "frame " << k;
    const NodeCacheFrame &a = one[k].second, &b = three[k].second;
    EXPECT_EQ(a.error_pixels, b.error_pixels) << "frame " << k;
    EXPECT_EQ(a.overlap_pixels, b.overlap_pixels) << "frame " << k;
    EXPECT_EQ(a.max_pixel_error_px, b.max_pixel_error_px) << "frame " << k;
    EXPECT_EQ(a.mean_pixel_error_px, b.mean_pixel_error_px) << "frame " << k;
    largest = std::max(largest, a.max_pixel_error_px);
  }
  EXPECT_GT(largest, 0.1);  // reused images did drift: the figures compared are not all zero
}

}  // namespace
}  // namespace oflab
