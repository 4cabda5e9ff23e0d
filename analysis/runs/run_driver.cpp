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

// The summary's totals, added frame by frame as the records come (baseline pixels and the
// IoU are summed in the loop, where the baseline's frames are at hand). Keeps the finite
// frame times (8 bytes each) for the exact medians.
class SummaryTotals {
 public:
  explicit SummaryTotals(RunSummary& summary) : s_(summary) {}

  void add(const FrameRecord& r) {
    const AnimationFrame& f = r.frame;
    if (first_) s_.layers = f.layers;
    first_ = false;
    for (int l = 0; l < kLevelCount; ++l) s_.levels[l] += f.levels[l];
    s_.back_facing += f.back_facing;
    s_.outside_frustum += f.outside_frustum;
    s_.hidden += f.hidden;
    s_.clipped += f.clipped;
    s_.hidden_area_px += f.hidden_area_px;
    s_.pixels += f.pixels_written;
    s_.model_work += f.model_work;
    s_.render_ms += f.render_ms;
    s_.max_photometric_error = std::max(s_.max_photometric_error, f.max_photometric_error);
    s_.time_ms += f.time_ms;
    s_.visibility_time_ms += f.visibility_ms;
    s_.max_measured_error_px = std::max(s_.max_measured_error_px, f.max_measured_error_px);
    s_.hole_pixels += f.hole_pixels;
    s_.inpainted_pixels += f.inpainted_pixels;
    s_.reports_holes = s_.reports_holes || f.reports_holes;
    const RerenderCauses& c = f.rerender_causes;
    RerenderCauses& sum = s_.rerender_causes;
    sum = {sum.schedule + c.schedule, sum.sampling_limit + c.sampling_limit,
           sum.refused + c.refused, sum.no_image + c.no_image, sum.clipped + c.clipped};
    for (const FrameReport& l : f.layer_reports) {
      if (!l.visible || !std::isfinite(l.measured_error_px)) continue;
      const double excess = l.measured_error_px - l.estimated_error_px;
      s_.max_excess_px = std::isnan(s_.max_excess_px) ? excess : std::max(s_.max_excess_px, excess);
    }
    add_budget(f.budget);
    s_.cache.add(f.cache);
    keep_finite(times_, f.time_ms);
    if (keep_finite(baseline_times_, r.baseline_ms)) s_.baseline_time_ms += r.baseline_ms;
    if (keep_finite(conventional_times_, r.conventional_ms))
      s_.conventional_time_ms += r.conventional_ms;
    if (std::isfinite(r.psnr_db)) {
      psnr_sum_ += r.psnr_db;
      ++psnr_count_;
    }
    if (std::isfinite(r.ssim)) {
      ssim_sum_ += r.ssim;
      ++ssim_count_;
    }
  }

  // The medians, the mean PSNR and the savings, once every frame is added.
  void finish() {
    s_.median_frame_ms = median_of(std::move(times_));
    s_.baseline_median_frame_ms = median_of(std::move(baseline_times_));
    s_.conventional_median_frame_ms = median_of(std::move(conventional_times_));
    s_.mean_psnr_db = psnr_count_ ? psnr_sum_ / psnr_count_ : kNaN;
    s_.mean_ssim = ssim_count_ ? ssim_sum_ / ssim_count_ : kNaN;
    s_.time_saved = s_.baseline_time_ms > 0.0 ? 1.0 - s_.time_ms / s_.baseline_time_ms : 0.0;
    s_.work_saved = s_.baseline_pixels > 0 ? 1.0 - static_cast<double>(s_.pixels) /
                                                       static_cast<double>(s_.baseline_pixels)
                                           : 0.0;
    s_.model_work_saved =
        s_.baseline_model_work > 0.0 ? 1.0 - s_.model_work / s_.baseline_model_work : 0.0;
    if (s_.gap_frames > 0) s_.mean_optimality_gap = gap_sum_ / s_.gap_frames;
  }

 private:
  static bool keep_finite(std::vector<double>& v, double x) {
    if (!std::isfinite(x)) return false;
    v.push_back(x);
    return true;
  }

  void add_budget(const BudgetReport& b) {
    if (!b.active) return;
    ++s_.budget_frames;
    s_.frames_over_budget += b.over() ? 1 : 0;
    s_.starved_layer_frames += b.starved;
    if (std::isfinite(b.optimality_gap)) {
      gap_sum_ += b.optimality_gap;
      ++s_.gap_frames;
    }
  }

  RunSummary& s_;
  double gap_sum_ = 0.0;
  bool first_ = true;
  std::vector<double> times_, baseline_times_, conventional_times_;
  double psnr_sum_ = 0.0;
  long psnr_count_ = 0;
  double ssim_sum_ = 0.0;
  long ssim_count_ = 0;
};

}  // namespace

void NodeCacheTotals::add(const NodeCacheFrame& f) {
  if (!f.active) return;
  active = true;
  nodes = f.nodes;
  node_frames += f.drawn;
  renders += f.rendered;
  fresh += f.fresh;
  by_angle += f.by_angle;
  by_sphere += f.by_sphere;
  uncacheable += f.uncacheable;
  overlap_pixels += f.overlap_pixels;
  max_pixel_error_px = std::max(max_pixel_error_px, f.max_pixel_error_px);
  const std::int64_t n = error_pixels + f.error_pixels;
  if (n > 0) {
    mean_pixel_error_px = (mean_pixel_error_px * static_cast<double>(error_pixels) +
                           f.mean_pixel_error_px * static_cast<double>(f.error_pixels)) /
                          static_cast<double>(n);
  }
  error_pixels = n;
  max_angle_deg = std::max(max_angle_deg, f.max_angle_deg);
  threshold_px = f.threshold_px;
}

nlohmann::json node_cache_json(const NodeCacheTotals& c) {
  return {{"nodes", c.nodes},
          {"node_frames", c.node_frames},
          {"node_renders", c.renders},
          {"renders_fresh", c.fresh},
          {"renders_by_angle", c.by_angle},
          {"renders_by_sphere", c.by_sphere},
          {"uncacheable", c.uncacheable},
          {"overlap_pixels", c.overlap_pixels},
          {"max_pixel_error_px", c.max_pixel_error_px},
          {"mean_pixel_error_px", c.mean_pixel_error_px},
          {"max_angle_deg", c.max_angle_deg},
          {"threshold_px", c.threshold_px}};
}

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

// The passes of one run. One pass records the frames (PSNR, IoU, on_frame, on_record): the
// timed pass when there is one, so records stream out as they are played; otherwise the
// first, whose records are held until the timed passes' medians are known.
class RunLoop {
 public:
  RunLoop(Animator& animator, Animator* baseline, VtkSceneRenderer* conventional,
          const RunOptions& options)
      : animator_(animator),
        baseline_(baseline),
        conventional_(conventional),
        options_(options),
        single_timed_(options.timing_repetitions == 1),
        totals_(run_.summary) {
    const int all = animator.frame_count();
    frames_ = options.max_frames < 0 ? all : std::min(all, options.max_frames);
    passes_ = options.timing_repetitions + (options.warm_up ? 1 : 0);
    if (!single_timed_) samples_.resize(static_cast<std::size_t>(std::max(frames_, 0)));
  }

  AnimationRun run() {
    for (int pass = 0; pass < passes_; ++pass) play_pass(pass);
    if (!single_timed_) emit_medians();
    run_.summary.frames = frames_;
    run_.summary.conventional_iou =
        conventional_ && baseline_ && frames_ > 0 ? iou_sum_ / frames_ : kNaN;
    totals_.finish();
    return std::move(run_);
  }

 private:
  int record_pass() const { return single_timed_ ? passes_ - 1 : 0; }

  bool conventional_in(int pass) const {
    if (!conventional_) return false;
    if (pass == 0 || pass == record_pass()) return true;  // warming up; the IoU
    const int timed_index = pass - (options_.warm_up ? 1 : 0);
    return options_.conventional_repetitions < 0 || timed_index < options_.conventional_repetitions;
  }

  void play_pass(int pass) {
    const bool record = pass == record_pass();
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
      if (record) record_frame(i, f, baseline_ms, conventional_ms);
      if (timed && !single_timed_)
        add_samples(samples_[static_cast<std::size_t>(i)], f, baseline_ms, conventional_ms);
      if (options_.progress) options_.progress(pass * frames_ + i + 1, passes_ * frames_);
    }
  }

  // The frame's deterministic facts, its PSNR and IoU against the baseline, on_frame; then
  // the record itself, or with several timed passes the frame and PSNR until the medians.
  void record_frame(int i, const AnimationFrame& f, double baseline_ms, double conventional_ms) {
    double psnr = kNaN, ssim = kNaN;
    if (baseline_ && (options_.psnr_when_nothing_drawn || f.drawn() > 0)) {
      psnr = psnr_db(animator_.image(), baseline_->image());
      const Image& shown = animator_.image();
      if (options_.measure_ssim && shown.width() >= kSsimWindow && shown.height() >= kSsimWindow) {
        ssim = mean_ssim(shown, baseline_->image());
      }
    }
    if (conventional_ && baseline_)
      iou_sum_ += alpha_iou(conventional_->image(), baseline_->image());
    if (options_.on_frame) options_.on_frame(i, animator_.image());
    if (options_.on_animators) options_.on_animators(i, animator_, baseline_);
    if (options_.on_view) options_.on_view(i, animator_.view());
    if (single_timed_) {
      emit({f, psnr, baseline_ms, conventional_ms, ssim}, options_.keep_frames);
      return;
    }
    run_.frames.push_back(f);
    run_.psnr_db.push_back(psnr);
    ssim_.push_back(ssim);
  }

  // A record with its final times: into the totals, to on_record and, with `store`, into
  // the run.
  void emit(const FrameRecord& r, bool store) {
    totals_.add(r);
    if (options_.on_record) options_.on_record(r);
    if (!store) return;
    run_.frames.push_back(r.frame);
    run_.psnr_db.push_back(r.psnr_db);
    run_.baseline_ms.push_back(r.baseline_ms);
    run_.conventional_ms.push_back(r.conventional_ms);
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

  // Several timed passes: each held frame's times become their medians, then it is emitted.
  void emit_medians() {
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
      emit({f, run_.psnr_db[i], run_.baseline_ms[i], run_.conventional_ms[i], ssim_[i]}, false);
    }
    if (!options_.keep_frames) {
      run_.frames = {};
      run_.psnr_db = {};
      run_.baseline_ms = {};
      run_.conventional_ms = {};
    }
  }

  Animator& animator_;
  Animator* baseline_;
  VtkSceneRenderer* conventional_;
  const RunOptions& options_;
  const bool single_timed_;
  int frames_ = 0;
  int passes_ = 0;
  std::vector<TimeSamples> samples_;  // per frame, with several timed passes
  std::vector<double> ssim_;          // per frame held for the medians
  double iou_sum_ = 0.0;
  AnimationRun run_;
  SummaryTotals totals_;
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
