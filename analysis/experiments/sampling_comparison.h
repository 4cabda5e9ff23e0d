// The measurement of the sampling experiment (experiments_sampling.h: shrinking without
// shimmering, dissertation section 7.5.5): a script played under each sampling of the warps
// (core/image/warp.h: nearest, bilinear, mipmap), every frame measured against an exact
// supersampled render (kSupersamplesPerAxis^2 samples per pixel, a box filter, of the exact
// projection), which is what a minified layer should look like: the PSNR per frame, its mean
// over the reused frames whose layer is minified by more than kMinifiedFactor (the gap mipmap
// gains over bilinear there), and the warps' median time per reused frame. The experiment
// reports it; the lesson claim `sampling_psnr_gain` (session/player/engine_claims.h) measures
// it on the state the lesson plays. Plain C++ over core and the script reader (the browser
// page compiles it).
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "engine/decision.h"
#include "engine/engine.h"
#include "engine/script.h"
#include "flow/camera.h"
#include "flow/plane.h"
#include "image/layer.h"
#include "image/warp.h"

namespace oflab {

constexpr int kSupersamplesPerAxis = 4;  // 16 samples per pixel, a 4 x 4 box
constexpr double kMinifiedFactor = 1.5;  // a reused frame counts as minified beyond this

// The exact image of `pose` with `samples_per_axis`^2 samples per pixel: the texture warped
// bilinearly by the exact projection into a camera `samples_per_axis` times finer, then
// box_reduce'd (core/image/mip_pyramid.h). A camera-sized frame, transparent where the plane
// is not. Precondition: the plane is visible whole (plane_visibility_problem empty).
Image supersampled_exact_frame(const Camera& camera, const Layer& texture, const PlanePose& pose,
                               int samples_per_axis = kSupersamplesPerAxis);

struct SamplingFrame {
  int frame = 0;
  Level level = Level::kRerender;
  // How many times smaller the shown layer draws the plane than the layer it was warped
  // from did when that was made (a re-render or a perspective update): the square root of
  // the ratio of the displayed outline's areas then and now. NaN in a re-rendered frame.
  double minification = std::numeric_limits<double>::quiet_NaN();
  double psnr_db = 0.0;  // the frame against supersampled_exact_frame, dB
  double warp_ms = 0.0;  // the engine's warps this frame (FrameReport::warp_ms)
};

struct SamplingRun {
  Sampling sampling = Sampling::kNearest;
  std::vector<SamplingFrame> frames;
  // Mean PSNR (dB) over the minified frames (minification > kMinifiedFactor; NaN when none),
  // and the median warp time (ms) over the reused frames with a warp (affine, perspective).
  double minified_psnr_db = std::numeric_limits<double>::quiet_NaN();
  double median_warp_ms = std::numeric_limits<double>::quiet_NaN();
};

struct SamplingSpec {
  std::string script = "recede";  // a shipped script's name or a file
  std::string policy = "exact";   // the reuse policy (core/engine/reuse_policy.h)
  int camera_divisor = 1;         // the script's camera shrunk by this (small frames)
  int timing_passes = 3;          // passes of each sampling; the warp times are medians
};

// Full: recede at 640 x 480 under the exact policy, 5 passes; quick: at 160 x 120, 1 pass.
SamplingSpec sampling_spec(bool quick);

struct SamplingComparison {
  SamplingSpec spec;
  int frames = 0;
  int minified_frames = 0;        // the same frames under every sampling (the geometry is)
  std::vector<SamplingRun> runs;  // nearest, bilinear, mipmap
  const SamplingRun& run(Sampling sampling) const;
  double mipmap_gain_db() const;   // mipmap's minified PSNR minus bilinear's
  double warp_time_ratio() const;  // mipmap's median warp time over bilinear's
};

// Plays spec.script under each sampling with `texture` (premultiplied; the experiment's is
// make_fabric_texture, analysis/generators/fabric_texture.h) and the default engine settings
// under spec.policy, and measures every frame. Throws std::invalid_argument for an unknown
// policy or a script it cannot read.
SamplingComparison compare_samplings(const Layer& texture, const SamplingSpec& spec);

// The same for `script` itself (spec.script only names it) played with `settings` (their
// sampling set to each in turn; spec.policy is not read). Precondition: the plane is visible
// whole on every frame of `script` (plane_visibility_problem empty).
SamplingComparison compare_samplings(const Layer& texture, MotionScript script,
                                     EngineSettings settings, const SamplingSpec& spec);

}  // namespace oflab
