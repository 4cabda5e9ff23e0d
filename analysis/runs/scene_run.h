// Runs a viewer script through a scene with the scene animator (core/scene/scene_animator.h) and,
// in the same run and frame by frame, the two baselines: the core's exact re-render of
// every visible polygon (mode rerender) and, on request, the conventional VTK renderer
// (analysis/runs/vtk_scene_renderer.h). Reports per frame and in summary.
#pragma once

#include <array>
#include <functional>
#include <iosfwd>
#include <nlohmann/json_fwd.hpp>
#include <vector>

#include "scene/scene_animator.h"
#include "scene/viewer_script.h"

namespace oflab {

struct SceneRunOptions {
  SceneSettings settings;
  int max_frames = -1;        // at most this many frames (-1: the whole script)
  bool run_baseline = true;   // the exact re-render (mode rerender, same culling and skipping)
  bool conventional = false;  // the VTK renderer (needs an X display)
  // Called after each frame with (frames done, total).
  std::function<void(int, int)> progress;
  // Called with each composited frame of the engine (camera-sized, premultiplied).
  std::function<void(int, const Image&)> on_frame;
};

struct SceneRunSummary {
  int frames = 0;
  int polygons = 0;
  BspStats bsp;
  std::array<long, kLevelCount> polygon_levels{};  // drawn polygons per level, over frames
  long back_facing = 0;
  long outside_frustum = 0;
  long hidden = 0;
  long clipped = 0;
  double hidden_area_px = 0.0;  // image area of the hidden polygons, over frames
  std::int64_t pixels = 0;      // warp kernel pixels of the engine
  std::int64_t baseline_pixels = 0;
  double time_ms = 0.0;
  double visibility_time_ms = 0.0;  // of time_ms, the hidden test
  double baseline_time_ms = 0.0;
  double conventional_time_ms = 0.0;
  double median_frame_ms = 0.0;               // engine
  double baseline_median_frame_ms = 0.0;      // exact re-render (NaN when not run)
  double conventional_median_frame_ms = 0.0;  // VTK (NaN when not run)
  double time_saved = 0.0;                    // 1 - engine time / re-render time
  double work_saved = 0.0;                    // 1 - engine pixels / re-render pixels
  double max_measured_error_px = 0.0;
  double mean_psnr_db = 0.0;      // engine frame against the exact frame (NaN when not run)
  double conventional_iou = 0.0;  // mean alpha-mask IoU of VTK against the exact frame
  long culled() const { return back_facing + outside_frustum; }
  long drawn() const;
};

struct SceneRun {
  std::vector<AnimationFrame> reports;
  std::vector<double> baseline_ms;      // per frame (NaN when not run)
  std::vector<double> conventional_ms;  // per frame (NaN when not run)
  std::vector<double> psnr_db;          // per frame, engine against exact (NaN when not run)
  SceneRunSummary summary;
};

// Plays the script. Throws std::invalid_argument for an invalid scene or settings (see
// SceneAnimator) and std::runtime_error when the conventional renderer cannot start.
SceneRun run_scene_animation(const Scene& scene, const ViewerScript& script,
                             const SceneRunOptions& options);

// Fills run.summary (except conventional_iou) from the per-frame reports and timings.
// Precondition: baseline_ms, conventional_ms and psnr_db hold one value per report (NaN
// where not measured); the summary starts zeroed.
void summarise_scene_run(SceneRun& run);

// One CSV row per frame (header first); columns documented in manual/scenes.md.
void write_scene_frame_csv(std::ostream& out, const SceneRun& run);

// Frame `i` of `script` on a scene renderer (SceneAnimator, SceneShiftingRenderer): the
// start at frame 0, otherwise the step from frame i - 1 with that frame's motion.
// Precondition: 0 <= i < script.frames.size(), frames played in order.
template <class Renderer>
auto play_frame(Renderer& renderer, const ViewerScript& script, int i) {
  return i == 0 ? renderer.start(script.frames[0].pose)
                : renderer.advance(script.frames[i - 1].pose, script.frames[i - 1].motion,
                                   script.frames[i].pose);
}

// Lines of the text summary shared by the scene forms of `oflab-cli animate`:
// "  polygons per level (N drawn polygon-frames):" and a line per level with its count and
// percent; leaves `out` in fixed notation with one decimal.
void print_polygon_levels(const SceneRunSummary& summary, std::ostream& out);
// "  time saved ...% against the exact re-render, work saved ...% (pixels written ...)" and
// "  max measured error ... px, mean PSNR against the exact frame ... dB", in the stream's
// current notation.
void print_savings_and_error(const SceneRunSummary& summary, std::ostream& out);

// The summary as JSON: polygon_levels {none, translate, affine, perspective, rerender},
// culled, hidden, median_frame_ms {engine, rerender, conventional} and the rest.
nlohmann::json scene_summary_json(const SceneRunSummary& summary);

// Alpha-mask intersection over union of two same-sized images (alpha > 127 is covered).
double alpha_iou(const Image& a, const Image& b);

}  // namespace oflab
