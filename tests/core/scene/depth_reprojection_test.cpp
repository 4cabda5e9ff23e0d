// Per-pixel depth reprojection and the automatic stabilization plane
// (core/scene/depth_reprojection.h) against independent computations: rays intersected with
// the polygons in world coordinates, a brute-force least-squares check, and the exact
// projection of every source pixel's surface point.
#include "scene/depth_reprojection.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "image/thread_pool.h"
#include "scene_cases.h"

namespace oflab {
namespace {

using testing::scene_with;
using testing::square;
using testing::world_point_at;

const Camera kCamera = make_camera(300.0, 160, 120);
constexpr double kNear = 0.05;

// Two squares, the near one partly in front of the far one.
Scene two_squares() {
  return scene_with({square("far", Vec3(0.0, 0.0, -2.0), Vec3(0, 0, 1), Vec3(0, 1, 0), 2.0),
                     square("near", Vec3(0.3, 0.1, 0.0), Vec3(0, 0, 1), Vec3(0, 1, 0), 0.6)});
}

TEST(DepthReprojection, DepthIsTheRaysHitOfTheNearestPolygon) {
  const Scene scene = two_squares();
  const ViewerPose view = look_at(Vec3(0.2, 0.3, 3.0), Vec3(0, 0, -1), Vec3(0, 1, 0));
  const DepthFrame depth = render_depth(scene, kCamera, view, kNear);
  int both = 0, near = 0;
  for (int y = 0; y < kCamera.height; ++y) {
    for (int x = 0; x < kCamera.width; ++x) {
      const int k = y * kCamera.width + x;
      const int p = depth.polygon[k];
      if (p < 0) continue;
      const Vec3 hit = world_point_at(kCamera, scene.polygons[p], view, x + 0.5, y + 0.5);
      EXPECT_NEAR(depth.inverse_depth[k], 1.0 / to_view(view, hit).z, 1e-9);
      near += p == 1;
      ++both;
    }
  }
  EXPECT_GT(near, 100);
  EXPECT_GT(both, near + 100);
}

TEST(DepthReprojection, AutomaticPlaneOfOnePlaneIsThePlane) {
  const Scene scene = scene_with(
      {square("tilted", Vec3(0, 0, 0), glm::normalize(Vec3(0.3, 0.2, 1.0)), Vec3(0, 1, 0), 2.0)});
  const ViewerPose view = look_at(Vec3(0.5, 0.2, 3.0), Vec3(0, 0, 0), Vec3(0, 1, 0));
  Vec3 m(0.0);
  ASSERT_TRUE(fit_inverse_depth_plane(render_depth(scene, kCamera, view, kNear), kCamera, m));
  const Vec3 expected = plane_vector_of(to_view(view, scene.polygons[0].centre),
                                        direction_to_view(view, scene.polygons[0].front));
  EXPECT_LT(glm::length(m - expected), 1e-9 * glm::length(expected));
}

double squared_residual(const DepthFrame& depth, const Vec3& m) {
  double sum = 0.0;
  for (int y = 0; y < depth.height; ++y) {
    for (int x = 0; x < depth.width; ++x) {
      const int k = y * depth.width + x;
      if (depth.polygon[k] < 0) continue;
      const Vec3 d((x + 0.5 - kCamera.cx) / kCamera.focal_px,
                   (y + 0.5 - kCamera.cy) / kCamera.focal_px, 1.0);
      const double r = depth.inverse_depth[k] - glm::dot(m, d);
      sum += r * r;
    }
  }
  return sum;
}

TEST(DepthReprojection, AutomaticPlaneIsTheLeastSquaresFitOfInverseDepth) {
  const DepthFrame depth = render_depth(
      two_squares(), kCamera, look_at(Vec3(0.2, 0.3, 3.0), Vec3(0, 0, -1), Vec3(0, 1, 0)), kNear);
  Vec3 m(0.0);
  ASSERT_TRUE(fit_inverse_depth_plane(depth, kCamera, m));
  const double best = squared_residual(depth, m);
  for (int axis = 0; axis < 3; ++axis) {
    for (double step : {-1e-3, 1e-3}) {
      Vec3 other = m;
      other[axis] += step;
      EXPECT_GT(squared_residual(depth, other), best);
    }
  }
}

TEST(DepthReprojection, PerPixelErrorIsTheDistanceToTheIndependentProjection) {
  const Scene scene = two_squares();
  const ViewerPose then = look_at(Vec3(0.2, 0.3, 3.0), Vec3(0, 0, -1), Vec3(0, 1, 0));
  const ViewerPose now = look_at(Vec3(0.35, 0.25, 2.8), Vec3(0.05, 0, -1), Vec3(0, 1, 0));
  const DepthFrame depth = render_depth(scene, kCamera, then, kNear);
  const Image rendered = testing::ray_cast_scene(scene, kCamera, then, kNear);
  const DepthFrame seen_now = render_depth(scene, kCamera, now, kNear);
  const Reprojection r = reproject_by_depth(rendered, depth, kCamera, viewer_step(then, now),
                                            HoleFill::kNone, kNear, &seen_now);
  double largest = 0.0;
  int checked = 0;
  for (int d = 0; d < kCamera.width * kCamera.height; ++d) {
    const int s = r.source[d];
    if (s < 0 || depth.polygon[s] < 0) continue;
    const Vec3 hit = world_point_at(kCamera, scene.polygons[depth.polygon[s]], then,
                                    s % kCamera.width + 0.5, s / kCamera.width + 0.5);
    const Vec2 exact = centred_to_pixel(kCamera, project_centred(kCamera, to_view(now, hit)));
    const double e = glm::length(Vec2(d % kCamera.width + 0.5, d / kCamera.width + 0.5) - exact);
    largest = std::max(largest, e);
    // Nearest-neighbour resampling of a splat grown by kSplatMargin: within the grown
    // footprint's half-diagonal at this step's small magnification (below 1.3).
    EXPECT_LT(e, (0.5 + kSplatMargin) * std::sqrt(2.0) * 1.3);
    ++checked;
  }
  EXPECT_GT(checked, 1000);
  EXPECT_NEAR(r.max_error_px, largest, 1e-9);
  // The near square moved against the far one: what it hid is now a hole.
  EXPECT_GT(r.hole_pixels, 0);
}

TEST(DepthReprojection, AZoomingPlaneHasNoHoles) {
  const Scene scene =
      scene_with({square("plane", Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(0, 1, 0), 1.0)});
  const ViewerPose then = look_at(Vec3(0.0, 0.0, 3.0), Vec3(0, 0, 0), Vec3(0, 1, 0));
  for (double z : {2.0, 2.5, 3.5, 4.0}) {  // magnified up to 1.5x, and minified
    const ViewerPose now = look_at(Vec3(0.05, 0.0, z), Vec3(0.05, 0, 0), Vec3(0, 1, 0));
    const DepthFrame seen_now = render_depth(scene, kCamera, now, kNear);
    const Reprojection r =
        reproject_by_depth(testing::ray_cast_scene(scene, kCamera, then, kNear),
                           render_depth(scene, kCamera, then, kNear), kCamera,
                           viewer_step(then, now), HoleFill::kNone, kNear, &seen_now);
    EXPECT_EQ(r.hole_pixels, 0) << "viewer at z = " << z;
  }
}

TEST(DepthReprojection, FillModesPaintOnlyTheUnreachedPixels) {
  const Scene scene = two_squares();
  const ViewerPose then = look_at(Vec3(0.2, 0.3, 3.0), Vec3(0, 0, -1), Vec3(0, 1, 0));
  const ViewerPose now = look_at(Vec3(0.5, 0.3, 3.0), Vec3(0.3, 0, -1), Vec3(0, 1, 0));
  const Image rendered = testing::ray_cast_scene(scene, kCamera, then, kNear);
  const DepthFrame depth = render_depth(scene, kCamera, then, kNear);
  const RigidStep3 step = viewer_step(then, now);
  const Reprojection none =
      reproject_by_depth(rendered, depth, kCamera, step, HoleFill::kNone, kNear);
  ASSERT_GT(none.hole_pixels, 0);
  for (HoleFill fill : {HoleFill::kStretch, HoleFill::kBackground}) {
    const Reprojection filled = reproject_by_depth(rendered, depth, kCamera, step, fill, kNear);
    EXPECT_EQ(filled.hole, none.hole) << hole_fill_name(fill);
    EXPECT_EQ(filled.hole_pixels, none.hole_pixels);
    for (std::size_t k = 0; k < none.unreached.size(); ++k) {
      if (!none.unreached[k]) {
        ASSERT_EQ(filled.image.pixels()[k], none.image.pixels()[k]);
      } else {
        EXPECT_EQ(none.image.pixels()[k], Pixel{});
        if (fill == HoleFill::kBackground) EXPECT_EQ(filled.image.pixels()[k], kHoleBackground);
      }
    }
  }
  HoleFill parsed = HoleFill::kNone;
  EXPECT_TRUE(parse_hole_fill("stretch", parsed));
  EXPECT_EQ(parsed, HoleFill::kStretch);
  EXPECT_FALSE(parse_hole_fill("blur", parsed));
}

// The forward splatting as the header states it, written out once more as plainly as it
// reads: one pass over the source pixels in order, each pixel's centre moved by its own
// inverse depth, its footprint's four corners moved each on its own with its surface's plane
// (no corner lattice, no plan, no bands), every pixel centre of the footprint's bounding box
// tested against its four edges, the nearest surface winning and, among one polygon's
// splats, the one landing nearest.
struct ReferenceSplats {
  std::vector<Pixel> image;
  std::vector<int> source;
  std::int64_t written = 0;
};

bool reference_move(const Camera& c, const RigidStep3& step, const Vec3& m, double w, double u,
                    double v, Vec2& q, double& moved_w) {
  const Vec3 d((u - c.cx) / c.focal_px, (v - c.cy) / c.focal_px, 1.0);
  Vec3 x;
  if (m == Vec3(0.0)) {
    x = step.rotation * d;
    if (!(x.z > 1e-9)) return false;
    moved_w = 0.0;
  } else {
    if (!(w > 0.0)) return false;
    x = step.rotation * (d / w) + step.translation;
    if (!(x.z > kNear)) return false;
    moved_w = 1.0 / x.z;
  }
  q = Vec2(c.cx + c.focal_px * x.x / x.z, c.cy + c.focal_px * x.y / x.z);
  return true;
}

bool reference_inside(const std::array<Vec2, 4>& q, const Vec2& c) {
  bool positive = true, negative = true;
  for (int e = 0; e < 4; ++e) {
    const Vec2 edge = q[(e + 1) % 4] - q[e];
    const double k = edge.x * (c.y - q[e].y) - edge.y * (c.x - q[e].x);
    positive = positive && k >= -1e-9;
    negative = negative && k <= 1e-9;
  }
  return positive || negative;
}

// Source pixel (i, j)'s footprint corners moved with plane m, and the centres its bounding
// box holds ([x0, x1] x [y0, y1]); false when it has none or a corner cannot move.
bool reference_footprint(const Camera& c, const RigidStep3& step, const Vec3& m, int i, int j,
                         std::array<Vec2, 4>& q, std::array<int, 4>& box) {
  const double u[4] = {i - 0.5, i + 1.5, i + 1.5, i - 0.5},
               v[4] = {j - 0.5, j - 0.5, j + 1.5, j + 1.5};
  double lo_x = 1e300, hi_x = -1e300, lo_y = 1e300, hi_y = -1e300, unused = 0.0;
  for (int k = 0; k < 4; ++k) {
    const double w = glm::dot(m, Vec3((u[k] - c.cx) / c.focal_px, (v[k] - c.cy) / c.focal_px, 1.0));
    if (!reference_move(c, step, m, w, u[k], v[k], q[k], unused)) return false;
    lo_x = std::min(lo_x, q[k].x), hi_x = std::max(hi_x, q[k].x);
    lo_y = std::min(lo_y, q[k].y), hi_y = std::max(hi_y, q[k].y);
  }
  box = {
      std::max(0, int(std::ceil(lo_x - 0.5))), std::min(c.width - 1, int(std::floor(hi_x - 0.5))),
      std::max(0, int(std::ceil(lo_y - 0.5))), std::min(c.height - 1, int(std::floor(hi_y - 0.5)))};
  return box[1] >= box[0] && box[3] >= box[2] &&
         double(box[1] - box[0] + 1) * (box[3] - box[2] + 1) <= 4096.0;
}

ReferenceSplats reference_splats(const Image& rendered, const DepthFrame& depth, const Camera& c,
                                 const RigidStep3& step) {
  const std::size_t n = static_cast<std::size_t>(c.width) * c.height;
  ReferenceSplats r{std::vector<Pixel>(n, Pixel{}), std::vector<int>(n, -1), 0};
  std::vector<double> z(n, -1.0), dist(n, 0.0);
  for (int s = 0; s < static_cast<int>(n); ++s) {
    const int i = s % c.width, j = s / c.width, p = depth.polygon[s];
    const Vec3 m = p >= 0 ? depth.planes[p] : Vec3(0.0);
    Vec2 landed;
    double centre_w = 0.0;
    std::array<Vec2, 4> q;
    std::array<int, 4> box;
    if (!reference_move(c, step, m, depth.inverse_depth[s], i + 0.5, j + 0.5, landed, centre_w) ||
        !reference_footprint(c, step, m, i, j, q, box)) {
      continue;
    }
    for (int y = box[2]; y <= box[3]; ++y) {
      for (int x = box[0]; x <= box[1]; ++x) {
        const Vec2 centre(x + 0.5, y + 0.5);
        const int d = y * c.width + x;
        if (!reference_inside(q, centre)) continue;
        const bool same = r.source[d] >= 0 && depth.polygon[r.source[d]] == p;
        const double e = glm::dot(centre - landed, centre - landed);
        if (same ? e >= dist[d] : centre_w <= z[d]) continue;
        z[d] = centre_w, dist[d] = e, r.source[d] = s, r.image[d] = rendered.pixels()[s];
        ++r.written;
      }
    }
  }
  return r;
}

// The banded, planned splatting (shared corners, spans decided row by row, on 2 threads) paints
// the same frame to the bit as the plain one-pass reference, under a translation with a turn
// (the near square disoccludes the far one), a zoom, a rotation that moves the background,
// and a translation without rotation (the background's footprints exactly axis-aligned).
TEST(DepthReprojection, PaintsWhatTheOnePassReferencePaints) {
  const Scene scene = two_squares();
  const ViewerPose then = look_at(Vec3(0.25, 0.5, 3.0), Vec3(0.25, 0.5, -1), Vec3(0, 1, 0));
  const Image rendered = testing::ray_cast_scene(scene, kCamera, then, kNear);
  const DepthFrame depth = render_depth(scene, kCamera, then, kNear);
  const ViewerPose steps[] = {look_at(Vec3(0.45, 0.25, 2.9), Vec3(0.2, 0, -1), Vec3(0, 1, 0)),
                              look_at(Vec3(0.2, 0.3, 2.2), Vec3(0, 0, -1), Vec3(0, 1, 0)),
                              look_at(Vec3(0.2, 0.3, 3.0), Vec3(-0.6, 0.2, -1), Vec3(0.1, 1, 0)),
                              look_at(Vec3(0.5, 0.4, 3.0), Vec3(0.5, 0.4, -1), Vec3(0, 1, 0))};
  // The last step turns nothing, to the bit (so the background's corners stay on a grid).
  ASSERT_EQ(viewer_step(then, steps[3]).rotation, Mat3(1.0));
  set_worker_threads(2);
  for (const ViewerPose& now : steps) {
    const RigidStep3 step = viewer_step(then, now);
    const Reprojection r =
        reproject_by_depth(rendered, depth, kCamera, step, HoleFill::kNone, kNear);
    const ReferenceSplats expected = reference_splats(rendered, depth, kCamera, step);
    ASSERT_GT(expected.written, kCamera.width * kCamera.height);
    EXPECT_EQ(r.image.pixels(), expected.image);
    EXPECT_EQ(r.source, expected.source);
    EXPECT_EQ(r.pixels_written, expected.written);
  }
  // Negative control: the reference of another step is another frame, and the comparison
  // sees it.
  const Reprojection r = reproject_by_depth(rendered, depth, kCamera, viewer_step(then, steps[0]),
                                            HoleFill::kNone, kNear);
  EXPECT_NE(r.source,
            reference_splats(rendered, depth, kCamera, viewer_step(then, steps[1])).source);
  set_worker_threads(1);
}

// Without rotation the background is painted pixel by pixel in each band, after the
// surfaces: on 3 threads and many bands the frame is still the one-pass reference's.
TEST(DepthReprojection, TheBackgroundWithoutTurningIsTheReferencesOnThreeThreads) {
  const Camera camera = make_camera(600.0, 640, 480);  // cut into many bands
  const Scene scene = two_squares();
  const ViewerPose then = look_at(Vec3(0.25, 0.5, 3.0), Vec3(0.25, 0.5, -1), Vec3(0, 1, 0));
  const ViewerPose now = look_at(Vec3(0.5, 0.4, 2.9), Vec3(0.5, 0.4, -1), Vec3(0, 1, 0));
  const RigidStep3 step = viewer_step(then, now);
  ASSERT_EQ(step.rotation, Mat3(1.0));
  ASSERT_GT(band_count(camera.height, 4), 1);
  const Image rendered = testing::ray_cast_scene(scene, camera, then, kNear);
  const DepthFrame depth = render_depth(scene, camera, then, kNear);
  set_worker_threads(3);
  const Reprojection r = reproject_by_depth(rendered, depth, camera, step, HoleFill::kNone, kNear);
  set_worker_threads(1);
  const ReferenceSplats expected = reference_splats(rendered, depth, camera, step);
  EXPECT_EQ(r.image.pixels(), expected.image);
  EXPECT_EQ(r.source, expected.source);
  EXPECT_EQ(r.pixels_written, expected.written);
}

// The splats are planned and painted in bands of rows on the worker threads: the frame, its
// sources, holes, writes and errors are the same bytes on 1 thread and on 3.
TEST(DepthReprojection, TheSameOnOneAndThreeThreads) {
  const Camera camera = make_camera(600.0, 640, 480);  // cut into many bands
  const Scene scene = two_squares();
  const ViewerPose then = look_at(Vec3(0.2, 0.3, 3.0), Vec3(0, 0, -1), Vec3(0, 1, 0));
  const Image rendered = testing::ray_cast_scene(scene, camera, then, kNear);
  const DepthFrame depth = render_depth(scene, camera, then, kNear);
  const auto reproject = [&](double x, int threads) {
    set_worker_threads(threads);
    const ViewerPose now = look_at(Vec3(x, 0.3, 2.6), Vec3(0.3, 0, -1), Vec3(0, 1, 0));
    const DepthFrame seen = render_depth(scene, camera, now, kNear);
    Reprojection r = reproject_by_depth(rendered, depth, camera, viewer_step(then, now),
                                        HoleFill::kStretch, kNear, &seen);
    set_worker_threads(1);
    return r;
  };
  ASSERT_GT(band_count(camera.height, 4), 1);
  const Reprojection one = reproject(0.5, 1), three = reproject(0.5, 3);
  ASSERT_GT(one.hole_pixels, 0);
  EXPECT_EQ(one.image.pixels(), three.image.pixels());
  EXPECT_EQ(one.source, three.source);
  EXPECT_EQ(one.hole, three.hole);
  EXPECT_EQ(one.hole_pixels, three.hole_pixels);
  EXPECT_EQ(one.pixels_written, three.pixels_written);
  EXPECT_EQ(one.max_error_px, three.max_error_px);
  EXPECT_EQ(one.mean_error_px, three.mean_error_px);
  // Negative control: another step gives another frame, and the comparison sees it.
  EXPECT_NE(reproject(0.52, 3).image.pixels(), one.image.pixels());
}

}  // namespace
}  // namespace oflab
