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
#include "formats/viewer_script_file.h"
#include "runs/source_kinds.h"
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
  SceneEngine exact(scene, script.camera, settings);
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

// ---- Lit contents: VTK draws the impostors' faces and the baked, normal-mapped brick ----

// Mean absolute difference, in grey levels (mean of the three channels, 0 .. 255), over the
// pixels both images cover.
double mean_grey_difference(const Image& a, const Image& b) {
  double sum = 0.0;
  long n = 0;
  for (std::size_t i = 0; i < a.pixels().size(); ++i) {
    const Pixel p = a.pixels()[i], q = b.pixels()[i];
    if (p.a == 0 || q.a == 0) continue;
    sum += (std::abs(p.r - q.r) + std::abs(p.g - q.g) + std::abs(p.b - q.b)) / 3.0;
    ++n;
  }
  return n ? sum / n : 255.0;
}

struct LitAgreement {
  double iou = 0.0;
  double grey = 0.0;
};

// The street at frame `f` of walk, lit by `light` in VTK, against the engine's exact re-render
// (rerender policy) lit by the default light. Writes both images when `write` is set.
LitAgreement street_agreement(int f, const Vec3& light, bool write) {
  const Scene scene = read_scene_file(resolve_scene_path("street"));
  const ViewerScript script = read_viewer_script_file(resolve_viewer_script_path("walk"));
  SceneSettings settings;
  settings.engine.policy = &reuse_policy("rerender");
  settings.engine.content.quality = scene.content_quality;
  SceneEngine exact(scene, script.camera, settings);
  LayerContent content = settings.engine.content;
  content.light = light;
  VtkSceneRenderer vtk(scene, script.camera, settings.near, content);
  exact.start(script.frames[f].pose);
  vtk.render(script.frames[f].pose);
  const LitAgreement a{alpha_iou(vtk.image(), exact.frame()),
                       mean_grey_difference(vtk.image(), exact.frame())};
  if (write) {
    const fs::path dir = fs::temp_directory_path();
    write_png((dir / ("vtk_street_" + std::to_string(f) + ".png")).string(), vtk.image());
    write_png((dir / ("exact_street_" + std::to_string(f) + ".png")).string(), exact.frame());
  }
  return a;
}

// Documented in manual/costs.md. The conventional renderer draws the impostors' balconies
// beyond the proxy rectangle's outline (the engine's layer cuts them there), filters a
// baked brick texture where the engine shades per sample, tints the brick's highlight by
// its albedo and lights with Phong's specular term: the silhouettes must agree to this
// IoU and the colours to this mean grey difference over the pixels both cover (measured on
// frames 0, 60 and 130: IoU 0.988-0.993, 0.8-0.9 grey levels). A light mirrored through
// the image plane (a wrong lighting frame) differs by 33 grey levels.
constexpr double kLitSilhouetteIou = 0.98;
constexpr double kLitMeanGrey = 3.0;

TEST(VtkBaseline, DrawsTheStreetsLitContentsAsTheEngineDoes) {
  if (!display_available()) GTEST_SKIP() << "needs an X display: run under xvfb-run -a";
  const Vec3 light = LayerContent{}.light;
  for (int f : {0, 60, 130}) {
    const LitAgreement a = street_agreement(f, light, false);
    EXPECT_GE(a.iou, kLitSilhouetteIou) << "frame " << f;
    EXPECT_LE(a.grey, kLitMeanGrey) << "frame " << f;
    if (a.iou < kLitSilhouetteIou || a.grey > kLitMeanGrey) {
      street_agreement(f, light, true);
      ADD_FAILURE() << "images written to " << fs::temp_directory_path();
    }
  }
  // Negative control: the light mirrored through the viewer's image plane.
  const LitAgreement wrong = street_agreement(0, Vec3(-light.x, -light.y, light.z), false);
  EXPECT_GT(wrong.grey, 3.0 * kLitMeanGrey);
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

// The street's comparison run draws the lit contents in VTK at one sample per pixel and
// multisampled; both cover the engine's frames (balconies aside) and report a frame time.
TEST(VtkBaseline, StreetComparisonRunsMultisampledAndSingleSampled) {
  if (!display_available()) GTEST_SKIP() << "needs an X display: run under xvfb-run -a";
  RunSource source;
  const Scene scene = read_scene_file(resolve_scene_path("street"));
  source.scene = std::make_shared<const Scene>(scene);
  source.viewer = read_viewer_script_file(resolve_viewer_script_path("walk"));
  source.settings.engine.content.quality = scene.content_quality;
  for (bool multisample : {true, false}) {
    PlayOptions options;
    options.max_frames = 2;
    options.conventional = true;
    options.conventional_multisample = multisample;
    const AnimationRun run = source_kind("scene").play(source, options);
    EXPECT_GT(run.summary.conventional_median_frame_ms, 0.0) << multisample;
    EXPECT_GE(run.summary.conventional_iou, kLitSilhouetteIou) << multisample;
  }
}

}  // namespace
}  // namespace oflab
