// View interpolation between two renders (core/scene/view_interpolation.h) and the scene
// engine's view-interpolation policy, against independent computations: world points found by
// rays in world coordinates and projected exactly, the disoccluded pixels of each render found
// the same way, the error read back from texel-coded images, and an exact re-render.
#include "scene/view_interpolation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "scene/scene_animator.h"
#include "scene_cases.h"

namespace oflab {
namespace {

using testing::open_cube;
using testing::project_world;
using testing::scene_with;
using testing::sliding_past;
using testing::world_point_at;

const Camera kCamera = make_camera(150.0, 160, 120);
constexpr double kNear = 0.05;

// The near cube sliding past the far one (testing::cube_past_cube), texel-coded.
Scene coded_cube_past_cube() { return testing::with_coded_textures(testing::cube_past_cube()); }

// Whether the surface point seen now at pixel centre d (polygon p, world point x) is seen by
// the render from `then`: its projection there falls in the frame on a pixel showing p.
bool seen_by(const DepthFrame& then_depth, const ViewerPose& then, int p, const Vec3& x) {
  const Vec2 q = project_world(kCamera, then, x);
  const int i = static_cast<int>(std::floor(q.x)), j = static_cast<int>(std::floor(q.y));
  if (i < 0 || j < 0 || i >= kCamera.width || j >= kCamera.height) return false;
  return then_depth.polygon[static_cast<std::size_t>(j) * kCamera.width + i] == p;
}

struct Renders {
  Image image[2];
  DepthFrame depth[2];
  ViewerPose view[2];
};

Renders render_both(const Scene& scene, const ViewerPose& a, const ViewerPose& b) {
  Renders r;
  r.view[0] = a;
  r.view[1] = b;
  for (int k = 0; k < 2; ++k) {
    r.image[k] = testing::ray_cast_scene(scene, kCamera, r.view[k], kNear);
    r.depth[k] = render_depth(scene, kCamera, r.view[k], kNear);
  }
  return r;
}

// Whether pixel d of g and its eight neighbours all show polygon p from render `from`.
bool interior(const InterpolatedFrame& g, const Renders& r, std::size_t d, int from, int p) {
  const int x = static_cast<int>(d % kCamera.width), y = static_cast<int>(d / kCamera.width);
  for (int j = y - 1; j <= y + 1; ++j) {
    for (int i = x - 1; i <= x + 1; ++i) {
      if (i < 0 || j < 0 || i >= kCamera.width || j >= kCamera.height) return false;
      const std::size_t n = static_cast<std::size_t>(j) * kCamera.width + i;
      if (g.source[n] < 0 || g.from_later[n] != from) return false;
      if (r.depth[from].polygon[g.source[n]] != p) return false;
    }
  }
  return true;
}

InterpolatedFrame interpolate(const Renders& r, const ViewerPose& now, double t,
                              const DepthFrame* seen_now) {
  return interpolate_views(RenderedView{r.image[0], r.depth[0], viewer_step(r.view[0], now)},
                           RenderedView{r.image[1], r.depth[1], viewer_step(r.view[1], now)}, t,
                           kCamera, kNear, seen_now);
}

TEST(ViewInterpolation, APlaneMovedToTheViewNowGivesTheInverseDepthOfTheRayThere) {
  const Scene scene = coded_cube_past_cube();
  const auto f = sliding_past(4, Vec3(0.1, 0.02, -0.05), Vec3(0.01, 0.03, 0));
  const DepthFrame then = render_depth(scene, kCamera, f[0].pose, kNear);
  const RigidStep3 step = viewer_step(f[0].pose, f[3].pose);
  int checked = 0;
  for (std::size_t p = 0; p < scene.polygons.size(); ++p) {
    if (then.planes[p] == Vec3(0.0)) continue;
    for (const Vec2 uv : {Vec2(20.5, 30.5), Vec2(80.5, 60.5), Vec2(140.5, 100.5), Vec2(60.5, 90.5),
                          Vec2(110.5, 20.5)}) {
      const Vec3 x = world_point_at(kCamera, scene.polygons[p], f[3].pose, uv.x, uv.y);
      const double z = to_view(f[3].pose, x).z;
      if (!(z > kNear && z < 1e3)) continue;  // the ray meets the plane ahead, not edge-on
      EXPECT_NEAR(moved_plane_inverse_depth(kCamera, then.planes[p], step, uv.x, uv.y), 1.0 / z,
                  1e-9 / z)
          << "polygon " << p;
      ++checked;
    }
  }
  EXPECT_GE(checked, 10);
  EXPECT_EQ(moved_plane_inverse_depth(kCamera, Vec3(0.0), step, 10.5, 10.5), 0.0);
}

TEST(ViewInterpolation, PixelsSeenByBothRendersLandWhereTheExactProjectionPutsThem) {
  const Scene scene = coded_cube_past_cube();
  // A slide with a turn and a push: not a motion parallel to the image plane.
  const auto f = sliding_past(5, Vec3(0.12, 0, -0.06), Vec3(0, 0.02, 0.01));  // frames 0..4
  const Renders r = render_both(scene, f[0].pose, f[4].pose);
  for (int k = 1; k <= 3; ++k) {
    const DepthFrame now = render_depth(scene, kCamera, f[k].pose, kNear);
    const InterpolatedFrame g = interpolate(r, f[k].pose, k / 4.0, &now);
    long both = 0;
    double worst = 0.0;
    for (std::size_t d = 0; d < g.source.size(); ++d) {
      const int s = g.source[d];
      if (s < 0) continue;
      const int from = g.from_later[d];
      const int p = r.depth[from].polygon[s];
      if (p < 0) continue;
      // The surface point at the source pixel's centre, found in world coordinates.
      const Vec3 x = world_point_at(kCamera, scene.polygons[p], r.view[from],
                                    s % kCamera.width + 0.5, s / kCamera.width + 0.5);
      const double e =
          glm::length(project_world(kCamera, f[k].pose, x) -
                      Vec2(static_cast<double>(d % kCamera.width) + 0.5, d / kCamera.width + 0.5));
      worst = std::max(worst, e);
      if (!seen_by(r.depth[1 - from], r.view[1 - from], p, x)) continue;
      ++both;
      // Inside a surface (its 3 x 3 neighbours shown from the same render and polygon) the
      // pixel shows the splat landing nearest its centre: within half a pixel's diagonal of
      // the motion's slight magnification; at a silhouette the splat's margin (half a source
      // pixel, magnified on a face seen obliquely) may overshoot.
      EXPECT_LT(e, interior(g, r, d, from, p) ? 0.75 : 2.0) << "pixel " << d << ", k = " << k;
    }
    EXPECT_GT(both, 2000) << "k = " << k;
    EXPECT_NEAR(g.max_error_px, worst, 1e-6) << "k = " << k;
    // And read back from the image alone: every texel shown sits where it projects now.
    EXPECT_LT(testing::coded_image_error(scene, kCamera, g.image, f[k].pose), 2.0) << "k = " << k;
  }
}

TEST(ViewInterpolation, TwoViewsLeaveFewerHolesThanEitherAtACubesDisocclusion) {
  // A near cube before a wall, the viewer sliding past: each render alone uncovers the wall
  // on one side of the cube, the other render saw it.
  std::vector<ScenePolygon> polygons = open_cube("near", Vec3(0, 0, 0), 0.8);
  polygons.push_back(testing::square("wall", Vec3(0, 0, -3), Vec3(0, 0, 1), Vec3(0, 1, 0), 8.0));
  const Scene scene = scene_with(polygons);
  const auto f = sliding_past(3, Vec3(0.3, 0, 0), Vec3(0.0));  // 6 px a frame past the wall
  const Renders r = render_both(scene, f[0].pose, f[2].pose);
  const DepthFrame now = render_depth(scene, kCamera, f[1].pose, kNear);
  const InterpolatedFrame g = interpolate(r, f[1].pose, 0.5, &now);
  // Each render alone, reprojected to the view between (the negative control).
  long single_holes[2];
  double single_mismatch[2];
  const Image exact = testing::ray_cast_scene(scene, kCamera, f[1].pose, kNear);
  for (int k = 0; k < 2; ++k) {
    const Reprojection one =
        reproject_by_depth(r.image[k], r.depth[k], kCamera, viewer_step(r.view[k], f[1].pose),
                           HoleFill::kNone, kNear, &now);
    single_holes[k] = one.hole_pixels;
    single_mismatch[k] = testing::mismatch_fraction(one.image, exact, 8);
  }
  // What neither render saw, found by rays: the merged frame's holes are no more than that
  // (and a ring of half a pixel of splat margin).
  long unseen_by_both = 0, seen_by_one = 0;
  for (std::size_t d = 0; d < now.polygon.size(); ++d) {
    const int p = now.polygon[d];
    if (p < 0) continue;
    const Vec3 x = world_point_at(kCamera, scene.polygons[p], f[1].pose, d % kCamera.width + 0.5,
                                  d / kCamera.width + 0.5);
    const bool seen = seen_by(r.depth[0], r.view[0], p, x) || seen_by(r.depth[1], r.view[1], p, x);
    unseen_by_both += !seen;
    seen_by_one += seen && g.unreached[d];
  }
  EXPECT_GT(single_holes[0], 40);
  EXPECT_GT(single_holes[1], 40);
  EXPECT_EQ(g.earlier_hole_pixels, single_holes[0]);
  EXPECT_EQ(g.later_hole_pixels, single_holes[1]);
  EXPECT_LT(g.hole_pixels, single_holes[0] / 4);
  EXPECT_LT(g.hole_pixels, single_holes[1] / 4);
  EXPECT_LE(seen_by_one, 10) << "a pixel one render saw is left empty";
  EXPECT_LE(g.hole_pixels, unseen_by_both + seen_by_one);
  // Nearest surface wins: the frame is the exact one's but for resampling at the checkers'
  // edges, closer than either render alone (whose holes show nothing).
  const double merged_mismatch = testing::mismatch_fraction(g.image, exact, 8);
  EXPECT_LT(merged_mismatch, 0.03);
  EXPECT_LT(merged_mismatch, std::min(single_mismatch[0], single_mismatch[1]));
}

// The engine under view-interpolation on a cadence of 3: the renders are an exact re-render's
// frames, the frames between are interpolated with their error measured, and each is shown
// two frames late.
TEST(ViewInterpolation, TheEngineRendersOnItsCadenceAndInterpolatesTheFramesBetween) {
  const Scene scene = coded_cube_past_cube();
  const auto frames = sliding_past(7, Vec3(0.08, 0, -0.04), Vec3(0, 0.02, 0));  // frames 0..6
  SceneSettings settings;
  settings.engine.policy = &reuse_policy("view-interpolation");
  settings.engine.cadence = 3;
  SceneSettings exact_settings;
  exact_settings.engine.policy = &reuse_policy("rerender");
  SceneEngine engine(scene, kCamera, settings), exact(scene, kCamera, exact_settings);
  engine.set_future_views([&](int k, ViewerPose& pose) {
    if (k < 0 || k >= static_cast<int>(frames.size())) return false;
    pose = frames[static_cast<std::size_t>(k)].pose;
    return true;
  });
  EXPECT_EQ(latency_frames(*settings.engine.policy, settings.engine.cadence), 2);
  int interpolated = 0;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const auto step = [&](SceneEngine& e) {
      return i == 0 ? e.start(frames[0].pose)
                    : e.advance(frames[i - 1].pose, frames[i - 1].motion, frames[i].pose);
    };
    const AnimationFrame r = step(engine);
    step(exact);
    const int drawn = r.drawn();
    ASSERT_GT(drawn, 0);
    if (i % 3 == 0) {  // frames 0, 3 and 6: rendered, as the exact re-render renders them
      EXPECT_EQ(r.levels[static_cast<int>(Level::kRerender)], drawn) << "frame " << i;
      EXPECT_EQ(engine.frame().pixels(), exact.frame().pixels()) << "frame " << i;
      continue;
    }
    ++interpolated;
    EXPECT_EQ(r.levels[static_cast<int>(Level::kPerspective)], drawn) << "frame " << i;
    const double seen = testing::coded_image_error(scene, kCamera, engine.frame(), frames[i].pose);
    EXPECT_GE(r.max_measured_error_px, seen - 0.25) << "frame " << i;
    EXPECT_LT(seen, 2.0) << "frame " << i;  // a silhouette's splat margin, magnified
  }
  EXPECT_EQ(interpolated, 4);
  // Without the views to come it cannot interpolate: every frame is rendered.
  SceneEngine blind(scene, kCamera, settings);
  for (std::size_t i = 0; i < 3; ++i) {
    const AnimationFrame r =
        i == 0 ? blind.start(frames[0].pose)
               : blind.advance(frames[i - 1].pose, frames[i - 1].motion, frames[i].pose);
    EXPECT_EQ(r.levels[static_cast<int>(Level::kRerender)], r.drawn()) << "frame " << i;
  }
}

// The engine's measured error of every interpolated frame against the error read back from
// texel-coded images, on three motions (a slide, a turn, and segments of both with a push):
// never under-reported by more than 0.25 px, and the image's error is sub-pixel to a few
// pixels, so the check has something to find.
TEST(ViewInterpolation, MeasuredErrorNeverUnderReportsTheErrorReadFromTheImage) {
  const Scene scene = coded_cube_past_cube();
  SceneSettings settings;
  settings.engine.policy = &reuse_policy("view-interpolation");
  settings.engine.cadence = 3;
  const std::vector<std::vector<ViewerFrame>> scripts = testing::three_motions_past();
  int interpolated = 0;
  double largest = 0.0;
  for (const auto& frames : scripts) {
    SceneEngine engine(scene, kCamera, settings);
    engine.set_future_views([&](int k, ViewerPose& pose) {
      if (k < 0 || k >= static_cast<int>(frames.size())) return false;
      pose = frames[static_cast<std::size_t>(k)].pose;
      return true;
    });
    for (std::size_t i = 0; i < frames.size(); ++i) {
      const AnimationFrame r =
          i == 0 ? engine.start(frames[0].pose)
                 : engine.advance(frames[i - 1].pose, frames[i - 1].motion, frames[i].pose);
      const double seen =
          testing::coded_image_error(scene, kCamera, engine.frame(), frames[i].pose);
      EXPECT_GE(r.max_measured_error_px, seen - 0.25) << "frame " << i;
      if (r.levels[static_cast<int>(Level::kPerspective)] > 0) {
        ++interpolated;
        largest = std::max(largest, seen);
      }
    }
  }
  EXPECT_GE(interpolated, 18);
  EXPECT_GT(largest, 0.5);
}

}  // namespace
}  // namespace oflab
