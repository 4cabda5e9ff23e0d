// Textured depth meshes (core/scene/depth_mesh.h) and the scene engine's depth-mesh policy,
// against independent computations: world points found by rays in world coordinates and
// projected exactly, a near square's outline projected exactly, the error read back from
// texel-coded images, and an exact re-render.
#include "scene/depth_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "engine/reuse_policy.h"
#include "scene/scene_animator.h"
#include "scene_cases.h"

namespace oflab {
namespace {

using testing::project_world;
using testing::scene_with;
using testing::sliding_past;
using testing::square;
using testing::world_point_at;

const Camera kCamera = make_camera(150.0, 160, 120);
constexpr double kNear = 0.05;

// A viewer at `eye` looking down world -Z, world Y up.
ViewerPose viewer_at(const Vec3& eye) {
  return look_at(eye, eye + Vec3(0.0, 0.0, -1.0), Vec3(0.0, 1.0, 0.0));
}

// A far square (side 8 at Z = -6) filling most of the view from (0, 0, 0).
Scene far_plane() {
  return testing::with_coded_textures(
      scene_with({square("wall", Vec3(0.0, 0.0, -6.0), Vec3(0, 0, 1), Vec3(0, 1, 0), 8.0)}));
}

// A far plane alone, the viewer translated sideways and forward: every pixel the mesh draws
// shows the surface point whose exact projection now lies within 0.75 px of its centre (the
// nearest sample's half diagonal, 0.71 px, and the magnification of a forward step), and the
// mesh draws every pixel the view now shows of what the render saw (away from its border).
TEST(DepthMesh, AFarPlaneMeshLandsWhereTheExactProjectionPutsItsPixels) {
  const Scene scene = far_plane();
  const ViewerPose then = viewer_at(Vec3(0.0)), now = viewer_at(Vec3(0.4, -0.2, -0.5));
  const DepthFrame depth = render_depth(scene, kCamera, then, kNear);
  const Image rendered = testing::ray_cast_scene(scene, kCamera, then, kNear);
  const DepthMesh mesh = build_depth_mesh(depth, kCamera, 4, 0.1, true);
  EXPECT_EQ(mesh.columns, 41);
  EXPECT_EQ(mesh.rows, 31);
  EXPECT_EQ(mesh.rubber_sheets, 0);
  // Every vertex lies on the plane Z = -6 (world), found without the mesh's plane vectors.
  for (std::size_t v = 0; v < mesh.points.size(); ++v) {
    ASSERT_FALSE(mesh.background[v]);
    EXPECT_NEAR(mesh.points[v].z, 6.0, 1e-9);
  }
  const MeshDraw drawn =
      draw_depth_mesh(mesh, rendered, depth, kCamera, viewer_step(then, now), kNear);
  const ScenePolygon& wall = scene.polygons[0];
  int checked = 0, missing = 0;
  double worst = 0.0;
  for (int y = 0; y < kCamera.height; ++y) {
    for (int x = 0; x < kCamera.width; ++x) {
      const std::size_t d = static_cast<std::size_t>(y) * kCamera.width + x;
      const int s = drawn.source[d];
      if (s >= 0) {
        const Vec3 seen =
            world_point_at(kCamera, wall, then, s % kCamera.width + 0.5, s / kCamera.width + 0.5);
        const Vec2 q = project_world(kCamera, now, seen);
        worst = std::max(worst, glm::length(q - Vec2(x + 0.5, y + 0.5)));
        ++checked;
        continue;
      }
      // Unreached: only where the render did not see the point (or within a pixel of its edge).
      const Vec3 p = world_point_at(kCamera, wall, now, x + 0.5, y + 0.5);
      const Vec2 q = project_world(kCamera, then, p);
      if (q.x > 1 && q.y > 1 && q.x < kCamera.width - 1 && q.y < kCamera.height - 1) ++missing;
    }
  }
  EXPECT_GT(checked, kCamera.width * kCamera.height / 2);
  EXPECT_LT(worst, 0.75);
  EXPECT_EQ(missing, 0);
  // Negative control: the same pixels, but the mesh drawn from the render's own view, are off.
  const MeshDraw stale = draw_depth_mesh(mesh, rendered, depth, kCamera, RigidStep3{}, kNear);
  EXPECT_NE(stale.source, drawn.source);
}

// A near square before the far plane: the triangles across its outline are rubber sheets.
// Dropped, they leave holes exactly there: every unreached pixel that shows a surface lies in a
// grid cell that the square's outline (projected exactly) crosses, and there are some; drawn
// stretched, nothing is unreached.
TEST(DepthMesh, RubberSheetsDroppedLeaveHolesExactlyAtTheDepthJump) {
  Scene scene = far_plane();
  scene.polygons.push_back(square("near", Vec3(0.3, 0.1, -3.0), Vec3(0, 0, 1), Vec3(0, 1, 0), 1.2));
  const ViewerPose view = viewer_at(Vec3(0.0));
  const DepthFrame depth = render_depth(scene, kCamera, view, kNear);
  const Image rendered = testing::ray_cast_scene(scene, kCamera, view, kNear);
  constexpr int kGrid = 4;
  // The square's outline in the image, projected from its world corners.
  const ScenePolygon& near = scene.polygons[1];
  double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
  for (const Vec3& corner : polygon_vertices(near)) {
    const Vec2 q = project_world(kCamera, view, corner);
    x0 = std::min(x0, q.x), x1 = std::max(x1, q.x), y0 = std::min(y0, q.y), y1 = std::max(y1, q.y);
  }
  const auto cell_crosses_outline = [&](int x, int y) {
    const double cx0 = std::floor(x / kGrid) * kGrid, cy0 = std::floor(y / kGrid) * kGrid;
    const double cx1 = cx0 + kGrid, cy1 = cy0 + kGrid;
    const bool overlaps = cx1 >= x0 && cx0 <= x1 && cy1 >= y0 && cy0 <= y1;
    const bool inside = cx0 >= x0 && cx1 <= x1 && cy0 >= y0 && cy1 <= y1;
    return overlaps && !inside;
  };
  for (const bool drop : {true, false}) {
    const DepthMesh mesh = build_depth_mesh(depth, kCamera, kGrid, 0.1, drop);
    EXPECT_GT(mesh.rubber_sheets, 20);
    EXPECT_EQ(mesh.dropped, drop ? mesh.rubber_sheets : 0);
    const MeshDraw drawn = draw_depth_mesh(mesh, rendered, depth, kCamera, RigidStep3{}, kNear);
    int holes = 0, misplaced = 0;
    for (int y = 0; y < kCamera.height; ++y) {
      for (int x = 0; x < kCamera.width; ++x) {
        const std::size_t d = static_cast<std::size_t>(y) * kCamera.width + x;
        if (drawn.source[d] >= 0 || depth.polygon[d] < 0) continue;
        ++holes;
        misplaced += !cell_crosses_outline(x, y);
      }
    }
    if (drop) {
      EXPECT_GT(holes, 100);
      EXPECT_EQ(misplaced, 0);
    } else {
      EXPECT_EQ(holes, 0);
    }
  }
}

TEST(DepthMesh, TheAutomaticSplitIsTheMiddleOfTheDepthsSeen) {
  Scene scene = far_plane();
  scene.polygons.push_back(square("near", Vec3(0.3, 0.1, -3.0), Vec3(0, 0, 1), Vec3(0, 1, 0), 1.2));
  const ViewerPose view = viewer_at(Vec3(0.0));
  EXPECT_NEAR(automatic_split(render_depth(scene, kCamera, view, kNear)), 4.5, 1e-9);
  const std::vector<char> far = far_polygons(scene, view, 4.5);
  EXPECT_EQ(far, (std::vector<char>{1, 0}));
  EXPECT_EQ(automatic_split(render_depth(scene, kCamera, viewer_at(Vec3(0, 0, -20)), kNear)), 0.0);
  DepthMeshSettings bad;
  bad.grid_px = 0;
  EXPECT_NE(depth_mesh_settings_problem(bad).find("mesh grid"), std::string::npos);
  EXPECT_EQ(depth_mesh_settings_problem(DepthMeshSettings{}), "");
}

// Every polygon near (a split beyond the scene): the policy is exact re-rendering, frame for
// frame to the byte. With the automatic split the far cube is meshed between builds.
TEST(DepthMesh, TheEngineWithNoFarPartIsExactReRendering) {
  const Scene scene = testing::cube_past_cube();
  const auto frames = sliding_past(4, Vec3(0.08, 0, -0.04), Vec3(0, 0.02, 0));
  SceneSettings settings;
  settings.engine.policy = &reuse_policy("depth-mesh");
  settings.engine.cadence = 3;
  settings.mesh.split = 1000.0;
  SceneSettings exact_settings;
  exact_settings.engine.policy = &reuse_policy("rerender");
  SceneSettings automatic = settings;
  automatic.mesh.split = 0.0;
  SceneEngine engine(scene, kCamera, settings), exact(scene, kCamera, exact_settings),
      meshed(scene, kCamera, automatic);
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const auto step = [&](SceneEngine& e) {
      return i == 0 ? e.start(frames[0].pose)
                    : e.advance(frames[i - 1].pose, frames[i - 1].motion, frames[i].pose);
    };
    const AnimationFrame r = step(engine), m = step(meshed);
    step(exact);
    EXPECT_EQ(engine.frame().pixels(), exact.frame().pixels()) << "frame " << i;
    EXPECT_EQ(r.levels[static_cast<int>(Level::kRerender)], r.drawn()) << "frame " << i;
    EXPECT_EQ(r.hole_pixels, 0);
    // The far cube (polygons 0..4) is far; it is meshed on frames 1 and 2.
    EXPECT_EQ(meshed.far_part(), (std::vector<char>{1, 1, 1, 1, 1, 0, 0, 0, 0, 0}));
    EXPECT_GT(m.levels[static_cast<int>(Level::kPerspective)], i % 3 == 0 ? -1 : 0);
    if (i % 3 == 0) {
      EXPECT_EQ(meshed.frame().pixels(), exact.frame().pixels()) << "frame " << i;
    }
  }
  EXPECT_GT(meshed.mesh_split(), 4.0);
}

// The mesh is rebuilt on its cadence, and before it once the viewer has travelled more than the
// rebuild distance since the build: a slide of 0.08 per frame with a distance of 0.1 rebuilds
// every second frame (the far polygons re-rendered, none meshed), at cadence 8 without it.
TEST(DepthMesh, TheEngineRebuildsOnItsCadenceOrAfterTheRebuildDistance) {
  const Scene scene = testing::cube_past_cube();
  const auto frames = sliding_past(6, Vec3(0.08, 0, 0), Vec3(0.0));
  for (const double distance : {0.0, 0.1}) {
    SceneSettings settings;
    settings.engine.policy = &reuse_policy("depth-mesh");
    settings.engine.cadence = 8;
    settings.mesh.rebuild_distance = distance;
    SceneEngine engine(scene, kCamera, settings);
    for (std::size_t i = 0; i < frames.size(); ++i) {
      const AnimationFrame r =
          i == 0 ? engine.start(frames[0].pose)
                 : engine.advance(frames[i - 1].pose, frames[i - 1].motion, frames[i].pose);
      const bool built = i == 0 || (distance > 0.0 && i % 2 == 0);
      EXPECT_EQ(r.levels[static_cast<int>(Level::kPerspective)] == 0, built)
          << "frame " << i << ", distance " << distance;
    }
  }
}

// The engine's measured error of every meshed frame against the error read back from
// texel-coded images, on three motions (a slide, a turn, and segments of both with a push):
// never under-reported by more than 0.25 px, and the image's error reaches a pixel, so the
// check has something to find.
TEST(DepthMesh, MeasuredErrorNeverUnderReportsTheErrorReadFromTheImage) {
  const Scene scene = testing::with_coded_textures(testing::cube_past_cube());
  SceneSettings settings;
  settings.engine.policy = &reuse_policy("depth-mesh");
  settings.engine.cadence = 3;
  int meshed = 0;
  double largest = 0.0;
  for (const auto& frames : testing::three_motions_past()) {
    SceneEngine engine(scene, kCamera, settings);
    for (std::size_t i = 0; i < frames.size(); ++i) {
      const AnimationFrame r =
          i == 0 ? engine.start(frames[0].pose)
                 : engine.advance(frames[i - 1].pose, frames[i - 1].motion, frames[i].pose);
      const double seen =
          testing::coded_image_error(scene, kCamera, engine.frame(), frames[i].pose);
      EXPECT_GE(r.max_measured_error_px, seen - 0.25) << "frame " << i;
      if (r.levels[static_cast<int>(Level::kPerspective)] > 0) {
        ++meshed;
        largest = std::max(largest, seen);
      }
    }
  }
  EXPECT_GE(meshed, 18);
  EXPECT_GT(largest, 0.5);
  std::printf("depth mesh: %d meshed frames, largest error read from the image %.3f px\n", meshed,
              largest);
}

}  // namespace
}  // namespace oflab
