#include "runs/scene_shifting_run.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "runs/statistics.h"
#include "image/image_compare.h"

namespace oflab {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

Level layer_level(LayerUpdate update) {
  switch (update) {
    case LayerUpdate::kStill:
      return Level::kNone;
    case LayerUpdate::kShifted:
      return Level::kTranslate;
    case LayerUpdate::kScaled:
      return Level::kAffine;
    case LayerUpdate::kRebuilt:
      break;
  }
  return Level::kRerender;
}

// The frame in the scene runs' terms: each drawn polygon at the level of its layer.
SceneFrameReport as_scene_frame(const SceneShiftingFrameReport& r,
                                const SceneShiftingRenderer& renderer, int polygons) {
  SceneFrameReport s;
  s.frame = r.frame;
  s.polygons = polygons;
  const std::vector<int>& slice_of = renderer.polygon_slices();
  for (int p = 0; p < polygons; ++p) {
    const int slice = slice_of[p];
    if (slice < 0 || renderer.shown_corners(p).empty()) {
      ++s.outside_frustum;
      continue;
    }
    ++s.levels[static_cast<int>(layer_level(r.updates[slice]))];
  }
  s.time_ms = r.time_ms;
  s.update_ms = r.time_ms;
  s.pixels_written = r.pixels_written;
  s.pixels_composited = r.pixels_composited;
  s.max_measured_error_px = r.max_measured_error_px;
  return s;
}

}  // namespace

double script_design_speed(const ViewerScript& script) {
  double speed = 0.0;
  for (const ViewerFrame& f : script.frames) {
    const Vec3 v = viewer_step(f.motion).translation;
    speed = std::max(speed, std::hypot(v.x, v.y));
  }
  return speed;
}

SceneShiftingRun run_scene_shifting(const Scene& scene, const ViewerScript& script,
                                    const SceneShiftingRunOptions& options) {
  SceneShiftingRun run;
  const int all = static_cast<int>(script.frames.size());
  const int frames = options.max_frames < 0 ? all : std::min(all, options.max_frames);
  SceneShiftingSettings settings = options.settings;
  if (settings.design_speed == 0.0) settings.design_speed = script_design_speed(script);
  run.design_speed = settings.design_speed;
  SceneShiftingRenderer renderer(scene, script.camera, settings);
  std::unique_ptr<SceneShiftingRenderer> exact;
  if (options.run_baseline) {
    SceneShiftingSettings always = settings;
    always.policy = &reuse_policy("rerender");
    exact = std::make_unique<SceneShiftingRenderer>(scene, script.camera, always);
  }
  const int polygons = static_cast<int>(scene.polygons.size());
  SceneRun& sr = run.scene_run;
  // The two renderers take turns frame by frame, so a busy machine slows them alike.
  for (int i = 0; i < frames; ++i) {
    const SceneShiftingFrameReport r = play_frame(renderer, script, i);
    if (i == 0) run.slices = renderer.slices();
    if (i > 0) {
      run.rebuilt_layers += r.rebuilt;
      run.shifted_layers += r.shifted + r.scaled;
    }
    if (r.view_turned) {
      ++run.turning_frames;
      if (r.rebuilt == r.occupied) ++run.turning_frames_all_rebuilt;
    }
    run.frames.push_back(r);
    sr.reports.push_back(as_scene_frame(r, renderer, polygons));
    double baseline_ms = kNaN, psnr = kNaN;
    if (exact) {
      const SceneShiftingFrameReport b = play_frame(*exact, script, i);
      baseline_ms = b.time_ms;
      sr.summary.baseline_pixels += b.pixels_written;
      psnr = psnr_db(renderer.frame(), exact->frame());
    }
    sr.baseline_ms.push_back(baseline_ms);
    sr.conventional_ms.push_back(kNaN);
    sr.psnr_db.push_back(psnr);
    if (options.on_frame) options.on_frame(i, renderer.frame());
    if (options.progress) options.progress(i + 1, frames);
  }
  sr.summary.frames = frames;
  sr.summary.polygons = polygons;
  summarise_scene_run(sr);
  sr.summary.conventional_iou = kNaN;
  return run;
}

}  // namespace oflab
