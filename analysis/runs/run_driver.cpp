#include "runs/run_driver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

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
    s.model_work += f.model_work;
    s.render_ms += f.render_ms;
    s.max_photometric_error = std::max(s.max_photometric_error, f.max_photometric_error);
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
  s.model_work_saved = s.baseline_model_work > 0.0 ? 1.0 - s.model_work / s.baseline_model_work
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

namespace {

// One frame's times in each timed pass, for the medians.
struct TimeSamples {
  std::vector<double> frame, update, composite, visibility, render, baseline, conventional;
  // Per layer report: its time, render and warp times.
  std::vector<std::vector<double>> layers, layer_render, layer_warp;
};

// The passes of one run: the first records the frames (and PSNR, IoU, on_frame); the last
// `timed` ones are timed.
class RunLoop {
 public:
  RunLoop(Animator& animator, Animator* baseline, VtkSceneRenderer* conventional,
          const RunOptions& options)
      : animator_(animator), baseline_(baseline), conventional_(conventional), options_(options) {
    const int all = animator.frame_count();
    frames_ = options.max_frames < 0 ? all : std::min(all, options.max_frames);
    passes_ = options.timing_repetitions + (options.warm_up ? 1 : 0);
    samples_.resize(static_cast<std::size_t>(std::max(frames_, 0)));
  }

  AnimationRun run() {
    for (int pass = 0; pass < passes_; ++pass) play_pass(pass);
    take_medians();
    run_.summary.frames = frames_;
    run_.summary.layers = run_.frames.empty() ? 0 : run_.frames.front().layers;
    run_.summary.conventional_iou =
        conventional_ && baseline_ && frames_ > 0 ? iou_sum_ / frames_ : kNaN;
    summarise(run_);
    return std::move(run_);
  }

 private:
  bool conventional_in(int pass) const {
    if (!conventional_) return false;
    if (pass == 0) return true;  // the recording pass, for the IoU
    const int timed_index = pass - (options_.warm_up ? 1 : 0);
    return options_.conventional_repetitions < 0 || timed_index < options_.conventional_repetitions;
  }

  void play_pass(int pass) {
    const bool record = pass == 0;
    const bool timed = pass >= (options_.warm_up ? 1 : 0);
    const bool with_conventional = conventional_in(pass);
    for (int i = 0; i < frames_; ++i) {
      const AnimationFrame f = i == 0 ? animator_.start() : animator_.advance();
      double baseline_ms = kNaN, conventional_ms = kNaN;
      if (baseline_) {
        const AnimationFrame b = i == 0 ? baseline_->start() : baseline_->advance();
        baseline_ms = b.time_ms;
        if (record) {
          run_.summary.baseline_pixels += b.pixels_written;
          run_.summary.baseline_model_work += b.model_work;
        }
      }
      if (with_conventional) conventional_ms = conventional_->render(animator_.view());
      if (record) record_frame(i, f);
      if (timed)
        add_samples(samples_[static_cast<std::size_t>(i)], f, baseline_ms, conventional_ms);
      if (options_.progress) options_.progress(pass * frames_ + i + 1, passes_ * frames_);
    }
  }

  // The frame's deterministic facts, its PSNR and IoU against the baseline, on_frame.
  void record_frame(int i, const AnimationFrame& f) {
    run_.frames.push_back(f);
    double psnr = kNaN;
    if (baseline_ && (options_.psnr_when_nothing_drawn || f.drawn() > 0)) {
      psnr = psnr_db(animator_.image(), baseline_->image());
    }
    if (conventional_ && baseline_)
      iou_sum_ += alpha_iou(conventional_->image(), baseline_->image());
    run_.psnr_db.push_back(psnr);
    if (options_.on_frame) options_.on_frame(i, animator_.image());
    if (options_.on_view) options_.on_view(i, animator_.view());
  }

  static void add_samples(TimeSamples& t, const AnimationFrame& f, double baseline_ms,
                          double conventional_ms) {
    t.frame.push_back(f.time_ms);
    t.update.push_back(f.update_ms);
    t.composite.push_back(f.composite_ms);
    t.visibility.push_back(f.visibility_ms);
    t.render.push_back(f.render_ms);
    t.baseline.push_back(baseline_ms);
    t.conventional.push_back(conventional_ms);
    const std::size_t n = std::max(t.layers.size(), f.layer_reports.size());
    t.layers.resize(n);
    t.layer_render.resize(n);
    t.layer_warp.resize(n);
    for (std::size_t k = 0; k < f.layer_reports.size(); ++k) {
      t.layers[k].push_back(f.layer_reports[k].time_ms);
      t.layer_render[k].push_back(f.layer_reports[k].render_ms);
      t.layer_warp[k].push_back(f.layer_reports[k].warp_ms);
    }
  }

  void take_medians() {
    for (std::size_t i = 0; i < run_.frames.size(); ++i) {
      AnimationFrame& f = run_.frames[i];
      const TimeSamples& t = samples_[i];
      f.time_ms = median_of(t.frame);
      f.update_ms = median_of(t.update);
      f.composite_ms = median_of(t.composite);
      f.visibility_ms = median_of(t.visibility);
      f.render_ms = median_of(t.render);
      for (std::size_t k = 0; k < f.layer_reports.size() && k < t.layers.size(); ++k) {
        f.layer_reports[k].time_ms = median_of(t.layers[k]);
        f.layer_reports[k].render_ms = median_of(t.layer_render[k]);
        f.layer_reports[k].warp_ms = median_of(t.layer_warp[k]);
      }
      run_.baseline_ms.push_back(median_of(t.baseline));
      run_.conventional_ms.push_back(median_of(t.conventional));
    }
  }

  Animator& animator_;
  Animator* baseline_;
  VtkSceneRenderer* conventional_;
  const RunOptions& options_;
  int frames_ = 0;
  int passes_ = 0;
  std::vector<TimeSamples> samples_;  // per frame
  double iou_sum_ = 0.0;
  AnimationRun run_;
};

}  // namespace

AnimationRun run_animator(Animator& animator, Animator* baseline, VtkSceneRenderer* conventional,
                          const RunOptions& options) {
  if (options.timing_repetitions < 1) {
    throw std::invalid_argument("run_animator: timing_repetitions must be at least 1, not " +
                                std::to_string(options.timing_repetitions));
  }
  return RunLoop(animator, baseline, conventional, options).run();
}

}  // namespace oflab
