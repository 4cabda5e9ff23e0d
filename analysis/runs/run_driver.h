// The one run driver: plays any Animator (core/engine/animator.h) frame by frame and, in the
// same loop, an optional baseline animator (the same source re-rendered exactly every frame)
// for time, work and PSNR, and an optional conventional renderer (VTK, for scenes). The
// three take turns frame by frame, so a busy machine slows them alike. What a kind of
// source adds (its factory, CSV and JSON summary) is analysis/runs/source_kinds.h.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <limits>
#include <nlohmann/json.hpp>
#include <vector>

#include "engine/animator.h"
#include "image/image.h"

namespace oflab {

class VtkSceneRenderer;

// Timed passes of `oflab-cli animate` unless --repeat-timing says otherwise.
constexpr int kDefaultTimingRepetitions = 15;

// One frame of a run as the driver hands it on: the frame (its times, and its layer reports'
// times, the medians over the timed passes), its PSNR against the baseline and the
// baseline's and conventional renderer's times in milliseconds (NaN: not measured, not run).
struct FrameRecord {
  const AnimationFrame& frame;
  double psnr_db;
  double baseline_ms;
  double conventional_ms;
  // Mean SSIM against the baseline (core/image/image_compare.h mean_ssim), NaN when not
  // measured (RunOptions::measure_ssim false, no baseline, or a frame under 11 x 11 pixels).
  double ssim = std::numeric_limits<double>::quiet_NaN();
};

struct RunOptions {
  int max_frames = -1;  // play at most this many frames (-1: all of the animator's)
  // A first pass whose times are thrown away (caches, allocator and branch predictors
  // warmed up); the frames, PSNR, IoU and on_frame come from the first pass either way.
  bool warm_up = false;
  // Timed passes (>= 1); per-frame times are medians over them.
  int timing_repetitions = 1;
  // Timed passes with the conventional renderer: the first this many (-1: all). It also
  // renders in the first pass, warm-up or not, and in the recording pass, for the IoU.
  int conventional_repetitions = -1;
  // PSNR of frames in which the animator drew nothing: measured (both images usually empty:
  // kIdenticalPsnrDb) when true, NaN when false (the single plane's "not visible" frames).
  bool psnr_when_nothing_drawn = true;
  // Also the SSIM of each recorded frame against the baseline (FrameRecord::ssim), where the
  // PSNR is measured; off by default, as it costs about as much as a frame's warp.
  bool measure_ssim = false;
  // Called after each frame of each pass with (frames done, total over all passes).
  std::function<void(int, int)> progress;
  // Called with each frame's image (camera-sized, premultiplied), e.g. to save PNGs.
  std::function<void(int, const Image&)> on_frame;
  // Called with each recorded frame's animator and baseline (null without one) right after
  // the frame, in frame order, e.g. to save the shown and the exact image and the layers'
  // outlines (Animator::image(), outlines()).
  std::function<void(int, const Animator&, const Animator*)> on_animators;
  // Called with each frame's view (Animator::view(): what the frame shows, as a viewer pose)
  // in the first pass, e.g. to check that two runs played the same poses.
  std::function<void(int, const ViewerPose&)> on_view;
  // Called with each frame's record, once per frame and in frame order: as the frames are
  // played when there is one timed pass, after the last pass otherwise (the medians need
  // them all). E.g. to write the per-frame CSV as a long run goes.
  std::function<void(const FrameRecord&)> on_record;
  // Keep every frame's record in the returned run (AnimationRun's per-frame vectors). With
  // false they come back empty and, with one timed pass, a run's memory does not grow with
  // its frames but for 8 bytes per frame per timed series (engine, baseline, conventional)
  // kept for the exact median frame times: long runs read the records through on_record.
  bool keep_frames = true;
};

// The hierarchical image cache's totals over a run (AnimationFrame::cache, core/engine/
// animator.h): the grouping's nodes, node-frames drawn, renders and their causes, overlap
// pixels, the per-pixel error (max, and mean over every measured pixel), the largest corner
// angle of a reused node and the threshold in pixels (f tan(angle)).
struct NodeCacheTotals {
  bool active = false;
  int nodes = 0;
  long node_frames = 0;
  long renders = 0;
  long fresh = 0;
  long by_angle = 0;
  long by_sphere = 0;
  long uncacheable = 0;
  std::int64_t overlap_pixels = 0;
  double max_pixel_error_px = 0.0;
  double mean_pixel_error_px = 0.0;
  std::int64_t error_pixels = 0;
  double max_angle_deg = 0.0;
  double threshold_px = 0.0;
  // Adds one frame's figures (the mean weighted by measured pixels).
  void add(const NodeCacheFrame& frame);
};
nlohmann::json node_cache_json(const NodeCacheTotals& totals);

// Totals over a run. Times in milliseconds of wall time; "baseline" is the exact re-render
// of the same frames, "conventional" the VTK renderer (NaN medians when not run).
struct RunSummary {
  int frames = 0;
  int layers = 0;                          // of the source (polygons of a scene)
  std::array<long, kLevelCount> levels{};  // drawn layers per level, summed over the frames
  long back_facing = 0;
  long outside_frustum = 0;
  long hidden = 0;
  long clipped = 0;
  double hidden_area_px = 0.0;  // image area of the hidden layers, over the frames
  std::int64_t pixels = 0;      // written by the animator's warp kernels
  std::int64_t baseline_pixels = 0;
  double time_ms = 0.0;
  double visibility_time_ms = 0.0;  // of time_ms, the hidden test
  double baseline_time_ms = 0.0;
  double conventional_time_ms = 0.0;
  double median_frame_ms = 0.0;
  double baseline_median_frame_ms = 0.0;
  double conventional_median_frame_ms = 0.0;
  double time_saved = 0.0;  // 1 - time / baseline time (0 without a baseline)
  double work_saved = 0.0;  // 1 - pixels / baseline pixels (0 without a baseline)
  // The cost model's work (core/engine/cost_model.h: pixels of a perspective warp, a re-render
  // at its content's cost), of the animator and of the baseline; deterministic.
  double model_work = 0.0;
  double baseline_model_work = 0.0;
  double model_work_saved = 0.0;       // 1 - model_work / baseline_model_work (0 without one)
  double render_ms = 0.0;              // of time_ms, rendering contents (re-renders)
  double max_photometric_error = 0.0;  // grey levels (FrameReport::photometric_error)
  double max_measured_error_px = 0.0;
  // Hole pixels over the frames (AnimationFrame::hole_pixels), and whether the policy
  // reports them (AnimationFrame::reports_holes: the summaries then carry the total).
  std::int64_t hole_pixels = 0;
  bool reports_holes = false;
  // The causes of the re-renders, summed over the frames (AnimationFrame::rerender_causes).
  RerenderCauses rerender_causes;
  // Measured minus estimated error (FrameReport) of the worst visible engine layer report
  // over the run, pixels: at most 0 when the estimates bound the truth; NaN when there was
  // no such report (scene shifting keeps no per-layer books).
  double max_excess_px = std::numeric_limits<double>::quiet_NaN();
  double mean_psnr_db = 0.0;  // over the finite per-frame PSNRs (NaN when none)
  double mean_ssim = std::numeric_limits<double>::quiet_NaN();  // over the measured SSIMs
  std::int64_t inpainted_pixels = 0;  // AnimationFrame::inpainted_pixels over the frames
  // A policy that shares a per-frame budget (AnimationFrame::budget, core/engine/budget.h):
  // frames with the budget active (all but the first), frames whose layers spent more than
  // the budget (the rule keeps this 0), starved layer-frames, and the mean optimality gap
  // over the gap_frames in which exhaustive search checked the greedy allocation (NaN when
  // none did).
  long budget_frames = 0;
  long frames_over_budget = 0;
  long starved_layer_frames = 0;
  long gap_frames = 0;
  double mean_optimality_gap = std::numeric_limits<double>::quiet_NaN();
  NodeCacheTotals cache;          // the hierarchical-cache policy only (cache.active)
  double conventional_iou = 0.0;  // mean alpha-mask IoU of VTK against the baseline (or NaN)
  long culled() const { return back_facing + outside_frustum; }
  long drawn() const;  // sum of levels
};

struct AnimationRun {
  // Per frame, empty when RunOptions::keep_frames is false.
  std::vector<AnimationFrame> frames;
  std::vector<double> psnr_db;          // per frame, animator against baseline (NaN: not measured)
  std::vector<double> baseline_ms;      // per frame (NaN when not run)
  std::vector<double> conventional_ms;  // per frame (NaN when not run)
  RunSummary summary;
  // What only this kind of source reports, filled by its SourceKind (source_kinds.h).
  nlohmann::json facts;
};

// Plays `animator` from start() for min(frame_count, max_frames) frames, as many passes as
// options say (warm-up and timed passes, each restarting from start()). `baseline` (may be
// null) must play the same frames from the same source; its image is the PSNR reference.
// `conventional` (may be null) renders animator.scene() from animator.view() each frame;
// its IoU is measured against the baseline's image. The frames recorded (returned, and
// handed to on_record and on_frame) are those of one pass: the first when there are several
// timed passes, with every time (the frame's, its parts, its layer reports', the
// baseline's and the conventional renderer's) replaced by its median over the timed passes;
// the timed pass itself when there is one (the frames' facts are the same in every pass).
// The summary is accumulated frame by frame. Throws what the animators throw, and
// std::invalid_argument for timing_repetitions < 1.
AnimationRun run_animator(Animator& animator, Animator* baseline, VtkSceneRenderer* conventional,
                          const RunOptions& options);

// Alpha-mask intersection over union of two same-sized images (alpha > 127 is covered);
// 1 when neither covers a pixel.
double alpha_iou(const Image& a, const Image& b);

}  // namespace oflab
