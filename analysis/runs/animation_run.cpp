#include "runs/animation_run.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <ostream>

#include "runs/statistics.h"
#include "image/composite.h"
#include "image/image_compare.h"

namespace oflab {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

int frame_count(const MotionScript& script, const AnimationOptions& options) {
  const int all = static_cast<int>(script.frames.size());
  return options.max_frames < 0 ? all : std::min(all, options.max_frames);
}

// Plays the frames with `settings`; calls `each` with the animator after every frame.
template <typename Each>
void play(const MotionScript& script, const Layer& texture, const EngineSettings& settings,
          int frames, Each each) {
  PlaneAnimator animator(script.camera, texture, settings);
  for (int i = 0; i < frames; ++i) {
    const FrameReport r =
        i == 0 ? animator.start(script.frames[0].pose)
               : animator.advance(script.frames[i - 1].pose, script.frames[i - 1].motion,
                                  script.frames[i].pose);
    each(i, r, animator);
  }
}

}  // namespace

Image compose_frame(const Camera& camera, const PlacedLayer& layer) {
  Image frame(camera.width, camera.height);
  if (!layer.layer.empty()) composite_over(frame, layer.layer, layer.offset_x, layer.offset_y);
  return frame;
}

AnimationRun run_animation(const MotionScript& script, const Layer& texture,
                           const AnimationOptions& options) {
  AnimationRun run;
  const int frames = frame_count(script, options);
  AnimationSummary& s = run.summary;
  std::vector<double> times;
  play(script, texture, options.settings, frames,
       [&](int i, const FrameReport& r, const PlaneAnimator& animator) {
         run.reports.push_back(r);
         times.push_back(r.time_ms);
         double psnr = kNaN;
         if ((options.measure_psnr || options.on_frame) && r.visible) {
           const Image shown = compose_frame(script.camera, animator.displayed());
           if (options.measure_psnr) {
             const PlacedLayer exact = render_exact(script.camera, texture, script.frames[i].pose,
                                                    options.settings.sampling);
             psnr = psnr_db(shown, compose_frame(script.camera, exact));
           }
           if (options.on_frame) options.on_frame(i, shown);
         } else if (options.on_frame) {
           options.on_frame(i, Image(script.camera.width, script.camera.height));
         }
         run.psnr_db.push_back(psnr);
         if (options.progress) options.progress(i + 1, frames);
       });
  s.frames = frames;
  double psnr_sum = 0.0;
  int psnr_count = 0;
  for (size_t i = 0; i < run.reports.size(); ++i) {
    const FrameReport& r = run.reports[i];
    ++s.levels[static_cast<int>(r.level)];
    if (!r.visible) ++s.invisible_frames;
    s.time_ms += r.time_ms;
    s.pixels += r.pixels_written;
    if (r.visible) s.max_measured_error_px = std::max(s.max_measured_error_px, r.measured_error_px);
    if (std::isfinite(run.psnr_db[i])) {
      psnr_sum += run.psnr_db[i];
      ++psnr_count;
    }
  }
  s.mean_psnr_db = psnr_count ? psnr_sum / psnr_count : kNaN;
  s.median_frame_ms = median_of(times);
  if (options.run_baseline) {
    EngineSettings baseline = options.settings;
    baseline.policy = &reuse_policy("rerender");
    std::vector<double> baseline_times;
    play(script, texture, baseline, frames, [&](int, const FrameReport& r, const PlaneAnimator&) {
      baseline_times.push_back(r.time_ms);
      s.baseline_time_ms += r.time_ms;
      s.baseline_pixels += r.pixels_written;
    });
    s.baseline_median_frame_ms = median_of(baseline_times);
    s.time_saved = s.baseline_time_ms > 0 ? 1.0 - s.time_ms / s.baseline_time_ms : 0.0;
    s.work_saved = s.baseline_pixels > 0 ? 1.0 - static_cast<double>(s.pixels) /
                                                     static_cast<double>(s.baseline_pixels)
                                         : 0.0;
  }
  return run;
}

void write_frame_csv(std::ostream& out, const AnimationRun& run) {
  out << "frame,level,visible,flow_translate,flow_affine,flow_perspective,flow_higher,"
         "err_translate,err_affine,err_perspective,err_higher,estimated_error_px,"
         "measured_error_px,affine_view_error_px,psnr_db,time_ms,pixels_written,note\n";
  for (size_t i = 0; i < run.reports.size(); ++i) {
    const FrameReport& r = run.reports[i];
    out << r.frame << ',' << level_name(r.level) << ',' << (r.visible ? 1 : 0);
    for (double f : r.flow) out << ',' << f;
    for (double e : r.accumulated) out << ',' << e;
    out << ',' << r.estimated_error_px << ',' << r.measured_error_px << ','
        << r.affine_view_error_px << ',' << run.psnr_db[i] << ',' << r.time_ms << ','
        << r.pixels_written << ",\"";
    for (char c : r.note) out << (c == '"' ? '\'' : c);
    out << "\"\n";
  }
}

nlohmann::json summary_json(const AnimationSummary& s) {
  auto finite_or_null = [](double v) {
    return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json();
  };
  nlohmann::json levels;
  for (int l = 0; l < kLevelCount; ++l) levels[level_name(static_cast<Level>(l))] = s.levels[l];
  return {{"frames", s.frames},
          {"levels", levels},
          {"invisible_frames", s.invisible_frames},
          {"time_saved", s.time_saved},
          {"work_saved", s.work_saved},
          {"max_measured_error_px", s.max_measured_error_px},
          {"mean_psnr_db", finite_or_null(s.mean_psnr_db)},
          {"time_ms", s.time_ms},
          {"baseline_time_ms", s.baseline_time_ms},
          {"median_frame_ms", finite_or_null(s.median_frame_ms)},
          {"baseline_median_frame_ms", finite_or_null(s.baseline_median_frame_ms)},
          {"pixels_written", s.pixels},
          {"baseline_pixels_written", s.baseline_pixels}};
}

}  // namespace oflab
