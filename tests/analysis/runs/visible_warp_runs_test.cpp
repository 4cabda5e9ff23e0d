// The scene engine's visible-only warp (EngineSettings::warp_area, core/engine/engine.h;
// manual/animation.md "What of a layer is warped") on the shipped scenes: every frame the same
// bytes as the whole-layer warp, and fewer pixels warped.
#include <gtest/gtest.h>

#include <iostream>
#include <memory>

#include "formats/datasets.h"
#include "formats/scene_file.h"
#include "formats/viewer_script_file.h"
#include "runs/policy_runs.h"
#include "scene/scene_animator.h"

namespace oflab {
namespace {

struct Played {
  std::vector<Image> frames;
  std::int64_t written = 0;  // over every frame
  std::int64_t warped = 0;
  bool reused = false;  // some layer was translated or kept as it was
};

// `frames` frames of `script` from its frame `first` through `scene` at half the script's image
// size (the same view), with the layers warped over `area` and sampled with `sampling`.
Played play(const char* scene, const char* script, int first, int frames, WarpArea area,
            Sampling sampling) {
  const auto s = std::make_shared<const Scene>(read_scene_file(resolve_scene_path(scene)));
  ViewerScript v = read_viewer_script_file(resolve_viewer_script_path(script));
  v.camera = make_camera(v.camera.focal_px / 2, v.camera.width / 2, v.camera.height / 2);
  v.frames.erase(v.frames.begin(), v.frames.begin() + first);
  v.frames.resize(static_cast<std::size_t>(frames));
  SceneSettings settings;
  settings.engine.warp_area = area;
  settings.engine.sampling = sampling;
  auto animator = make_scene_animator(s, v, settings);
  Played p;
  for (int k = 0; k < frames; ++k) {
    const AnimationFrame f = k == 0 ? animator->start() : animator->advance();
    p.frames.push_back(animator->image());
    p.written += f.pixels_written;
    p.warped += f.pixels_written - f.pixels_not_warped;
    p.reused = p.reused || f.levels[static_cast<int>(Level::kNone)] > 0 ||
               f.levels[static_cast<int>(Level::kTranslate)] > 0;
  }
  return p;
}

// Plays both and compares every frame byte for byte; returns the pixels warped over every
// frame, whole and visible-only.
std::pair<std::int64_t, std::int64_t> expect_same_frames(const char* scene, const char* script,
                                                         int frames,
                                                         Sampling sampling = Sampling::kNearest,
                                                         int first = 0) {
  const Played whole = play(scene, script, first, frames, WarpArea::kWhole, sampling);
  const Played visible = play(scene, script, first, frames, WarpArea::kVisible, sampling);
  EXPECT_EQ(whole.frames.size(), visible.frames.size());
  for (std::size_t k = 0; k < whole.frames.size() && k < visible.frames.size(); ++k) {
    EXPECT_TRUE(whole.frames[k].pixels() == visible.frames[k].pixels())
        << scene << " frame " << k << " differs";
  }
  // The whole warp computes every pixel it writes; the visible-only one no more, the same
  // pixels written (the policy's work is the same).
  EXPECT_EQ(whole.warped, whole.written) << scene;
  EXPECT_EQ(visible.written, whole.written) << scene;
  EXPECT_LE(visible.warped, whole.warped) << scene;
  EXPECT_TRUE(visible.reused) << scene << ": the reused layers' completion went untested";
  std::cout << scene << " " << script << ": pixels warped " << whole.warped << " -> "
            << visible.warped << "\n";
  return {whole.warped, visible.warped};
}

// The cubes hide parts of each other: fewer pixels warped, the layers reused in the frames
// after (translations, no update) warping the pixels they come to show.
TEST(VisibleWarpRuns, FourCubesFramesAreTheSameBytesWithFewerPixelsWarped) {
  const auto [whole, visible] = expect_same_frames("four-cubes", "compound", 24);
  EXPECT_LT(visible, whole);
}

// Bilinear sampling: the affine kernel computes whole blocks of 64 columns around the wanted
// pixels, and the engine counts them as done (WarpOptions::computed_pixels), so a layer
// completed a few columns at a time computes no block twice: fewer pixels than the whole warp.
TEST(VisibleWarpRuns, BilinearFramesAreTheSameBytesWithFewerPixelsWarped) {
  const auto [whole, visible] =
      expect_same_frames("four-cubes", "compound", 24, Sampling::kBilinear);
  EXPECT_LT(visible, whole);
}

// Mipmap sampling (--sampling mipmap --warp visible against --warp whole): the cubes' layers
// sampled through the pyramids kept with their textures and caches (the kernels' partial
// warps on two blended levels: tests/core/image/partial_warp_test.cpp).
TEST(VisibleWarpRuns, MipmapFramesAreTheSameBytesWithFewerPixelsWarped) {
  const auto [whole, visible] = expect_same_frames("four-cubes", "compound", 12, Sampling::kMipmap);
  EXPECT_LT(visible, whole);
}

// The street seen from inside is a corridor: no animated layer hides another (each side's
// walls are coplanar, the closing facade lies between them), and a wall reaching out of the
// frame beyond the guard band is a clipped render, drawn exactly and only within the frame.
// Walking straight on (the walk's first 90 frames), every warped layer lies whole in the frame:
// nothing to leave out, the same pixels warped. Turning right (from frame 90), the left walls
// slide out of the frame while still warped: their pixels beyond the frame's left edge are
// left out.
TEST(VisibleWarpRuns, StreetWarpsFewerPixelsOnceItsWallsLeaveTheFrame) {
  const auto [straight_whole, straight_visible] = expect_same_frames("street", "walk", 6);
  EXPECT_EQ(straight_visible, straight_whole);
  const auto [whole, visible] = expect_same_frames("street", "walk", 14, Sampling::kNearest, 96);
  EXPECT_LT(visible, whole);
}

// compare's figure (PolicyRow::pixels_warped, its JSON and summary.csv): the pixels computed,
// fewer than those written under the visible-only warp, all of them under `whole`.
TEST(VisibleWarpRuns, ComparesPixelsWarpedBesideThePixelsWritten) {
  RunSource source;
  source.scene = std::make_shared<const Scene>(read_scene_file(resolve_scene_path("four-cubes")));
  source.viewer = read_viewer_script_file(resolve_viewer_script_path("compound"));
  PlayOptions quick;
  quick.max_frames = 12;
  quick.timing_repetitions = 1;
  quick.warm_up = false;
  const auto row = [&](WarpArea area) {
    source.settings.engine.warp_area = area;
    return policy_row(
        run_policies(source_kind("scene"), source, parse_policy_list("perspective"), quick)
            .front());
  };
  const PolicyRow visible = row(WarpArea::kVisible), whole = row(WarpArea::kWhole);
  EXPECT_EQ(visible.pixels_written, whole.pixels_written);
  EXPECT_EQ(whole.pixels_warped, whole.pixels_written);
  EXPECT_LT(visible.pixels_warped, visible.pixels_written);
  EXPECT_LE(visible.pixels_warped_p95, visible.pixels_written_p95);
  EXPECT_EQ(policy_row_json(visible).at("pixels_warped"), visible.pixels_warped);
}

}  // namespace
}  // namespace oflab
