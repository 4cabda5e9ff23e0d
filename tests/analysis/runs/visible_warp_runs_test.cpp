// The scene engine's visible-only warp (EngineSettings::warp_area, core/engine/engine.h;
// manual/animation.md "What of a layer is warped") on the shipped scenes: every frame the same
// bytes as the whole-layer warp, and fewer pixels warped.
#include <gtest/gtest.h>

#include <iostream>
#include <memory>

#include "formats/datasets.h"
#include "formats/scene_file.h"
#include "formats/viewer_script_file.h"
#include "scene/scene_animator.h"

namespace oflab {
namespace {

struct Played {
  std::vector<Image> frames;
  std::int64_t written = 0;  // after frame 0
  std::int64_t warped = 0;   // after frame 0
  bool reused = false;       // some layer was translated or kept as it was
};

// `frames` frames of `script` through `scene` at half the script's image size (the same view),
// with the layers warped over `area`.
Played play(const char* scene, const char* script, int frames, WarpArea area) {
  const auto s = std::make_shared<const Scene>(read_scene_file(resolve_scene_path(scene)));
  ViewerScript v = read_viewer_script_file(resolve_viewer_script_path(script));
  v.camera = make_camera(v.camera.focal_px / 2, v.camera.width / 2, v.camera.height / 2);
  v.frames.resize(static_cast<std::size_t>(frames));
  SceneSettings settings;
  settings.engine.warp_area = area;
  auto animator = make_scene_animator(s, v, settings);
  Played p;
  for (int k = 0; k < frames; ++k) {
    const AnimationFrame f = k == 0 ? animator->start() : animator->advance();
    p.frames.push_back(animator->image());
    if (k == 0) continue;
    p.written += f.pixels_written;
    p.warped += f.pixels_written - f.pixels_not_warped;
    p.reused = p.reused || f.levels[static_cast<int>(Level::kNone)] > 0 ||
               f.levels[static_cast<int>(Level::kTranslate)] > 0;
  }
  return p;
}

void expect_same_frames_fewer_pixels(const char* scene, const char* script, int frames) {
  const Played whole = play(scene, script, frames, WarpArea::kWhole);
  const Played visible = play(scene, script, frames, WarpArea::kVisible);
  ASSERT_EQ(whole.frames.size(), visible.frames.size());
  for (std::size_t k = 0; k < whole.frames.size(); ++k) {
    EXPECT_TRUE(whole.frames[k].pixels() == visible.frames[k].pixels())
        << scene << " frame " << k << " differs";
  }
  // The whole warp computes every pixel it writes; the visible-only one fewer, the same
  // pixels written (the policy's work is the same).
  EXPECT_EQ(whole.warped, whole.written) << scene;
  EXPECT_EQ(visible.written, whole.written) << scene;
  EXPECT_LT(visible.warped, whole.warped) << scene;
  EXPECT_TRUE(visible.reused) << scene << ": the reused layers' completion went untested";
  std::cout << scene << " " << script << ": pixels warped after frame 0 " << whole.warped << " -> "
            << visible.warped << "\n";
}

TEST(VisibleWarpRuns, FourCubesFramesAreTheSameBytesWithFewerPixelsWarped) {
  expect_same_frames_fewer_pixels("four-cubes", "compound", 24);
}

TEST(VisibleWarpRuns, StreetFramesAreTheSameBytesWithFewerPixelsWarped) {
  expect_same_frames_fewer_pixels("street", "walk", 6);
}

}  // namespace
}  // namespace oflab
