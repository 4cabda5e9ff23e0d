#include "runs/scene_run.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>

#include "runs/statistics.h"
#include "runs/vtk_scene_renderer.h"
#include "image/image_compare.h"

namespace oflab {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

long SceneRunSummary::drawn() const {
  long n = 0;
  for (long c : polygon_levels) n += c;
  return n;
}

void summarise_scene_run(SceneRun& run) {
  SceneRunSummary& s = run.summary;
  std::vector<double> times;
  double psnr_sum = 0.0;
  int psnr_count = 0;
  for (std::size_t i = 0; i < run.reports.size(); ++i) {
    const SceneFrameReport& r = run.reports[i];
    for (int l = 0; l < kLevelCount; ++l) s.polygon_levels[l] += r.levels[l];
    s.back_facing += r.back_facing;
    s.outside_frustum += r.outside_frustum;
    s.hidden += r.hidden;
    s.clipped += r.clipped;
    s.hidden_area_px += r.hidden_area_px;
    s.pixels += r.pixels_written;
    s.time_ms += r.time_ms;
    s.visibility_time_ms += r.visibility_ms;
    s.max_measured_error_px = std::max(s.max_measured_error_px, r.max_measured_error_px);
    times.push_back(r.time_ms);
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

SceneRun run_scene_animation(const Scene& scene, const ViewerScript& script,
                             const SceneRunOptions& options) {
  SceneRun run;
  const int all = static_cast<int>(script.frames.size());
  const int frames = options.max_frames < 0 ? all : std::min(all, options.max_frames);
  SceneAnimator engine(scene, script.camera, options.settings);
  std::unique_ptr<SceneAnimator> exact;
  if (options.run_baseline) {
    SceneSettings settings = options.settings;
    settings.engine.policy = &reuse_policy("rerender");
    exact = std::make_unique<SceneAnimator>(scene, script.camera, settings);
  }
  std::unique_ptr<VtkSceneRenderer> conventional;
  if (options.conventional) {
    conventional = std::make_unique<VtkSceneRenderer>(scene, script.camera, options.settings.near);
  }
  double iou_sum = 0.0;
  // The three renderers take turns frame by frame, so a busy machine slows them alike.
  for (int i = 0; i < frames; ++i) {
    run.reports.push_back(play_frame(engine, script, i));
    double baseline_ms = kNaN, conventional_ms = kNaN, psnr = kNaN;
    if (exact) {
      const SceneFrameReport r = play_frame(*exact, script, i);
      baseline_ms = r.time_ms;
      run.summary.baseline_pixels += r.pixels_written;
      psnr = psnr_db(engine.frame(), exact->frame());
    }
    if (conventional) {
      conventional_ms = conventional->render(script.frames[i].pose);
      if (exact) iou_sum += alpha_iou(conventional->image(), exact->frame());
    }
    run.baseline_ms.push_back(baseline_ms);
    run.conventional_ms.push_back(conventional_ms);
    run.psnr_db.push_back(psnr);
    if (options.on_frame) options.on_frame(i, engine.frame());
    if (options.progress) options.progress(i + 1, frames);
  }
  SceneRunSummary& s = run.summary;
  s.frames = frames;
  s.polygons = static_cast<int>(scene.polygons.size());
  s.bsp = engine.bsp().stats();
  s.conventional_iou = conventional && exact && frames > 0 ? iou_sum / frames : kNaN;
  summarise_scene_run(run);
  return run;
}

void write_scene_frame_csv(std::ostream& out, const SceneRun& run) {
  out << "frame,polygons,drawn,none,translate,affine,perspective,rerender,back_facing,"
         "outside_frustum,hidden,clipped,time_ms,update_ms,composite_ms,visibility_ms,"
         "pixels_written,"
         "pixels_composited,hidden_area_px,max_measured_error_px,psnr_db,rerender_time_ms,"
         "conventional_time_ms\n";
  for (std::size_t i = 0; i < run.reports.size(); ++i) {
    const SceneFrameReport& r = run.reports[i];
    out << r.frame << ',' << r.polygons << ',' << r.drawn();
    for (int c : r.levels) out << ',' << c;
    out << ',' << r.back_facing << ',' << r.outside_frustum << ',' << r.hidden << ',' << r.clipped
        << ',' << r.time_ms << ',' << r.update_ms << ',' << r.composite_ms << ',' << r.visibility_ms
        << ',' << r.pixels_written << ',' << r.pixels_composited << ',' << r.hidden_area_px << ','
        << r.max_measured_error_px << ',' << run.psnr_db[i] << ',' << run.baseline_ms[i] << ','
        << run.conventional_ms[i] << '\n';
  }
}

void print_polygon_levels(const SceneRunSummary& s, std::ostream& out) {
  const long drawn = s.drawn();
  out << std::fixed << std::setprecision(1) << "  polygons per level (" << drawn
      << " drawn polygon-frames):\n";
  for (int l = 0; l < kLevelCount; ++l) {
    out << "    " << std::setw(12) << std::left << level_name(static_cast<Level>(l)) << std::right
        << std::setw(8) << s.polygon_levels[l] << " (" << percent(s.polygon_levels[l], drawn)
        << "%)\n";
  }
}

void print_savings_and_error(const SceneRunSummary& s, std::ostream& out) {
  out << "  time saved " << 100.0 * s.time_saved << "% against the exact re-render, work saved "
      << 100.0 * s.work_saved << "% (pixels written " << s.pixels << " vs " << s.baseline_pixels
      << ")\n"
      << "  max measured error " << s.max_measured_error_px << " px, mean PSNR against the exact "
      << "frame " << s.mean_psnr_db << " dB\n";
}

nlohmann::json scene_summary_json(const SceneRunSummary& s) {
  auto finite_or_null = [](double v) {
    return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json();
  };
  nlohmann::json levels, level_percent;
  const long drawn = s.drawn();
  for (int l = 0; l < kLevelCount; ++l) {
    const char* name = level_name(static_cast<Level>(l));
    levels[name] = s.polygon_levels[l];
    level_percent[name] = percent(s.polygon_levels[l], drawn);
  }
  return {{"frames", s.frames},
          {"polygons", s.polygons},
          {"bsp",
           {{"nodes", s.bsp.nodes},
            {"fragments", s.bsp.fragments},
            {"splits", s.bsp.splits},
            {"depth", s.bsp.depth}}},
          {"polygon_levels", levels},
          {"polygon_level_percent", level_percent},
          {"drawn", drawn},
          {"culled", s.culled()},
          {"back_facing", s.back_facing},
          {"outside_frustum", s.outside_frustum},
          {"hidden", s.hidden},
          {"clipped", s.clipped},
          {"hidden_area_px", s.hidden_area_px},
          {"visibility_ms", s.visibility_time_ms},
          {"median_frame_ms",
           {{"engine", finite_or_null(s.median_frame_ms)},
            {"rerender", finite_or_null(s.baseline_median_frame_ms)},
            {"conventional", finite_or_null(s.conventional_median_frame_ms)}}},
          {"time_ms",
           {{"engine", s.time_ms},
            {"rerender", s.baseline_time_ms},
            {"conventional", s.conventional_time_ms}}},
          {"time_saved", s.time_saved},
          {"work_saved", s.work_saved},
          {"pixels_written", s.pixels},
          {"baseline_pixels_written", s.baseline_pixels},
          {"max_measured_error_px", s.max_measured_error_px},
          {"mean_psnr_db", finite_or_null(s.mean_psnr_db)},
          {"conventional_iou", finite_or_null(s.conventional_iou)}};
}

}  // namespace oflab
