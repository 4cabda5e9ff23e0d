// Runs a motion script through the engine (core/engine/engine.h), measures the truth next to the
// engine's estimates (corner error, PSNR against an exact render), and runs the
// re-render baseline on the same frames so savings are measured in the same run.
#pragma once

#include <array>
#include <functional>
#include <iosfwd>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "engine/engine.h"
#include "engine/script.h"

namespace oflab {

struct AnimationOptions {
  EngineSettings settings;
  int max_frames = -1;        // run at most this many frames (-1: the whole script)
  bool measure_psnr = true;   // render exactly each frame and compare (not timed)
  bool run_baseline = true;   // also run mode re-render on the same frames
  // Called after each frame with (frames done, total); may print progress.
  std::function<void(int, int)> progress;
  // Called with each displayed frame (camera-sized, premultiplied), e.g. to save PNGs.
  std::function<void(int, const Image&)> on_frame;
};

struct AnimationSummary {
  int frames = 0;
  std::array<int, kLevelCount> levels{};  // frame counts per Level
  int invisible_frames = 0;
  double time_ms = 0.0;            // total engine time over the frames
  double baseline_time_ms = 0.0;   // total time of mode re-render on the same frames
  double median_frame_ms = 0.0;
  double baseline_median_frame_ms = 0.0;
  std::int64_t pixels = 0;         // pixels written by warp kernels
  std::int64_t baseline_pixels = 0;
  double time_saved = 0.0;         // 1 - time / baseline time
  double work_saved = 0.0;         // 1 - pixels / baseline pixels
  double max_measured_error_px = 0.0;
  double mean_psnr_db = 0.0;       // over visible frames (NaN if none or not measured)
};

struct AnimationRun {
  std::vector<FrameReport> reports;
  std::vector<double> psnr_db;  // per frame; NaN when not visible or not measured
  AnimationSummary summary;
};

// Plays `script` (at most options.max_frames frames) with `texture`. Never throws for
// frames the plane cannot be drawn in: they are reported as not visible.
AnimationRun run_animation(const MotionScript& script, const Layer& texture,
                           const AnimationOptions& options);

// The displayed image of the engine's current frame, camera-sized and premultiplied.
Image compose_frame(const Camera& camera, const PlacedLayer& layer);

// One CSV row per frame (header first); columns documented in manual/animation.md.
void write_frame_csv(std::ostream& out, const AnimationRun& run);

// The summary as JSON: frames, levels {none, translate, affine, perspective, rerender},
// time_saved, work_saved, max_measured_error_px, mean_psnr_db and the raw totals.
nlohmann::json summary_json(const AnimationSummary& summary);

}  // namespace oflab
