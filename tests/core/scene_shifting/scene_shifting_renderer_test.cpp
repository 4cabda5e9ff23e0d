// The scene-shifting renderer against the optic-flow engine's translation level (sideways
// viewer) and the turning viewer that forces every slice to be rebuilt.
#include "scene_shifting/scene_shifting_renderer.h"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/engine.h"
#include "scene_cases.h"

namespace oflab {
namespace {

using testing::scene_with;
using testing::square;

constexpr double kEpsilon = 1.0;  // px, the renderer's budget
// px, the engine's translation budget: at least the 0.71 px a whole-pixel translation may
// leave, or the engine's exact check rightly prefers a sub-pixel affine warp.
constexpr double kEngineThreshold = 1.0;
// Both place layers on whole pixels: each rounding moves a corner by at most sqrt(2)/2.
const double kRounding = std::sqrt(2.0) / 2.0;

// Planes parallel to the image plane of a viewer at the origin looking along world -Z.
Scene train_like_scene() {
  const Vec3 front(0.0, 0.0, 1.0), up(0.0, 1.0, 0.0);
  return scene_with({square("far", {0.53, 0.07, -20.0}, front, up, 12.1),
                     square("middle", {0.31, -0.21, -6.0}, front, up, 3.01),
                     square("bush-a", {-0.3, 0.2, -2.0}, front, up, 0.6),
                     square("bush-b", {0.4, 0.1, -2.4}, front, up, 0.6),
                     square("bush-c", {1.0, 0.0, -3.0}, front, up, 0.6)});
}

ViewerPose start_view() { return look_at({0.0, 0.0, 0.0}, {0.0, 0.0, -1.0}, {0.0, 1.0, 0.0}); }

std::vector<ViewerFrame> frames(const Vec3& velocity, const Vec3& omega, int count) {
  return expand_viewer_segments(start_view(), {{count, velocity, omega}});
}

SceneShiftingSettings settings_for(double speed) {
  SceneShiftingSettings s;
  s.epsilon_px = kEpsilon;
  s.design_speed = speed;
  return s;
}

std::vector<Vec2> engine_corners(const PlaneEngine& engine, const PlanePose& pose,
                                 const Camera& camera) {
  const double tw = pose.texture_size.x, th = pose.texture_size.y;
  std::vector<Vec2> corners;
  for (const Vec2& t : {Vec2(0, 0), Vec2(tw, 0), Vec2(tw, th), Vec2(0, th)}) {
    corners.push_back(pixel_to_centred(camera, apply_homography(engine.displayed_warp(), t)));
  }
  return corners;
}

TEST(SceneShiftingRenderer, SidewaysViewerMatchesTheEnginesTranslationLevelPlaneByPlane) {
  const Scene scene = train_like_scene();
  const Camera camera = make_camera(300.0, 320, 240);
  const double speed = 0.03;
  const std::vector<ViewerFrame> script = frames({speed, 0.0, 0.0}, {0.0, 0.0, 0.0}, 40);
  SceneShiftingRenderer renderer(scene, camera, settings_for(speed));
  EngineSettings engine_settings;
  engine_settings.thresholds.fill(kEngineThreshold);
  const glm::ivec2 size(scene.textures[0].width(), scene.textures[0].height());
  std::vector<PlaneEngine> engines;
  for (std::size_t p = 0; p < scene.polygons.size(); ++p) {
    engines.emplace_back(camera, make_layer(scene.textures[0]), engine_settings);
  }
  for (std::size_t i = 0; i < script.size(); ++i) {
    if (i == 0) {
      renderer.start(script[0].pose);
    } else {
      renderer.advance(script[i - 1].pose, script[i - 1].motion, script[i].pose);
    }
    const SceneShiftingFrameReport& r = renderer.slice_report();
    EXPECT_FALSE(r.view_turned);
    EXPECT_LE(r.max_measured_error_px, kEpsilon + 1e-9) << "frame " << i;
    for (std::size_t p = 0; p < scene.polygons.size(); ++p) {
      const PlanePose pose = polygon_pose(scene.polygons[p], script[i].pose, size);
      const FrameReport e =
          i == 0 ? engines[p].start(pose)
                 : engines[p].advance(polygon_pose(scene.polygons[p], script[i - 1].pose, size),
                                      script[i - 1].motion, pose);
      // Beyond the guard band the engine clips and renders exactly, outside the image it
      // shows nothing: no warp to compare then.
      if (e.clipped || !e.visible) continue;
      // A fronto-parallel plane under a sideways viewer only translates in the image.
      EXPECT_TRUE(e.level == Level::kNone || e.level == Level::kTranslate || i == 0)
          << scene.polygons[p].name << " frame " << i << ": " << level_name(e.level);
      const std::vector<Vec2> shown = renderer.shown_corners(static_cast<int>(p));
      const std::vector<Vec2> flow = engine_corners(engines[p], pose, camera);
      ASSERT_EQ(shown.size(), 4u);
      for (int k = 0; k < 4; ++k) {
        EXPECT_LE(glm::length(shown[k] - flow[k]), kEpsilon + kEngineThreshold + 2 * kRounding)
            << scene.polygons[p].name << " corner " << k << " frame " << i;
      }
    }
  }
}

TEST(SceneShiftingRenderer, SidewaysViewerShiftsLayersInsteadOfRenderingThemEveryFrame) {
  const Scene scene = train_like_scene();
  const Camera camera = make_camera(300.0, 320, 240);
  const std::vector<ViewerFrame> script = frames({0.03, 0.0, 0.0}, {0.0, 0.0, 0.0}, 30);
  SceneShiftingRenderer renderer(scene, camera, settings_for(0.03));
  int rebuilt = 0, shifted = 0;
  renderer.start(script[0].pose);
  for (std::size_t i = 1; i < script.size(); ++i) {
    renderer.advance(script[i - 1].pose, script[i - 1].motion, script[i].pose);
    const SceneShiftingFrameReport& r = renderer.slice_report();
    rebuilt += r.rebuilt;
    shifted += r.shifted;
  }
  EXPECT_GT(shifted, rebuilt);
}

TEST(SceneShiftingRenderer, TurningViewerRebuildsEveryOccupiedSliceEveryFrame) {
  const Scene scene = train_like_scene();
  const Camera camera = make_camera(300.0, 320, 240);
  const std::vector<ViewerFrame> script = frames({0.03, 0.0, 0.0}, {0.0, 0.004, 0.0}, 15);
  SceneShiftingRenderer renderer(scene, camera, settings_for(0.03));
  renderer.start(script[0].pose);
  EXPECT_GE(renderer.slice_report().occupied, 3);
  for (std::size_t i = 1; i < script.size(); ++i) {
    renderer.advance(script[i - 1].pose, script[i - 1].motion, script[i].pose);
    const SceneShiftingFrameReport& r = renderer.slice_report();
    EXPECT_TRUE(r.view_turned);
    EXPECT_EQ(r.rebuilt, r.occupied) << "frame " << i;
    EXPECT_EQ(r.shifted + r.scaled, 0);
    // Rebuilt layers are exact renders.
    EXPECT_LE(r.max_measured_error_px, 1e-9);
  }
}

TEST(SceneShiftingRenderer, RejectsPlanesNotParallelToTheImagePlane) {
  const Scene scene = scene_with({square(
      "tilted", {0.0, 0.0, -3.0}, glm::normalize(Vec3(0.3, 0.0, 1.0)), {0.0, 1.0, 0.0}, 1.0)});
  SceneShiftingRenderer renderer(scene, make_camera(300.0, 320, 240), settings_for(0.03));
  EXPECT_THROW(renderer.start(start_view()), std::invalid_argument);
}

// The memory estimate against a count by hand: 4 bytes a pixel for the frame, the scene's
// texture, each polygon's copy of it, and per occupied slice plus two a layer of the frame
// grown by the guard band on every side.
TEST(SceneShiftingRenderer, MemoryEstimateCountsTexturesFrameAndGuardBandLayers) {
  const Scene scene = train_like_scene();
  ASSERT_EQ(scene.textures.size(), 1u);
  const double texture = 4.0 * scene.textures[0].width() * scene.textures[0].height();
  const Camera camera = make_camera(300.0, 320, 240);
  const double frame = 4.0 * 320 * 240;
  EXPECT_DOUBLE_EQ(scene_shifting_memory_bytes(scene, camera, 1.0, 0),
                   frame + texture + 5 * texture);
  EXPECT_DOUBLE_EQ(scene_shifting_memory_bytes(scene, camera, 1.0, 3),
                   frame + 6 * texture + 5 * 4.0 * (3 * 320) * (3 * 240));
  EXPECT_DOUBLE_EQ(scene_shifting_memory_bytes(scene, camera, 0.0, 3),
                   frame + 6 * texture + 5 * frame);
}

// Twelve squares of a 4096 x 4096 texture: their copies alone are 768 MiB, so the renderer
// is refused when it is made, naming the figure and the limit; two of them are made.
TEST(SceneShiftingRenderer, TextureCopiesOverTheMemoryLimitAreRefusedWhenMade) {
  const Vec3 front(0.0, 0.0, 1.0), up(0.0, 1.0, 0.0);
  std::vector<ScenePolygon> squares;
  for (int i = 0; i < 12; ++i) {
    squares.push_back(square("s" + std::to_string(i), {0.1 * i, 0.0, -3.0}, front, up, 1.0));
  }
  Scene scene = scene_with(squares);
  scene.textures[0] = Image(4096, 4096, Pixel{10, 20, 30, 255});
  const Camera camera = make_camera(300.0, 320, 240);
  try {
    SceneShiftingRenderer renderer(scene, camera, settings_for(0.03));
    FAIL() << "twelve copies of a 64 MiB texture were accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "scene shifting of the scene's 12 polygons at 320 x 240 px may hold 833 MiB of "
                 "textures, more than 768 MiB (the scene engine memory limit)");
  }
  scene.polygons.resize(2);
  EXPECT_NO_THROW(SceneShiftingRenderer(scene, camera, settings_for(0.03)));
}

// At 4096 x 4096 px with the default guard band a slice's layer may reach 3 x 3 frames of
// 64 MiB: one occupied slice, its scratch and a rebuild's new image are 1.75 GiB, refused
// after the cut and before anything is rendered; the frame and textures alone were accepted.
TEST(SceneShiftingRenderer, SliceLayersOverTheMemoryLimitAreRefusedAtStart) {
  const Scene scene =
      scene_with({square("far", {0.0, 0.0, -20.0}, {0.0, 0.0, 1.0}, {0.0, 1.0, 0.0}, 12.0)});
  SceneShiftingRenderer renderer(scene, make_camera(4000.0, 4096, 4096), settings_for(0.03));
  try {
    renderer.start(start_view());
    FAIL() << "the slice layers were not refused";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("scene shifting of the scene's 1 polygons in 1 slice at "
                                         "4096 x 4096 px may hold 1793 MiB of slice layers"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace oflab
