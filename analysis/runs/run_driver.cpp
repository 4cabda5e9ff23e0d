#include "runs/run_driver.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "image/image_compare.h"
#include "runs/statistics.h"
#include "runs/vtk_scene_renderer.h"

namespace oflab {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The summary's totals from the per-frame records (baseline pixels and the IoU are summed
// in the loop, where the baseline's frames are at hand).
void summarise(AnimationRun& run) {
  RunSummary& s = run.summary;
  std::vector<double> times;
  double psnr_sum = 0.0;
  int psnr_count = 0;
  for (std::size_t i = 0; i < run.frames.size(); ++i) {
    const AnimationFrame& f = run.frames[i];
    for (int l = 0; l < kLevelCount; ++l) s.levels[l] += f.levels[l];
    s.back_facing += f.back_facing;
    s.outside_frustum += f.outside_frustum;
    s.hidden += f.hidden;
    s.clipped += f.clipped;
    s.hidden_area_px += f.hidden_area_px;
    s.pixels += f.pixels_written;
    s.time_ms += f.time_ms;
    s.visibility_time_ms += f.visibility_ms;
    s.max_measured_error_px = std::max(s.max_measured_error_px, f.max_measured_error_px);
    for (const FrameReport& r : f.layer_reports) {
      if (!r.visible || !std::isfinite(r.measured_error_px)) continue;
      const double excess = r.measured_error_px - r.estimated_error_px;
      s.max_excess_px = std::isnan(s.max_excess_px) ? excess : std::max(s.max_excess_px, excess);
    }
    times.push_back(f.time_ms);
    if (std::isfinite(run.baseline_ms[i])) s.baseline_time_ms += run.baseline_ms[i];
    if (std::isfinite(run.conventional_ms[i])) s.conventional_time_ms += run.conventional_ms[i];
    if (std::isfinite(run.psnr_db[i])) {
      psnr_sum += run.psnr_db[i];
      ++psnr_count;
    }
  }
  s.median_frame_ms = median_of(times);
  s.baseline_median_frame_ms = median_of(run.baseline_ms);
  s.conventional_median_frame_ms = median_of(run.conventional_ms);
  s.mean_psnr_db = psnr_count ? psnr_sum / psnr_count : kNaN;
  s.time_saved = s.baseline_time_ms > 0.0 ? 1.0 - s.time_ms / s.baseline_time_ms : 0.0;
  s.work_saved = s.baseline_pixels > 0
                     ? 1.0 - static_cast<double>(s.pixels) / static_cast<double>(s.baseline_pixels)
                     : 0.0;
}

}  // namespace

long RunSummary::drawn() const {
  long n = 0;
  for (long c : levels) n += c;
  return n;
}

double alpha_iou(const Image& a, const Image& b) {
  long both = 0, either = 0;
  const std::size_t n = std::min(a.pixels().size(), b.pixels().size());
  for (std::size_t i = 0; i < n; ++i) {
    const bool p = a.pixels()[i].a > 127, q = b.pixels()[i].a > 127;
    both += p && q;
    either += p || q;
  }
  return either ? static_cast<double>(both) / static_cast<double>(either) : 1.0;
}

AnimationRun run_animator(Animator& animator, Animator* baseline, VtkSceneRenderer* conventional,
                          const RunOptions& options) {
  AnimationRun run;
  const int all = animator.frame_count();
  const int frames = options.max_frames < 0 ? all : std::min(all, options.max_frames);
  double iou_sum = 0.0;
  for (int i = 0; i < frames; ++i) {
    run.frames.push_back(i == 0 ? animator.start() : animator.advance());
    const AnimationFrame& f = run.frames.back();
    double baseline_ms = kNaN, conventional_ms = kNaN, psnr = kNaN;
    if (baseline) {
      const AnimationFrame b = i == 0 ? baseline->start() : baseline->advance();
      baseline_ms = b.time_ms;
      run.summary.baseline_pixels += b.pixels_written;
      if (options.psnr_when_nothing_drawn || f.drawn() > 0) {
        psnr = psnr_db(animator.image(), baseline->image());
      }
    }
    if (conventional) {
      conventional_ms = conventional->render(animator.view());
      if (baseline) iou_sum += alpha_iou(conventional->image(), baseline->image());
    }
    run.baseline_ms.push_back(baseline_ms);
    run.conventional_ms.push_back(conventional_ms);
    run.psnr_db.push_back(psnr);
    if (options.on_frame) options.on_frame(i, animator.image());
    if (options.progress) options.progress(i + 1, frames);
  }
  run.summary.frames = frames;
  run.summary.layers = run.frames.empty() ? 0 : run.frames.front().layers;
  run.summary.conventional_iou = conventional && baseline && frames > 0 ? iou_sum / frames : kNaN;
  summarise(run);
  return run;
}

}  // namespace oflab
