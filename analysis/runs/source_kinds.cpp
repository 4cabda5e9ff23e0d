#include "runs/source_kinds.h"

#include <cmath>
#include <iomanip>
#include <limits>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include "engine/reuse_policy.h"
#include "runs/statistics.h"
#include "runs/vtk_scene_renderer.h"

namespace oflab {
namespace {

nlohmann::json finite_or_null(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json();
}

// `settings` (EngineSettings or SceneShiftingSettings), or for the baseline the same with
// the rerender policy: the source rendered exactly every frame.
template <class Settings>
Settings with_baseline(Settings settings, bool baseline) {
  if (baseline) settings.policy = &reuse_policy("rerender");
  return settings;
}

constexpr char kNoColumns[] = "";
// The causes of a scene frame's re-renders (AnimationFrame::rerender_causes), in its order.
constexpr char kRerenderCauseColumns[] =
    ",rerender_schedule,rerender_sampling_limit,rerender_refused,rerender_no_image,"
    "rerender_clipped";

// ---- Single plane ----

std::unique_ptr<Animator> make_plane(const RunSource& source, bool baseline) {
  return make_plane_animator(source.script, source.texture,
                             with_baseline(source.settings.engine, baseline), source.repeat);
}

// A kind's CSV of a run that kept its frames: the header, then a row per frame.
template <void (*Header)(std::ostream&), void (*Row)(std::ostream&, const FrameRecord&),
          const char* Extra>
void write_csv_of(std::ostream& out, const AnimationRun& run) {
  write_csv_header_for(out, Header, !run.frames.empty() && run.frames.front().reports_holes, Extra);
  for (std::size_t i = 0; i < run.frames.size(); ++i) {
    Row(out, {run.frames[i], run.psnr_db[i], run.baseline_ms[i], run.conventional_ms[i]});
  }
}

AnimationRun play_plane(const RunSource& source, const PlayOptions& options) {
  const std::unique_ptr<Animator> animator = make_plane(source, false);
  const std::unique_ptr<Animator> baseline = options.baseline ? make_plane(source, true) : nullptr;
  RunOptions run_options = options;
  run_options.psnr_when_nothing_drawn = false;  // NaN while the plane is not visible
  // Frames per level, the not visible ones at the level their engine reported, counted as
  // the records come (a long run keeps no frames).
  std::array<long, kLevelCount> frames_at{};
  long invisible = 0;
  run_options.on_record = [&](const FrameRecord& record) {
    const FrameReport& r = record.frame.layer_reports.at(0);
    ++frames_at[static_cast<int>(r.level)];
    if (!r.visible) ++invisible;
    if (options.on_record) options.on_record(record);
  };
  AnimationRun run = run_animator(*animator, baseline.get(), nullptr, run_options);
  nlohmann::json levels;
  for (int l = 0; l < kLevelCount; ++l) levels[level_name(static_cast<Level>(l))] = frames_at[l];
  run.facts["frame_levels"] = levels;
  run.facts["invisible_frames"] = invisible;
  return run;
}

void write_plane_csv_header(std::ostream& out) {
  out << "frame,level,visible,flow_translate,flow_affine,flow_perspective,flow_higher,"
         "err_translate,err_affine,err_perspective,err_higher,estimated_error_px,"
         "measured_error_px,affine_view_error_px,psnr_db,time_ms,pixels_written,render_ms,"
         "warp_ms,model_work,photometric_error,note\n";
}

// The plane's engine report of the frame (exactly one per frame).
void write_plane_csv_row(std::ostream& out, const FrameRecord& record) {
  const FrameReport& r = record.frame.layer_reports.at(0);
  out << r.frame << ',' << level_name(r.level) << ',' << (r.visible ? 1 : 0);
  for (double f : r.flow) out << ',' << f;
  for (double e : r.accumulated) out << ',' << e;
  out << ',' << r.estimated_error_px << ',' << r.measured_error_px << ',' << r.affine_view_error_px
      << ',' << record.psnr_db << ',' << r.time_ms << ',' << r.pixels_written << ',' << r.render_ms
      << ',' << r.warp_ms << ',' << r.model_work << ',' << r.photometric_error << ",\"";
  for (char c : r.note) out << (c == '"' ? '\'' : c);
  out << '"';
  if (record.frame.reports_holes) out << ',' << record.frame.hole_pixels;
  out << '\n';
}

// Levels count frames here (the facts play_plane counted).
// `summary` with the "budget" block of a policy that shares a per-frame budget.
nlohmann::json with_budget(nlohmann::json summary, const RunSummary& s) {
  const nlohmann::json budget = budget_json(s);
  if (!budget.is_null()) summary["budget"] = budget;
  if (s.reports_holes) summary["hole_pixels"] = s.hole_pixels;

  if (s.cache.active) summary["cache"] = node_cache_json(s.cache);
  return summary;
}

nlohmann::json plane_summary_fields(const AnimationRun& run) {
  const RunSummary& s = run.summary;
  return {{"frames", s.frames},
          {"levels", run.facts.at("frame_levels")},
          {"invisible_frames", run.facts.at("invisible_frames")},
          {"time_saved", s.time_saved},
          {"work_saved", s.work_saved},
          {"max_measured_error_px", s.max_measured_error_px},
          {"max_excess_px", finite_or_null(s.max_excess_px)},
          {"mean_psnr_db", finite_or_null(s.mean_psnr_db)},
          {"time_ms", s.time_ms},
          {"baseline_time_ms", s.baseline_time_ms},
          {"median_frame_ms", finite_or_null(s.median_frame_ms)},
          {"baseline_median_frame_ms", finite_or_null(s.baseline_median_frame_ms)},
          {"pixels_written", s.pixels},
          {"baseline_pixels_written", s.baseline_pixels},
          {"model_work", s.model_work},
          {"baseline_model_work", s.baseline_model_work},
          {"model_work_saved", s.model_work_saved},
          {"render_ms", s.render_ms},
          {"max_photometric_error", s.max_photometric_error}};
}

nlohmann::json plane_summary_json(const AnimationRun& run) {
  return with_budget(plane_summary_fields(run), run.summary);
}

// ---- Scenes (the scene animator and scene shifting share the CSV and most of the JSON) ----

std::unique_ptr<Animator> make_scene(const RunSource& source, bool baseline) {
  SceneSettings settings = source.settings;
  settings.engine = with_baseline(settings.engine, baseline);
  return make_scene_animator(source.scene, source.viewer, settings);
}

AnimationRun play_scene(const RunSource& source, const PlayOptions& options) {
  const auto animator = make_scene_animator(source.scene, source.viewer, source.settings);
  const std::unique_ptr<Animator> baseline = options.baseline ? make_scene(source, true) : nullptr;
  std::unique_ptr<VtkSceneRenderer> conventional;
  if (options.conventional) {
    conventional = std::make_unique<VtkSceneRenderer>(
        *source.scene, source.viewer.camera, source.settings.near, source.settings.engine.content,
        options.conventional_multisample);
  }
  AnimationRun run = run_animator(*animator, baseline.get(), conventional.get(), options);
  const BspStats bsp = animator->renderer().bsp().stats();
  run.facts["bsp"] = {{"nodes", bsp.nodes},
                      {"fragments", bsp.fragments},
                      {"splits", bsp.splits},
                      {"depth", bsp.depth}};
  return run;
}

void write_scene_csv_header(std::ostream& out) {
  out << "frame,polygons,drawn,none,translate,affine,perspective,rerender,back_facing,"
         "outside_frustum,hidden,clipped,time_ms,update_ms,composite_ms,visibility_ms,"
         "pixels_written,"
         "pixels_composited,hidden_area_px,max_measured_error_px,psnr_db,rerender_time_ms,"
         "conventional_time_ms,render_ms,model_work,max_photometric_error\n";
}

void write_scene_csv_row(std::ostream& out, const FrameRecord& record) {
  const AnimationFrame& r = record.frame;
  out << r.frame << ',' << r.layers << ',' << r.drawn();
  for (int c : r.levels) out << ',' << c;
  out << ',' << r.back_facing << ',' << r.outside_frustum << ',' << r.hidden << ',' << r.clipped
      << ',' << r.time_ms << ',' << r.update_ms << ',' << r.composite_ms << ',' << r.visibility_ms
      << ',' << r.pixels_written << ',' << r.pixels_composited << ',' << r.hidden_area_px << ','
      << r.max_measured_error_px << ',' << record.psnr_db << ',' << record.baseline_ms << ','
      << record.conventional_ms << ',' << r.render_ms << ',' << r.model_work << ','
      << r.max_photometric_error;
  if (r.reports_holes) {
    const RerenderCauses& c = r.rerender_causes;
    out << ',' << r.hole_pixels << ',' << c.schedule << ',' << c.sampling_limit << ',' << c.refused
        << ',' << c.no_image << ',' << c.clipped;
  }
  out << '\n';
}

nlohmann::json scene_levels_json(const RunSummary& s, bool as_percent) {
  nlohmann::json levels;
  for (int l = 0; l < kLevelCount; ++l) {
    const char* name = level_name(static_cast<Level>(l));
    levels[name] =
        as_percent ? nlohmann::json(percent(s.levels[l], s.drawn())) : nlohmann::json(s.levels[l]);
  }
  return levels;
}

nlohmann::json scene_summary_fields(const AnimationRun& run) {
  const RunSummary& s = run.summary;
  const nlohmann::json no_bsp = {{"nodes", 0}, {"fragments", 0}, {"splits", 0}, {"depth", 0}};
  return {{"frames", s.frames},
          {"polygons", s.layers},
          {"bsp", run.facts.value("bsp", no_bsp)},
          {"polygon_levels", scene_levels_json(s, false)},
          {"polygon_level_percent", scene_levels_json(s, true)},
          {"drawn", s.drawn()},
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
          {"model_work", s.model_work},
          {"baseline_model_work", s.baseline_model_work},
          {"model_work_saved", s.model_work_saved},
          {"render_ms", s.render_ms},
          {"max_photometric_error", s.max_photometric_error},
          {"max_measured_error_px", s.max_measured_error_px},
          {"max_excess_px", finite_or_null(s.max_excess_px)},
          {"mean_psnr_db", finite_or_null(s.mean_psnr_db)},
          {"conventional_iou", finite_or_null(s.conventional_iou)}};
}

// The scene summary; under a policy that reports holes (those on a fixed cadence) also the
// causes of its re-renders, which say how far it kept its cadence.
nlohmann::json scene_summary_json(const AnimationRun& run) {
  nlohmann::json j = with_budget(scene_summary_fields(run), run.summary);
  if (run.summary.reports_holes) {
    const RerenderCauses& c = run.summary.rerender_causes;
    j["rerender_causes"] = {{"schedule", c.schedule},
                            {"sampling_limit", c.sampling_limit},
                            {"refused", c.refused},
                            {"no_image", c.no_image},
                            {"clipped", c.clipped}};
  }
  return j;
}

// ---- Scene shifting ----

std::unique_ptr<Animator> make_shifting(const RunSource& source, bool baseline) {
  return make_scene_shifting_animator(source.scene, source.viewer,
                                      with_baseline(source.shifting, baseline));
}

// The "scene_shifting" block of the summary: the slices and the layer updates.
nlohmann::json shifting_facts(const SceneShiftingRenderer& renderer) {
  nlohmann::json slices = nlohmann::json::array();
  for (const Slice& s : renderer.slices()) {
    slices.push_back(
        {{"near", s.near}, {"far", is_background(s) ? nlohmann::json() : nlohmann::json(s.far)}});
  }
  const SceneShiftingTotals& t = renderer.totals();
  return {{"epsilon_px", renderer.settings().epsilon_px},
          {"design_speed", renderer.settings().design_speed},
          {"slices", slices},
          {"rebuilt_layers", t.rebuilt_layers},
          {"shifted_layers", t.shifted_layers},
          {"turning_frames", t.turning_frames},
          {"turning_frames_all_rebuilt", t.turning_frames_all_rebuilt}};
}

AnimationRun play_shifting(const RunSource& source, const PlayOptions& options) {
  const auto animator = make_scene_shifting_animator(source.scene, source.viewer, source.shifting);
  const std::unique_ptr<Animator> baseline =
      options.baseline ? make_shifting(source, true) : nullptr;
  AnimationRun run = run_animator(*animator, baseline.get(), nullptr, options);
  run.facts["scene_shifting"] = shifting_facts(animator->renderer());
  // Slices holding polygons: fixed at start, so the last frame's count is every frame's.
  run.facts["occupied_slices"] = animator->renderer().slice_report().occupied;
  return run;
}

nlohmann::json shifting_summary_json(const AnimationRun& run) {
  nlohmann::json j = scene_summary_json(run);
  j["scene_shifting"] = run.facts.at("scene_shifting");
  return j;
}

}  // namespace

const std::vector<SourceKind>& source_kinds() {
  static const std::vector<SourceKind> kinds = {
      {"plane", make_plane, play_plane,
       write_csv_of<write_plane_csv_header, write_plane_csv_row, kNoColumns>,
       write_plane_csv_header, write_plane_csv_row, plane_summary_json},
      {"scene", make_scene, play_scene,
       write_csv_of<write_scene_csv_header, write_scene_csv_row, kRerenderCauseColumns>,
       write_scene_csv_header, write_scene_csv_row, scene_summary_json, false,
       kRerenderCauseColumns},
      {"scene-shifting", make_shifting, play_shifting,
       write_csv_of<write_scene_csv_header, write_scene_csv_row, kNoColumns>,
       write_scene_csv_header, write_scene_csv_row, shifting_summary_json, true},
  };
  return kinds;
}

const SourceKind* source_kind_for_mode(const std::string& mode) {
  for (const SourceKind& kind : source_kinds()) {
    if (kind.selected_by_mode && mode == kind.name) return &kind;
  }
  return nullptr;
}

std::string source_kind_modes(const std::string& separator) {
  std::string list;
  for (const SourceKind& kind : source_kinds()) {
    if (kind.selected_by_mode) list += (list.empty() ? "" : separator) + std::string(kind.name);
  }
  return list;
}

const SourceKind& source_kind(const std::string& name) {
  for (const SourceKind& kind : source_kinds()) {
    if (name == kind.name) return kind;
  }
  throw std::invalid_argument("unknown kind of animation source '" + name + "'");
}

void print_polygon_levels(const RunSummary& s, std::ostream& out) {
  const long drawn = s.drawn();
  out << std::fixed << std::setprecision(1) << "  polygons per level (" << drawn
      << " drawn polygon-frames):\n";
  for (int l = 0; l < kLevelCount; ++l) {
    out << "    " << std::setw(12) << std::left << level_name(static_cast<Level>(l)) << std::right
        << std::setw(8) << s.levels[l] << " (" << percent(s.levels[l], drawn) << "%)\n";
  }
}

nlohmann::json budget_json(const RunSummary& s) {
  if (s.budget_frames == 0) return nullptr;
  return {{"frames", s.budget_frames},
          {"frames_over_budget", s.frames_over_budget},
          {"starved_layer_frames", s.starved_layer_frames},
          {"gap_frames", s.gap_frames},
          {"mean_optimality_gap", finite_or_null(s.mean_optimality_gap)}};
}

void print_budget(const nlohmann::json& b, std::ostream& out) {
  if (b.is_null()) return;
  const nlohmann::json& gap = b.at("mean_optimality_gap");
  out << "  budget: " << b.at("frames_over_budget").get<long>() << " frames over budget (of "
      << b.at("frames").get<long>() << "), " << b.at("starved_layer_frames").get<long>()
      << " starved layer-frames, mean optimality gap "
      << optimality_gap_text(gap.is_null() ? std::nan("") : gap.get<double>(),
                             b.at("gap_frames").get<long>())
      << "\n";
}

std::string optimality_gap_text(double mean_gap, long gap_frames) {
  if (!std::isfinite(mean_gap)) {
    return "not checked (a time budget with more than " + std::to_string(kExhaustiveMaxLayers) +
           " layers competing in every frame)";
  }
  std::ostringstream text;
  text << std::fixed << std::setprecision(2) << 100.0 * mean_gap << "% over " << gap_frames
       << " frames checked against the optimum";
  return text.str();
}

void print_savings_and_error(const RunSummary& s, std::ostream& out) {
  out << "  time saved " << 100.0 * s.time_saved << "% against the exact re-render, work saved "
      << 100.0 * s.work_saved << "% (pixels written " << s.pixels << " vs " << s.baseline_pixels
      << ")\n"
      << "  max measured error " << s.max_measured_error_px << " px, mean PSNR against the exact "
      << "frame " << s.mean_psnr_db << " dB\n"
      << "  model work saved " << 100.0 * s.model_work_saved
      << "% (cost model: perspective warp 1, "
      << "affine 1/2.1, translation 1/35 per pixel, re-render at its content's cost); content "
      << "render time " << s.render_ms << " ms; max photometric error " << s.max_photometric_error
      << " grey levels\n";
}

void write_csv_header_for(std::ostream& out, void (*header)(std::ostream&), bool holes,
                          const char* extra) {
  if (!holes) {
    header(out);
    return;
  }
  std::ostringstream line;
  header(line);
  std::string text = line.str();
  if (!text.empty() && text.back() == '\n') text.pop_back();
  out << text << ",hole_pixels" << extra << "\n";
}

}  // namespace oflab
