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
#include "formats/viewer_script_file.h"
#include "runs/source_kinds.h"

namespace oflab {
namespace {

// Options of the engine's scene modes that scene shifting has no use for.
constexpr const char* kEngineOnlyOptions[] = {"--threshold",
                                              "--thresholds",
                                              "--delta",
                                              "--compare-conventional",
                                              "--near",
                                              "--guard-band",
                                              "--no-skip-hidden",
                                              "--budget-pixels",
                                              "--budget-ms",
                                              "--cadence",
                                              "--stabilization-plane",
                                              "--hole-fill",
                                              "--cache-angle",
                                              "--node-polygons",
                                              "--safety-radius",
                                              "--mesh-grid",
                                              "--mesh-split",
                                              "--mesh-rebuild",
                                              "--mesh-jump",
                                              "--rubber-sheets"};

void print_summary(const AnimationRun& run, const std::string& scene, const std::string& script,
                   std::ostream& out) {
  const RunSummary& s = run.summary;
  const nlohmann::json& f = run.facts.at("scene_shifting");
  out << "scene " << scene << " (" << s.layers << " polygons), viewer script " << script
      << ", mode scene-shifting, " << s.frames << " frames\n"
      << "  " << f.at("slices").size() << " slices (" << run.facts.at("occupied_slices").get<int>()
      << " holding planes) for |V| = " << f.at("design_speed").get<double>()
      << " units/frame, epsilon = " << f.at("epsilon_px").get<double>() << " px\n";
  print_polygon_levels(s, out);
  out << "  layers after the first frame: " << f.at("rebuilt_layers").get<long>() << " rebuilt, "
      << f.at("shifted_layers").get<long>() << " shifted or scaled\n";
  const int turning = f.at("turning_frames");
  if (turning > 0) {
    out << "  the view turned in " << turning << " frames; every occupied slice was rebuilt in "
        << f.at("turning_frames_all_rebuilt").get<int>() << " of them\n";
  }
  out << std::setprecision(3) << "  median frame time: scene shifting " << s.median_frame_ms
      << " ms, exact re-render " << s.baseline_median_frame_ms << " ms\n";
  print_savings_and_error(s, out);
}

// Plays the run; the slicing's refusal of --epsilon ("scene slices: max_slices: ..." or
// "scene slices: epsilon_px: ...", core/scene_shifting/scene_shifting.h) becomes a UsageError
// naming --epsilon. Other errors pass through.
AnimationRun play_slices(const SourceKind& kind, const RunSource& source,
                         const PlayOptions& options) {
  try {
    return kind.play(source, options);
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    for (const char* field : {"max_slices: ", "epsilon_px: "}) {
      const std::string prefix = std::string("scene slices: ") + field;
      if (message.rfind(prefix, 0) == 0) {
        throw UsageError("--epsilon: " + message.substr(prefix.size()));
      }
    }
    throw;
  }
}

int run(const CliArgs& a, std::ostream& out, std::ostream& err) {
  for (const char* option : kEngineOnlyOptions) {
    if (a.has(option))
      throw UsageError(std::string(option) + ": not used by --mode scene-shifting");
  }
  if (a.has("--warp")) throw UsageError("--warp: not used by --mode scene-shifting");
  RunSource source;
  source.viewer = read_viewer_script_option(a);
  source.scene = std::make_shared<const Scene>(read_scene_option(a));
  SceneShiftingSettings& settings = source.shifting;
  settings.epsilon_px = a.number_or("--epsilon", settings.epsilon_px);
  if (!(settings.epsilon_px > 0.0) || !std::isfinite(settings.epsilon_px)) {
    throw UsageError("--epsilon: must be a positive number of pixels");
  }
  settings.sampling = read_sampling(a);
  PlayOptions options;
  const RunOutput output = read_run_output(a, err);
  const SourceKind& kind = source_kind("scene-shifting");
  output.apply_to(options, kind);
  const AnimationRun result = play_slices(kind, source, options);
  const double eps = settings.epsilon_px;
  nlohmann::json j = kind.summary_json(result);
  j["scene"] = source.scene->name;
  j["script"] = source.viewer.name;
  j["mode"] = "scene-shifting";
  j["thresholds"] = {eps, eps, eps, eps};  // the one budget, epsilon, stands for every term
  j["skip_hidden"] = false;
  output.finish();
  output.write_summary(j);
  if (a.has("--json")) {
    out << j.dump(2) << "\n";
  } else {
    print_summary(result, source.scene->name, source.viewer.name, out);
  }
  return 0;
}

}  // namespace

int animate_scene_shifting(const CliArgs& a, std::ostream& out, std::ostream& err) {
  return report_scene_input_errors([&] { return run(a, out, err); }, err);
}

}  // namespace oflab
