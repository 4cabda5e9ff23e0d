// The conventional baseline against the core's exact re-render of the same frames: VTK must
// draw the same polygons in the same places with the same texels. Needs an X display (the
// test command runs ctest under xvfb-run); without one the tests are skipped, never passed.
#include "runs/vtk_scene_renderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "formats/image_io.h"
#include "formats/scene_file.h"
#include "runs/source_kinds.h"
#include "formats/viewer_script_file.h"
#include "scene/scene_animator.h"

namespace oflab {
namespace {

namespace fs = std::filesystem;

// Documented in manual/scenes.md ("How the scene code is tested"). OpenGL and the core's
// scan conversion both sample at pixel centres but round edges and texel boundaries
// differently: the alpha masks (silhouettes) must agree to this intersection over union,
// and at most this share of the pixels covered by either may differ in colour by more
// than 8 of 255 in a channel.
constexpr double kSilhouetteIou = 0.995;
constexpr double kColourMismatch = 0.005;

double colour_mismatch(const Image& a, const Image& b) {
  long covered = 0, different = 0;
  for (std::size_t i = 0; i < a.pixels().size(); ++i) {
    const Pixel p = a.pixels()[i], q = b.pixels()[i];
    if (p.a == 0 && q.a == 0) continue;
    ++covered;
    const int d = std::max(
        {std::abs(p.r - q.r), std::abs(p.g - q.g), std::abs(p.b - q.b), std::abs(p.a - q.a)});
    different += d > 8;
  }
  return covered ? static_cast<double>(different) / covered : 0.0;
}

long covered_pixels(const Image& image) {
  return std::count_if(image.pixels().begin(), image.pixels().end(),
                       [](const Pixel& p) { return p.a != 0; });
}

void compare_with_exact(const std::string& scene_name, const std::string& script_name,
                        const std::vector<int>& frames) {
  const Scene scene = read_scene_file(resolve_scene_path(scene_name));
  const ViewerScript script = read_viewer_script_file(resolve_viewer_script_path(script_name));
  SceneSettings settings;
  settings.engine.policy = &reuse_policy("rerender");
  SceneAnimator exact(scene, script.camera, settings);
  VtkSceneRenderer vtk(scene, script.camera, settings.near);
  for (int f : frames) {
    exact.start(script.frames[f].pose);
    const double ms = vtk.render(script.frames[f].pose);
    EXPECT_GT(ms, 0.0);
    const Image& a = vtk.image();
    const Image& b = exact.frame();
    const std::string what = scene_name + " / " + script_name + " frame " + std::to_string(f);
    EXPECT_GT(covered_pixels(a), 1000) << what;
    const double iou = alpha_iou(a, b), mismatch = colour_mismatch(a, b);
    EXPECT_GE(iou, kSilhouetteIou) << what;
    EXPECT_LE(mismatch, kColourMismatch) << what;
    if (iou < kSilhouetteIou || mismatch > kColourMismatch) {
      const fs::path dir = fs::temp_directory_path();
      write_png((dir / ("vtk_" + scene_name + "_" + std::to_string(f) + ".png")).string(), a);
      write_png((dir / ("exact_" + scene_name + "_" + std::to_string(f) + ".png")).string(), b);
      ADD_FAILURE() << "images written to " << dir;
    }
  }
}

TEST(VtkBaseline, DrawsWhatTheExactRerenderDraws) {
  if (!display_available()) GTEST_SKIP() << "needs an X display: run under xvfb-run -a";
  compare_with_exact("single-1", "stationary", {0});
  compare_with_exact("two", "circle", {0, 30, 60});
  compare_with_exact("four-cubes", "compound", {0, 120, 250, 400});
}

TEST(VtkBaseline, ClipsAtTheSameNearPlane) {
  if (!display_available()) GTEST_SKIP() << "needs an X display: run under xvfb-run -a";
  // Frames of fly-through where the viewer is passing through the polygons.
  compare_with_exact("five-parallel", "fly-through", {55, 62, 75});
}

TEST(VtkBaseline, ComparisonRunReportsThreeFrameTimes) {
  if (!display_available()) GTEST_SKIP() << "needs an X display: run under xvfb-run -a";
  RunSource source;
  source.scene = std::make_shared<const Scene>(read_scene_file(resolve_scene_path("cube")));
  source.viewer = read_viewer_script_file(resolve_viewer_script_path("circle"));
  PlayOptions options;
  options.max_frames = 20;
  options.conventional = true;
  const AnimationRun run = source_kind("scene").play(source, options);
  EXPECT_GT(run.summary.median_frame_ms, 0.0);
  EXPECT_GT(run.summary.baseline_median_frame_ms, 0.0);
  EXPECT_GT(run.summary.conventional_median_frame_ms, 0.0);
  EXPECT_GE(run.summary.conventional_iou, kSilhouetteIou);
}

}  // namespace
}  // namespace oflab
