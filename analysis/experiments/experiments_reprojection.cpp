// Today's reprojection beside optic flow (analysis/experiments/experiments_reprojection.h).
#include "experiments/experiments_reprojection.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "formats/datasets.h"
#include "formats/scene_file.h"
#include "formats/viewer_script_file.h"
#include "image/thread_pool.h"
#include "runs/source_kinds.h"
#include "scene/scene_animator.h"

namespace oflab {
namespace {

std::string fixed(double v, int digits) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << v;
  return s.str();
}

}  // namespace

ReprojectionSpec reprojection_spec(bool quick) {
  ReprojectionSpec spec;
  if (quick) {
    spec.max_frames = 12;
    spec.ssim = false;
    spec.timing_width = 480;
    spec.timing_height = 270;
  }
  return spec;
}

std::vector<const ReusePolicy*> reprojection_policies() {
  std::vector<const ReusePolicy*> out;
  for (const char* name : {"timewarp", "stabilized-plane", "depth-reprojection", "cadence",
                           "mv-extrapolation", "mv-no-inpaint", "view-interpolation", "depth-mesh",
                           "perspective", "talisman", "hierarchical-cache"}) {
    out.push_back(&reuse_policy(name));
  }
  return out;
}

std::vector<const ReusePolicy*> one_motion_policies() {
  std::vector<const ReusePolicy*> out;
  for (const char* name : {"perspective", "timewarp", "depth-reprojection", "mv-extrapolation",
                           "mv-no-inpaint", "view-interpolation", "depth-mesh"}) {
    out.push_back(&reuse_policy(name));
  }
  return out;
}

namespace {

// The worker threads set to `count` while it lives, then restored.
class WorkerThreadsFor {
 public:
  explicit WorkerThreadsFor(int count) : saved_(worker_threads()) { set_worker_threads(count); }
  ~WorkerThreadsFor() { set_worker_threads(saved_); }
  WorkerThreadsFor(const WorkerThreadsFor&) = delete;
  WorkerThreadsFor& operator=(const WorkerThreadsFor&) = delete;

 private:
  int saved_;
};

double median(std::vector<double> v) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

// One policy's frames that it makes without rendering, timed (see MethodTiming).
MethodTiming time_method(const ReusePolicy& policy, std::shared_ptr<const Scene> scene,
                         const ViewerScript& script, int cadence) {
  SceneSettings settings;
  settings.engine.policy = &policy;
  settings.engine.cadence = cadence;
  // Layers animated only within 5 % of the frame beyond its edges: at 1920 x 1080 the default
  // half-frame guard band would let four cubes' layers exceed the scene memory limit.
  settings.guard_band = 0.05;
  const auto animator = make_scene_animator(std::move(scene), script, settings);
  std::vector<double> ms;
  animator->start();
  for (int k = 1; k < animator->frame_count(); ++k) {
    const AnimationFrame f = animator->advance();
    if (policy.schedule == Schedule::kCadence && k % cadence == 0) continue;  // a render
    ms.push_back(f.time_ms);
  }
  MethodTiming t;
  t.policy = &policy;
  t.ms = median(ms);
  t.frames = static_cast<int>(ms.size());
  const Camera& c = script.camera;
  t.ms_1080p = t.ms * (1920.0 * 1080.0) / (static_cast<double>(c.width) * c.height);
  return t;
}

}  // namespace

std::vector<MethodTiming> time_one_motion(int width, int height, int cadence) {
  const auto scene =
      std::make_shared<const Scene>(read_scene_file(resolve_scene_path("four-cubes")));
  ViewerScript script = read_viewer_script_file(resolve_viewer_script_path("translate"));
  const Camera& c = script.camera;
  script.camera = make_camera(c.focal_px * height / c.height, width, height);
  if (script.frames.size() > 9) script.frames.resize(9);
  const WorkerThreadsFor one_thread(1);
  std::vector<MethodTiming> out;
  for (const ReusePolicy* p : one_motion_policies()) {
    out.push_back(time_method(*p, scene, script, cadence));
  }
  return out;
}

ReprojectionResult run_reprojection_experiment(
    const ReprojectionSpec& spec, const std::function<void(const std::string&)>& progress) {
  ReprojectionResult result;
  result.spec = spec;
  std::vector<std::pair<std::string, std::string>> sources;
  for (const char* scene : {"single-1", "two", "five-collinear", "four-cubes"}) {
    for (const char* script : {"translate", "zoom", "rotate"}) sources.emplace_back(scene, script);
  }
  sources.emplace_back("street", "walk");
  // A far city block from a moving viewer: the far, shallow clusters the image cache was
  // made for, beside the street's long walls walked through, where it cannot pay.
  sources.emplace_back("city-block", "city-flyby");
  PlayOptions options;
  options.max_frames = spec.max_frames;
  options.warm_up = false;
  options.timing_repetitions = 1;
  options.measure_ssim = spec.ssim;
  for (const auto& [scene, script] : sources) {
    if (progress) progress(scene + ", " + script);
    RunSource source;
    source.scene = std::make_shared<const Scene>(read_scene_file(resolve_scene_path(scene)));
    source.viewer = read_viewer_script_file(resolve_viewer_script_path(script));
    source.settings.engine.cadence = spec.cadence;
    ReprojectionSource s{scene, script, 0, {}};
    s.frame_pixels =
        static_cast<std::int64_t>(source.viewer.camera.width) * source.viewer.camera.height;
    s.runs = run_policies(source_kind("scene"), source, reprojection_policies(), options);
    result.sources.push_back(std::move(s));
  }
  if (progress) progress("four-cubes, translate: ms per frame on one thread");
  result.timings = time_one_motion(spec.timing_width, spec.timing_height, spec.cadence);
  return result;
}

namespace {

ReportTable results_table(const ReprojectionResult& r) {
  ReportTable t;
  t.caption = "Every policy on the same frames (cadence " + std::to_string(r.spec.cadence) +
              "; perspective is optic flow's threshold rule, for reference)";
  t.header = {"scene, script", "policy",           "re-render %",   "max error px",
              "mean error px", "hole px (total)",  "inpainted px",  "mean PSNR dB",
              "mean SSIM",     "model work saved", "latency frames"};
  for (const ReprojectionSource& s : r.sources) {
    for (const PolicyRun& run : s.runs) {
      const PolicyRow row = policy_row(run);
      // The per-pixel warp reports no layer reports: its error is the frames' per-pixel one.
      const double max_error =
          std::max(row.max_measured_error_px, run.run.summary.max_measured_error_px);
      t.rows.push_back({s.scene + ", " + s.script, row.name,
                        fixed(100.0 * row.level_share[static_cast<int>(Level::kRerender)], 1),
                        fixed(max_error, 2),
                        run.policy->frame_warp == FrameWarp::kPerPixelDepth
                            ? std::string("per pixel")
                            : fixed(row.mean_measured_error_px, 3),
                        std::to_string(row.hole_pixels), std::to_string(row.inpainted_pixels),
                        fixed(row.mean_psnr_db, 1),
                        std::isfinite(row.mean_ssim) ? fixed(row.mean_ssim, 4) : std::string("-"),
                        fixed(100.0 * row.model_work_saved, 1) + "%",
                        std::to_string(row.latency_frames)});
    }
  }
  return t;
}

Chart error_work_chart(const ReprojectionResult& r) {
  ChartPanel panel;
  panel.title = "measured error against model work saved, one point per policy and source";
  panel.x_label = "model work saved %";
  panel.y_label = "log10 max error px";
  panel.y_range = std::make_pair(-2.2, 2.0);
  int colour = 0;
  for (const ReusePolicy* p : reprojection_policies()) {
    ChartSeries series{p->name, {}, {}, SeriesStyle::kPoints, chart_palette(colour++)};
    for (const ReprojectionSource& s : r.sources) {
      for (const PolicyRun& run : s.runs) {
        if (run.policy != p) continue;
        const PolicyRow row = policy_row(run);
        series.x.push_back(100.0 * row.model_work_saved);
        series.y.push_back(std::log10(
            std::max({row.max_measured_error_px, run.run.summary.max_measured_error_px, 0.01})));
      }
    }
    panel.series.push_back(series);
  }
  Chart chart;
  chart.panels = {panel};
  return chart;
}

ReportTable vendor_table() {
  ReportTable t;
  t.caption =
      "The vendors' and authors' published figures: theirs, quoted as context, not "
      "reproduced here";
  t.header = {"system", "published figure", "source"};
  t.rows = {
      {"asynchronous spacewarp", "renders 45 of 90 frames per second, synthesises the rest",
       "Oculus (Meta) developer documentation"},
      {"late-stage reprojection (HoloLens)",
       "renders 60 frames per second for its 240 Hz colour fields",
       "Microsoft HoloLens documentation"},
      {"post-rendering 3D warping", "5-10x apparent frame rate", "Mark, McMillan and Bishop 97"},
      {"hierarchical image caching (landscape fly-through)",
       "speedups of 4.1 to 25.2, 11.9 on average, before the cost of building the caches",
       "Shade et al. 96, as quoted in the dissertation's section 2.4.7"},
      {"frame generation (DLSS 3, FSR 3)",
       "interpolates between two rendered frames: shows each one frame late (1 frame of "
       "latency, as view-interpolation here at cadence 2; the other policies extrapolate, 0 "
       "frames)",
       "NVIDIA, AMD"},
  };
  return t;
}

// The hierarchical image cache's own figures per source: its nodes and why they were rendered,
// the seams between node images and the per-pixel error.
ReportTable cache_table(const ReprojectionResult& r) {
  ReportTable t;
  t.caption =
      "hierarchical-cache: nodes (at most 8 polygons per cluster), node renders by cause, the "
      "threshold in pixels, holes and overlaps where node images meet, per-pixel error";
  t.header = {"scene, script",   "nodes",      "node-frames",      "renders",
              "by angle",        "by sphere",  "uncacheable",      "threshold px",
              "hole px (total)", "overlap px", "max per-pixel px", "mean per-pixel px"};
  for (const ReprojectionSource& s : r.sources) {
    for (const PolicyRun& run : s.runs) {
      const NodeCacheTotals& c = run.run.summary.cache;
      if (!c.active) continue;
      t.rows.push_back(
          {s.scene + ", " + s.script, std::to_string(c.nodes), std::to_string(c.node_frames),
           std::to_string(c.renders), std::to_string(c.by_angle), std::to_string(c.by_sphere),
           std::to_string(c.uncacheable), fixed(c.threshold_px, 2),
           std::to_string(run.run.summary.hole_pixels), std::to_string(c.overlap_pixels),
           fixed(c.max_pixel_error_px, 2), fixed(c.mean_pixel_error_px, 3)});
    }
  }
  return t;
}

const ReprojectionSource& four_cubes_translate(const ReprojectionResult& r) {
  for (const ReprojectionSource& s : r.sources) {
    if (s.scene == "four-cubes" && s.script == "translate") return s;
  }
  throw std::invalid_argument("the reprojection result has no four-cubes under translate");
}

const PolicyRun& run_of(const ReprojectionSource& s, const ReusePolicy* p) {
  for (const PolicyRun& run : s.runs) {
    if (run.policy == p) return run;
  }
  throw std::invalid_argument(std::string("no run of ") + p->name + " on " + s.scene);
}

const MethodTiming& timing_of(const ReprojectionResult& r, const ReusePolicy* p) {
  for (const MethodTiming& t : r.timings) {
    if (t.policy == p) return t;
  }
  throw std::invalid_argument(std::string("no timing of ") + p->name);
}

double largest_error(const PolicyRun& run) {
  return std::max(policy_row(run).max_measured_error_px, run.run.summary.max_measured_error_px);
}

// Error against work, one point per method, each named with its latency.
Chart one_motion_chart(const ReprojectionResult& r) {
  ChartPanel panel;
  panel.title =
      "four cubes under translate: every method, error against work (latency in the legend)";
  panel.x_label = "log10 ms per 1920x1080 frame, one thread";
  panel.y_label = "log10 max error px";
  // Room above the points for the legend (top right): errors up to 10^1.4 px, times up to
  // 10^3.6 ms.
  panel.x_range = std::make_pair(0.0, 3.6);
  panel.y_range = std::make_pair(-0.6, 2.4);
  int colour = 0;
  const ReprojectionSource& s = four_cubes_translate(r);
  for (const ReusePolicy* p : one_motion_policies()) {
    const int latency = latency_frames(*p, r.spec.cadence);
    ChartSeries series{std::string(p->name) + ", latency " + std::to_string(latency) +
                           (latency == 1 ? " frame" : " frames"),
                       {std::log10(timing_of(r, p).ms_1080p)},
                       {std::log10(std::max(largest_error(run_of(s, p)), 0.01))},
                       SeriesStyle::kPoints,
                       chart_palette(colour++)};
    panel.series.push_back(series);
  }
  Chart chart;
  chart.panels = {panel};
  return chart;
}

}  // namespace

ReportTable one_motion_table(const ReprojectionResult& r) {
  const ReprojectionSource& s = four_cubes_translate(r);
  const std::string timed =
      std::to_string(r.spec.timing_width) + " x " + std::to_string(r.spec.timing_height);
  ReportTable t;
  t.caption = "Every method on one motion: four cubes under translate, the first " +
              std::to_string(r.spec.max_frames) + " frames at cadence " +
              std::to_string(r.spec.cadence) + "; ms per 1920 x 1080 frame on one thread " +
              (r.spec.timing_width == 1920 && r.spec.timing_height == 1080
                   ? std::string("measured at that size")
                   : "measured at " + timed + " and scaled by the pixel count");
  t.header = {"method",    "max error px",       "hole %",        "inpainted %", "mean PSNR dB",
              "mean SSIM", "ms per 1080p frame", "latency frames"};
  for (const ReusePolicy* p : one_motion_policies()) {
    const PolicyRun& run = run_of(s, p);
    const PolicyRow row = policy_row(run);
    const double pixels = static_cast<double>(row.frames) * static_cast<double>(s.frame_pixels);
    const auto percent = [&](std::int64_t n) {
      return fixed(pixels > 0 ? 100.0 * static_cast<double>(n) / pixels : 0.0, 3);
    };
    t.rows.push_back({p->name, fixed(largest_error(run), 2), percent(row.hole_pixels),
                      percent(row.inpainted_pixels), fixed(row.mean_psnr_db, 1),
                      std::isfinite(row.mean_ssim) ? fixed(row.mean_ssim, 4) : std::string("-"),
                      fixed(timing_of(r, p).ms_1080p, 1),
                      std::to_string(latency_frames(*p, r.spec.cadence))});
  }
  return t;
}

ReportSection reprojection_section(const ReprojectionResult& result, ExperimentContext& context) {
  ReportSection s;
  s.id = "reprojection";
  s.title = "Today's reprojection beside optic flow";
  s.paragraph(
      "Timewarp (rotation-only homography), one stabilization plane for the frame (automatic: "
      "the least-squares fit of inverse depth to the visible pixels at each render), per-pixel "
      "depth reprojection (forward splatting, holes counted, fill none), frame generation by "
      "extrapolation along the render's motion vectors without the new pose (mv-extrapolation, "
      "its disocclusions filled by push-pull inpainting, and without inpainting), view "
      "interpolation, textured depth meshes of the far part (depth-mesh: the near part rendered "
      "every frame, the far part's mesh rebuilt at each render; split automatic, 4-pixel grid, "
      "rubber sheets dropped) and each layer's own plane (cadence), all rendering every " +
      std::to_string(result.spec.cadence) +
      "nd frame and warping between, beside optic flow's threshold rule; the first " +
      std::to_string(result.spec.max_frames) +
      " frames of each Experiment 2 scene under translate, zoom and rotate, of the street "
      "under walk and of the city block under city-flyby. Error: the largest corner displacement "
      "of a layer (per-layer warps) or the largest per-pixel displacement (depth reprojection, "
      "frame generation, view interpolation, the depth mesh's far part). PSNR and SSIM "
      "against the exact frame (SSIM after Wang et al. 2004, on luma, 11 x 11 Gaussian window; "
      "'-' when not measured, as in a quick run). Work: the cost model's, in pixels "
      "of a perspective warp (a per-pixel warp costs one per pixel of the frame). Latency: "
      "frames of delay; every policy here but view-interpolation extrapolates from the last "
      "render (0), view-interpolation (Chen and Williams 93) makes the frames between two "
      "renders from both and so waits for the later one (cadence - 1 frames).");
  s.table(results_table(result));
  s.paragraph(
      "Talisman re-renders a layer when its affine fit misses a corner by more than its "
      "threshold. The hierarchical image cache (Shade et al. 96, the dissertation's section "
      "2.4.7) groups the BSP tree's polygons into nodes and warps each node's image on a quad "
      "facing the viewer, re-rendering when a corner of the node's box is off by more than the "
      "angle (0.2 degrees) or the viewer leaves the conservative safety sphere; each polygon of "
      "a node counts as one layer-frame.");
  s.table(cache_table(result));
  s.figure(context.add_chart("reprojection-error-work", error_work_chart(result),
                             "Largest measured error (log10 px; 0 px drawn at -2) against model "
                             "work saved, one point per policy and source."));
  s.paragraph(
      "Every method from 1993 to today on one motion: optic flow's layers (perspective), "
      "timewarp, depth reprojection (Mark, McMillan and Bishop 97), frame generation by "
      "extrapolation along motion vectors with and without inpainting (the DLSS 3 / FSR 3 "
      "family, extrapolating), view interpolation (Chen and Williams 93) and textured depth "
      "meshes (Sillion, Drettakis and Bodelet 97), on four cubes under translate. Holes and "
      "inpainted pixels are shares of every pixel of every frame. The "
      "milliseconds are the median over the frames each method makes without rendering (every "
      "frame after the first for perspective) of the first 9 frames with the script's camera "
      "widened to the timing size at the same vertical field of view (guard band 0.05: layers "
      "animated within 5 % of the frame beyond its edges), on one thread, measured "
      "by this run on this machine: indicative, not a benchmark (oflab-bench). The published "
      "systems run on the GPU.");
  s.table(one_motion_table(result));
  s.figure(context.add_chart("reprojection-one-motion", one_motion_chart(result),
                             "Four cubes under translate: largest measured error (log10 px) "
                             "against milliseconds per 1920 x 1080 frame on one thread (log10), "
                             "one point per method; its latency in frames in the legend."));
  s.table(vendor_table());
  return s;
}

}  // namespace oflab
