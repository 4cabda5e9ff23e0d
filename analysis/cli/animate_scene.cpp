// The scene form of `oflab-cli animate` (see analysis/cli/animate_scene.h).
#include "cli/animate_scene.h"

#include <cmath>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <ostream>
#include <sstream>

#include "cli/animate_options.h"
#include "formats/atomic_file.h"
#include "formats/image_io.h"
#include "formats/scene_file.h"
#include "formats/viewer_script_file.h"
#include "runs/source_kinds.h"
#include "runs/statistics.h"

namespace oflab {

namespace {

// The depth-mesh policy's options (core/scene/depth_mesh.h DepthMeshSettings).
void read_mesh_settings(const CliArgs& a, DepthMeshSettings& m) {
  if (a.has("--mesh-grid")) m.grid_px = a.integer_in("--mesh-grid", limits::kMeshGrid);
  if (a.has("--mesh-split")) m.split = a.number_in("--mesh-split", limits::kMeshSplit);
  if (a.has("--mesh-rebuild")) {
    m.rebuild_distance = a.number_in("--mesh-rebuild", limits::kMeshRebuild);
  }
  if (a.has("--mesh-jump")) m.max_depth_jump = a.number_in("--mesh-jump", limits::kMeshJump);
  const std::string sheets = a.text_or("--rubber-sheets", "drop");
  if (sheets != "drop" && sheets != "keep") {
    throw UsageError("--rubber-sheets: '" + sheets + "' is not one of drop, keep");
  }
  m.drop_rubber_sheets = sheets == "drop";
}

}  // namespace

SceneSettings read_scene_settings(const CliArgs& a) {
  SceneSettings s;
  s.engine = read_engine_settings(a);
  s.near = a.number_or("--near", s.near);
  if (!(s.near > 0.0)) throw UsageError("--near: must be a positive distance");
  s.guard_band = a.number_or("--guard-band", s.guard_band);
  if (!(s.guard_band >= 0.0 && s.guard_band <= 16.0)) {
    throw UsageError("--guard-band: must be from 0 to 16 image sizes");
  }
  s.skip_hidden = !a.has("--no-skip-hidden");
  const std::string warp = a.text_or("--warp", warp_area_name(s.engine.warp_area));
  if (!parse_warp_area(warp, &s.engine.warp_area)) {
    throw UsageError("--warp: '" + warp + "' is not one of " + warp_area_name_list());
  }
  const std::string fill = a.text_or("--hole-fill", hole_fill_name(s.hole_fill));
  if (!parse_hole_fill(fill, s.hole_fill)) {
    throw UsageError("--hole-fill: '" + fill + "' is not one of " + hole_fill_name_list());
  }
  if (a.has("--cache-angle")) s.cache.angle_deg = a.number_in("--cache-angle", limits::kCacheAngle);
  if (a.has("--node-polygons")) {
    s.cache.max_node_polygons = a.integer_in("--node-polygons", limits::kCacheNodePolygons);
  }
  if (a.has("--safety-radius")) {
    s.cache.safety_radius = a.number_in("--safety-radius", limits::kSafetyRadius);
  }
  read_mesh_settings(a, s.mesh);
  return s;
}

RunSource read_scene_source(const CliArgs& a) {
  RunSource source;
  source.viewer = read_viewer_script_option(a);
  source.scene = std::make_shared<const Scene>(read_scene_option(a));
  source.settings = read_scene_settings(a);
  // The scene's content quality unless --quality says otherwise.
  if (!a.has("--quality")) {
    source.settings.engine.content.quality =
        scene_content_quality(*source.scene, source.settings.engine.content.quality);
  }
  return source;
}

namespace {

void print_scene_summary(const AnimationRun& run, const std::string& scene,
                         const std::string& script, const ReusePolicy& policy, std::ostream& out) {
  const RunSummary& s = run.summary;
  const long total = static_cast<long>(s.layers) * s.frames;
  const nlohmann::json& bsp = run.facts.at("bsp");
  out << "scene " << scene << " (" << s.layers << " polygons; BSP " << bsp.at("nodes").get<int>()
      << " nodes, " << bsp.at("splits").get<int>() << " splits), viewer script " << script
      << ", mode " << policy.name << ", " << s.frames << " frames\n";
  print_polygon_levels(s, out);
  out << "  culled " << s.culled() << " (" << percent(s.culled(), total) << "% of " << total
      << " polygon-frames: back-facing " << s.back_facing << ", outside the frustum "
      << s.outside_frustum << ")\n"
      << "  hidden " << s.hidden << " (" << percent(s.hidden, total)
      << "%, not updated: " << std::setprecision(0) << s.hidden_area_px
      << " px of polygon image left unwarped)\n"
      << "  clipped at the near plane or guard band " << s.clipped << "\n";
  if (s.reports_holes) {
    const RerenderCauses& c = s.rerender_causes;
    out << "  re-rendered polygon-frames: " << c.schedule << " on the cadence, " << c.off_schedule()
        << " off it (sampling limit " << c.sampling_limit << ", refused " << c.refused
        << ", no image " << c.no_image << ", clipped " << c.clipped << ")\n";
  }
  out << std::setprecision(3) << "  median frame time: engine " << s.median_frame_ms
      << " ms, exact re-render " << s.baseline_median_frame_ms << " ms";
  if (std::isfinite(s.conventional_median_frame_ms)) {
    out << ", conventional (VTK) " << s.conventional_median_frame_ms << " ms";
  }
  out << "\n";
  print_savings_and_error(s, out);
  print_budget(budget_json(s), out);
  if (std::isfinite(s.conventional_iou)) {
    out << "  conventional frames cover the exact frames' pixels with mean IoU "
        << s.conventional_iou << "\n";
  }
}

int run(const CliArgs& a, std::ostream& out, std::ostream& err) {
  const RunSource source = read_scene_source(a);
  const SceneSettings& settings = source.settings;
  PlayOptions options;
  options.conventional = a.has("--compare-conventional");
  options.conventional_multisample = !a.has("--conventional-single-sample");
  const RunOutput output = read_run_output(a, err);
  const SourceKind& kind = source_kind("scene");
  output.apply_to(options, kind);
  const AnimationRun result = kind.play(source, options);
  const nlohmann::json j = scene_animate_json(source, result);
  output.finish();
  output.write_summary(j);
  if (a.has("--json")) {
    out << j.dump(2) << "\n";
  } else {
    print_scene_summary(result, source.scene->name, source.viewer.name, *settings.engine.policy,
                        out);
  }
  return 0;
}

}  // namespace

nlohmann::json scene_animate_json(const RunSource& source, const AnimationRun& run) {
  const SceneSettings& settings = source.settings;
  nlohmann::json j = source_kind("scene").summary_json(run);
  j["scene"] = source.scene->name;
  j["script"] = source.viewer.name;
  j["mode"] = settings.engine.policy->name;
  j["thresholds"] = settings.engine.thresholds;
  j["skip_hidden"] = settings.skip_hidden;
  if (reports_holes(*settings.engine.policy)) {
    j["cadence"] = settings.engine.cadence;
    j["latency_frames"] = latency_frames(*settings.engine.policy, settings.engine.cadence);
    j["hole_fill"] = hole_fill_name(settings.hole_fill);
  }
  return j;
}

int animate_scene(const CliArgs& a, std::ostream& out, std::ostream& err) {
  try {
    return report_scene_input_errors([&] { return run(a, out, err); }, err);
  } catch (const UsageError&) {
    throw;
  } catch (const FileWriteError&) {
    throw;  // run_cli names the file
  } catch (const std::runtime_error& e) {
    err << "oflab-cli animate: --compare-conventional: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace oflab
