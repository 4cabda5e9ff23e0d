// Today's reprojection beside optic flow (beyond the dissertation; manual/policies.md
// "Today's reprojection"): timewarp, one stabilization plane, per-pixel depth, frame generation
// along motion vectors and the plane per layer on a fixed cadence, with optic flow's threshold rule
// (`perspective`) for reference, on every Experiment 2 scene under each of its viewer scripts
// (translate, zoom, rotate), on the street and on the city block: measured error, hole pixels,
// work, latency; a chart of error against work; the vendors' published figures quoted as theirs.
// Beside them the dissertation's named rivals: Talisman and Shade et al.'s hierarchical image
// cache, with the cache's nodes, renders by cause, seams and per-pixel error in a table of their
// own. Then every reuse method from 1993 to today on one motion (four cubes under translate):
// measured error, holes, inpainting, PSNR, SSIM, milliseconds per 1920 x 1080 frame on one
// thread and latency, with a chart of error against work, latency marked.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "experiments/experiments.h"
#include "runs/policy_runs.h"

namespace oflab {

struct ReprojectionSpec {
  int max_frames = 40;  // per source (the first frames of each viewer script)
  int cadence = 2;      // EngineSettings::cadence: spacewarp's half rate
  bool ssim = true;     // measure each frame's SSIM (RunOptions::measure_ssim); quick: false
  // The frame size each method of one_motion_policies() is timed at on one thread; its
  // milliseconds are scaled by the pixel count to 1920 x 1080 (1 at full size).
  int timing_width = 1920;
  int timing_height = 1080;
};
// Full: 40 frames per source with SSIM, timed at 1920 x 1080; quick: 12 without, timed at
// 480 x 270 (scaled by 16). Both at cadence 2, one timed pass without warm-up (the figures
// reported are deterministic but the times), so the whole section takes seconds.
ReprojectionSpec reprojection_spec(bool quick);

struct ReprojectionSource {
  std::string scene;
  std::string script;
  std::int64_t frame_pixels = 0;  // the viewer script's camera: width x height
  std::vector<PolicyRun> runs;    // one per policy of reprojection_policies(), in that order
};

// One method's time on one thread: the median over the frames it makes without rendering
// (warped, generated or interpolated; the threshold rule's every frame after the first) of
// AnimationFrame::time_ms (diagnostics and view interpolation's render made ahead left out),
// at the spec's timing size, and scaled by the pixel count to 1920 x 1080.
struct MethodTiming {
  const ReusePolicy* policy = nullptr;
  double ms = 0.0;
  double ms_1080p = 0.0;
  int frames = 0;  // frames timed
};

struct ReprojectionResult {
  ReprojectionSpec spec;
  std::vector<ReprojectionSource> sources;
  std::vector<MethodTiming> timings;  // one per policy of one_motion_policies(), in that order
};

// The policies compared: timewarp, stabilized-plane, depth-reprojection, cadence, frame
// generation's mv-extrapolation with and without inpainting, view-interpolation, depth-mesh,
// perspective, and the
// dissertation's two named rivals, talisman and hierarchical-cache.
std::vector<const ReusePolicy*> reprojection_policies();

// The methods of the one-motion table, 1993 to today: the layered perspective policy,
// timewarp, depth reprojection, frame generation by extrapolation with and without
// inpainting, view interpolation and textured depth meshes (each in reprojection_policies()).
std::vector<const ReusePolicy*> one_motion_policies();

// Times each policy of one_motion_policies() on four cubes under translate, the script's camera
// widened to width x height at the same vertical field of view, guard band 0.05 (SceneSettings:
// the default 0.5 puts four cubes over the scene memory limit at 1920 x 1080), on one thread
// (the worker threads are restored after): the first 9 frames (at cadence 2 four frames between
// renders). Throws what the readers and the scene engine throw.
std::vector<MethodTiming> time_one_motion(int width, int height, int cadence);

// The Experiment 2 scenes (single-1, two, five-collinear, four-cubes) under translate, zoom
// and rotate, then the street under walk and the city block under city-flyby, and the
// one-motion timings. Throws what the readers and runs throw.
ReprojectionResult run_reprojection_experiment(
    const ReprojectionSpec& spec, const std::function<void(const std::string&)>& progress);

ReportSection reprojection_section(const ReprojectionResult& result, ExperimentContext& context);

// The one-motion table: per method of one_motion_policies() its row on four cubes under
// translate (result.sources) and its timing (result.timings): the largest measured error px
// (a layer's corners, or a frame's per-pixel displacement), hole %
// and inpainted % (of every pixel of every frame), mean PSNR dB, mean SSIM ('-' when not
// measured), ms per 1920 x 1080 frame on one thread, latency frames. Throws
// std::invalid_argument when the result has no four cubes under translate or a timing is
// missing.
ReportTable one_motion_table(const ReprojectionResult& result);

}  // namespace oflab
