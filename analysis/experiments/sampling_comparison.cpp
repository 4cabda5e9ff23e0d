// The measurement of the sampling experiment: a script under each sampling of the warps
// against an exact supersampled render (sampling_comparison.h).
#include "experiments/sampling_comparison.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <memory>
#include <stdexcept>

#include "engine/animator.h"
#include "engine/exact_render.h"
#include "engine/reuse_policy.h"
#include "formats/datasets.h"
#include "formats/script_file.h"
#include "image/composite.h"
#include "image/image_compare.h"
#include "image/mip_pyramid.h"
#include "runs/statistics.h"

namespace oflab {
namespace {

constexpr Sampling kSamplings[] = {Sampling::kNearest, Sampling::kBilinear, Sampling::kMipmap};

Camera finer_camera(const Camera& camera, int factor) {
  Camera c = camera;
  c.focal_px *= factor;
  c.cx *= factor;
  c.cy *= factor;
  c.width *= factor;
  c.height *= factor;
  return c;
}

Camera smaller_camera(const Camera& camera, int divisor) {
  Camera c = camera;
  c.focal_px /= divisor;
  c.cx /= divisor;
  c.cy /= divisor;
  c.width /= divisor;
  c.height /= divisor;
  return c;
}

// Area of the shown outline (pixels squared), 0 when nothing is shown.
double outline_area(const Animator& animator) {
  const std::vector<LayerOutline> outlines = animator.outlines();
  if (outlines.empty() || outlines[0].points.size() < 3) return 0.0;
  const std::vector<Vec2>& p = outlines[0].points;
  double twice = 0.0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    const Vec2& a = p[k];
    const Vec2& b = p[(k + 1) % p.size()];
    twice += a.x * b.y - b.x * a.y;
  }
  return 0.5 * std::abs(twice);
}

// One pass of the script under `sampling`: every frame's level, minification and warp time,
// and, when `references` is given, its PSNR against them.
std::vector<SamplingFrame> play(const MotionScript& script, const Layer& texture,
                                const EngineSettings& settings,
                                const std::vector<Image>* references) {
  std::unique_ptr<Animator> animator = make_plane_animator(script, texture.image, settings);
  std::vector<SamplingFrame> frames;
  double source_area = 0.0;  // the outline when the shown layer's source was made
  for (int k = 0; k < animator->frame_count(); ++k) {
    const AnimationFrame f = k == 0 ? animator->start() : animator->advance();
    SamplingFrame row;
    row.frame = k;
    const FrameReport& report = f.layer_reports.at(0);
    row.level = report.level;
    row.warp_ms = report.warp_ms;
    const double area = outline_area(*animator);
    if (row.level == Level::kRerender || row.level == Level::kPerspective) source_area = area;
    if (row.level != Level::kRerender && area > 0.0) {
      row.minification = std::sqrt(source_area / area);
    }
    if (references) row.psnr_db = psnr_db(animator->image(), (*references)[std::size_t(k)]);
    frames.push_back(row);
  }
  return frames;
}

void summarise(SamplingRun& run) {
  std::vector<double> minified, warps;
  for (const SamplingFrame& f : run.frames) {
    if (f.minification > kMinifiedFactor) minified.push_back(f.psnr_db);
    if (f.level == Level::kAffine || f.level == Level::kPerspective) warps.push_back(f.warp_ms);
  }
  if (!minified.empty()) {
    double sum = 0.0;
    for (double v : minified) sum += v;
    run.minified_psnr_db = sum / static_cast<double>(minified.size());
  }
  if (!warps.empty()) run.median_warp_ms = median_of(warps);
}

}  // namespace

Image supersampled_exact_frame(const Camera& camera, const Layer& texture, const PlanePose& pose,
                               int samples_per_axis) {
  const Camera fine = finer_camera(camera, samples_per_axis);
  const PlacedLayer placed = render_exact(fine, texture, pose, Sampling::kBilinear);
  Image frame(fine.width, fine.height);
  composite_over(frame, placed.layer, placed.offset_x, placed.offset_y);
  return box_reduce(frame, samples_per_axis);
}

SamplingSpec sampling_spec(bool quick) {
  SamplingSpec spec;
  spec.camera_divisor = quick ? 4 : 1;
  spec.timing_passes = quick ? 1 : 5;
  return spec;
}

const SamplingRun& SamplingComparison::run(Sampling sampling) const {
  for (const SamplingRun& r : runs) {
    if (r.sampling == sampling) return r;
  }
  throw std::invalid_argument(std::string("no run of sampling ") + sampling_name(sampling));
}

double SamplingComparison::mipmap_gain_db() const {
  return run(Sampling::kMipmap).minified_psnr_db - run(Sampling::kBilinear).minified_psnr_db;
}

double SamplingComparison::warp_time_ratio() const {
  return run(Sampling::kMipmap).median_warp_ms / run(Sampling::kBilinear).median_warp_ms;
}

SamplingComparison compare_samplings(const Layer& texture, const SamplingSpec& spec) {
  EngineSettings settings;
  settings.policy = &reuse_policy(spec.policy);
  return compare_samplings(texture, read_script_file(resolve_script_path(spec.script)), settings,
                           spec);
}

SamplingComparison compare_samplings(const Layer& texture, MotionScript script,
                                     EngineSettings settings, const SamplingSpec& spec) {
  script.camera = smaller_camera(script.camera, spec.camera_divisor);
  std::vector<Image> references;
  for (const ScriptFrame& f : script.frames) {
    references.push_back(supersampled_exact_frame(script.camera, texture, f.pose));
  }
  SamplingComparison comparison;
  comparison.spec = spec;
  comparison.frames = static_cast<int>(script.frames.size());
  // Passes interleave the samplings, so that a slow moment of the machine hits each alike;
  // the PSNRs come from the first pass, each frame's warp time is its median over the passes.
  std::vector<std::vector<std::vector<double>>> times(std::size(kSamplings));
  for (int pass = 0; pass < std::max(spec.timing_passes, 1); ++pass) {
    for (std::size_t s = 0; s < std::size(kSamplings); ++s) {
      settings.sampling = kSamplings[s];
      std::vector<SamplingFrame> frames =
          play(script, texture, settings, pass == 0 ? &references : nullptr);
      times[s].resize(frames.size());
      for (std::size_t k = 0; k < frames.size(); ++k) times[s][k].push_back(frames[k].warp_ms);
      if (pass == 0) comparison.runs.push_back(SamplingRun{kSamplings[s], std::move(frames)});
    }
  }
  for (std::size_t s = 0; s < comparison.runs.size(); ++s) {
    SamplingRun& run = comparison.runs[s];
    for (std::size_t k = 0; k < run.frames.size(); ++k)
      run.frames[k].warp_ms = median_of(times[s][k]);
    summarise(run);
  }
  for (const SamplingFrame& f : comparison.runs[0].frames) {
    comparison.minified_frames += f.minification > kMinifiedFactor;
  }
  return comparison;
}

}  // namespace oflab
