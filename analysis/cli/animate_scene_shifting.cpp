// The scene-shifting form of `oflab-cli animate` (see analysis/cli/animate_scene_shifting.h).
#include "cli/animate_scene_shifting.h"

#include <cmath>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <ostream>
#include <sstream>

#include "cli/animate_options.h"
#include "formats/image_io.h"
#include "formats/scene_file.h"
#include "runs/scene_shifting_run.h"
#include "formats/viewer_script_file.h"

namespace oflab {
namespace {

// Options of the engine's scene modes that scene shifting has no use for.
constexpr const char* kEngineOnlyOptions[] = {
    "--threshold", "--thresholds", "--delta",         "--compare-conventional",
    "--near",      "--guard-band", "--no-skip-hidden"};

void print_summary(const SceneShiftingRun& run, const std::string& scene, const std::string& script,
                   double epsilon, std::ostream& out) {
  const SceneRunSummary& s = run.scene_run.summary;
  out << "scene " << scene << " (" << s.polygons << " polygons), viewer script " << script
      << ", mode scene-shifting, " << s.frames << " frames\n"
      << "  " << run.slices.size() << " slices (" << run.frames.front().occupied
      << " holding planes) for |V| = " << run.design_speed << " units/frame, epsilon = " << epsilon
      << " px\n";
  print_polygon_levels(s, out);
  out << "  layers after the first frame: " << run.rebuilt_layers << " rebuilt, "
      << run.shifted_layers << " shifted or scaled\n";
  if (run.turning_frames > 0) {
    out << "  the view turned in " << run.turning_frames
        << " frames; every occupied slice was rebuilt in " << run.turning_frames_all_rebuilt
        << " of them\n";
  }
  out << std::setprecision(3) << "  median frame time: scene shifting " << s.median_frame_ms
      << " ms, exact re-render " << s.baseline_median_frame_ms << " ms\n";
  print_savings_and_error(s, out);
}

int run(const CliArgs& a, std::ostream& out, std::ostream& err) {
  for (const char* option : kEngineOnlyOptions) {
    if (a.has(option))
      throw UsageError(std::string(option) + ": not used by --mode scene-shifting");
  }
  const ViewerScript script = read_viewer_script_option(a);
  const Scene scene = read_scene_option(a);
  SceneShiftingRunOptions options;
  options.settings.epsilon_px = a.number_or("--epsilon", options.settings.epsilon_px);
  if (!(options.settings.epsilon_px > 0.0) || !std::isfinite(options.settings.epsilon_px)) {
    throw UsageError("--epsilon: must be a positive number of pixels");
  }
  options.settings.sampling = read_sampling(a);
  const RunOutput output = read_run_output(a, err);
  output.apply_to(options);
  const std::string& dir = output.dir;  // empty without --out
  const SceneShiftingRun result = run_scene_shifting(scene, script, options);
  const double eps = options.settings.epsilon_px;
  nlohmann::json j = scene_summary_json(result.scene_run.summary);
  j["scene"] = scene.name;
  j["script"] = script.name;
  j["mode"] = "scene-shifting";
  j["thresholds"] = {eps, eps, eps, eps};  // the one budget, epsilon, stands for every term
  j["skip_hidden"] = false;
  nlohmann::json slices = nlohmann::json::array();
  for (const Slice& s : result.slices) {
    slices.push_back(
        {{"near", s.near}, {"far", is_background(s) ? nlohmann::json() : nlohmann::json(s.far)}});
  }
  j["scene_shifting"] = {{"epsilon_px", eps},
                         {"design_speed", result.design_speed},
                         {"slices", slices},
                         {"rebuilt_layers", result.rebuilt_layers},
                         {"shifted_layers", result.shifted_layers},
                         {"turning_frames", result.turning_frames},
                         {"turning_frames_all_rebuilt", result.turning_frames_all_rebuilt}};
  if (!dir.empty()) write_scene_outputs(dir, result.scene_run, j);
  if (a.has("--json")) {
    out << j.dump(2) << "\n";
  } else {
    print_summary(result, scene.name, script.name, eps, out);
  }
  return 0;
}

}  // namespace

int animate_scene_shifting(const CliArgs& a, std::ostream& out, std::ostream& err) {
  return report_scene_input_errors([&] { return run(a, out, err); }, err);
}

}  // namespace oflab
