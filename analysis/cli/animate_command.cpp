// `oflab-cli animate`: plays a motion script through the engine and reports, per frame
// (CSV) and in summary (text or JSON), what it did and what it cost.
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "cli/animate_options.h"
#include "cli/animate_scene.h"
#include "cli/animate_scene_shifting.h"
#include "cli/cli_args.h"
#include "cli/commands.h"
#include "formats/image_io.h"
#include "formats/script_file.h"

namespace oflab {
namespace {

constexpr const char* kSceneOnlyOptions[] = {"--compare-conventional",
                                             "--conventional-single-sample",
                                             "--near",
                                             "--guard-band",
                                             "--no-skip-hidden",
                                             "--warp",
                                             "--hole-fill",
                                             "--cache-angle",
                                             "--node-polygons",
                                             "--safety-radius",
                                             "--mesh-grid",
                                             "--mesh-split",
                                             "--mesh-rebuild",
                                             "--mesh-jump",
                                             "--rubber-sheets"};

// The text summary, from the JSON summary of the plane kind (runs/source_kinds.h).
void print_summary(const nlohmann::json& j, const std::string& script, const ReusePolicy& policy,
                   std::ostream& out) {
  const int frames = j.at("frames");
  out << "script " << script << ", mode " << policy.name << ", " << frames << " frames\n";
  for (int l = 0; l < kLevelCount; ++l) {
    const char* name = level_name(static_cast<Level>(l));
    const int count = j.at("levels").at(name);
    out << "  " << std::setw(12) << std::left << name << std::right << std::setw(6) << count
        << " frames (" << std::fixed << std::setprecision(1) << 100.0 * count / std::max(1, frames)
        << "%)\n";
  }
  const auto number = [&](const char* key) {
    return j.at(key).is_null() ? std::nan("") : j.at(key).get<double>();
  };
  out << std::setprecision(3) << "  time saved " << 100.0 * number("time_saved") << "% (engine "
      << number("time_ms") << " ms, re-render " << number("baseline_time_ms") << " ms, same run)\n"
      << "  work saved " << 100.0 * number("work_saved") << "% (pixels written "
      << j.at("pixels_written").get<std::int64_t>() << " vs "
      << j.at("baseline_pixels_written").get<std::int64_t>() << ")\n"
      << "  max measured error " << number("max_measured_error_px") << " px, mean PSNR "
      << number("mean_psnr_db") << " dB\n"
      << "  max excess " << number("max_excess_px")
      << " px (measured minus estimated error, worst frame)\n"
      << "  model work saved " << 100.0 * number("model_work_saved")
      << "% (cost model: perspective warp 1, affine 1/2.1, translation 1/35 per pixel, "
         "re-render at its content's cost); content render "
      << number("render_ms") << " ms; max photometric error " << number("max_photometric_error")
      << " grey levels\n";
  const int invisible = j.at("invisible_frames");
  if (invisible) out << "  " << invisible << " frames not visible\n";
  if (j.contains("budget")) print_budget(j.at("budget"), out);
}

// The single-plane form: a motion script and a texture.
int animate_plane(const CliArgs& a, std::ostream& out, std::ostream& err) {
  const AnimateInputs inputs = read_animate_inputs(a);
  const std::string& script_arg = inputs.script_arg;
  const RunSource& source = inputs.source;
  const EngineSettings& settings = source.settings.engine;
  PlayOptions options;
  const RunOutput output = read_run_output(a, err);
  const SourceKind& kind = source_kind("plane");
  output.apply_to(options, kind);
  const AnimationRun run = kind.play(source, options);
  const nlohmann::json summary = kind.summary_json(run);
  output.finish();
  output.write_summary(summary);
  if (a.has("--json")) {
    out << plane_animate_json(source, run, script_arg).dump(2) << "\n";
  } else {
    const std::string name = source.script.name.empty() ? script_arg : source.script.name;
    print_summary(summary, name, *settings.policy, out);
  }
  return 0;
}

// The form of `animate` for each kind of source (analysis/runs/source_kinds.h).
struct AnimateForm {
  const char* kind;
  int (*run)(const CliArgs& args, std::ostream& out, std::ostream& err);
};
constexpr AnimateForm kAnimateForms[] = {
    {"plane", animate_plane}, {"scene", animate_scene}, {"scene-shifting", animate_scene_shifting}};

// The kind --mode selects (a mode of source_kind_modes, which needs --scene), else the
// scene with --scene, else the plane. Throws UsageError naming the option.
const SourceKind& animate_kind(const CliArgs& a) {
  const std::string mode = a.text_or("--mode", "");
  if (const SourceKind* kind = source_kind_for_mode(mode)) {
    if (!a.has("--scene")) throw UsageError("--mode " + mode + ": needs --scene NAME|FILE");
    return *kind;
  }
  if (a.has("--epsilon")) throw UsageError("--epsilon: needs --mode scene-shifting");
  const ReusePolicy* policy = find_reuse_policy(mode);
  if (std::string why; policy && needs_scene(*policy, &why) && !a.has("--scene")) {
    throw UsageError("--mode " + mode + ": needs --scene NAME|FILE (" + why + ")");
  }
  return source_kind(a.has("--scene") ? "scene" : "plane");
}

// The single plane's source, every refusal of animate's plane form made.
RunSource read_plane_form_source(const CliArgs& a) {
  for (const char* option : kSceneOnlyOptions) {
    if (a.has(option)) throw UsageError(std::string(option) + ": needs --scene NAME|FILE");
  }
  RunSource source = read_plane_source(a);
  source.repeat = read_repeat(a, source.script);
  return source;
}

void refuse_repeat_with_scene(const CliArgs& a) {
  if (a.has("--repeat") && a.has("--scene")) {
    throw UsageError("--repeat: plays a motion script again and again; not with --scene");
  }
}

int animate(const CliArgs& a, std::ostream& out, std::ostream& err) {
  refuse_repeat_with_scene(a);
  const std::string kind = animate_kind(a).name;
  for (const AnimateForm& form : kAnimateForms) {
    if (kind == form.kind) return form.run(a, out, err);
  }
  throw std::logic_error("oflab-cli animate: no form for the source kind '" + kind + "'");
}

}  // namespace

// --repeat N (default 1): within limits::kRepeat, and N times the script's frames fits an
// int. Throws UsageError naming --repeat, the value as typed and the limit.
int read_repeat(const CliArgs& a, const MotionScript& script) {
  if (!a.has("--repeat")) return 1;
  const double repeat = a.number("--repeat");
  const long frames = static_cast<long>(script.frames.size());
  const long most = std::min<long>(static_cast<long>(limits::kRepeat.maximum),
                                   std::numeric_limits<int>::max() / frames);
  const std::string range = "1.." + std::to_string(most) + " (plays of the script's " +
                            std::to_string(frames) + " frames)";
  const std::string& text = a.values("--repeat").at(0);
  if (repeat != std::floor(repeat)) {
    throw UsageError("--repeat: " + text + " is not a whole number, " + range);
  }
  if (repeat < 1 || repeat > most) throw UsageError("--repeat: " + text + " is outside " + range);
  return static_cast<int>(repeat);
}

nlohmann::json plane_animate_json(const RunSource& source, const AnimationRun& run,
                                  const std::string& script_arg) {
  const EngineSettings& settings = source.settings.engine;
  nlohmann::json j = source_kind("plane").summary_json(run);
  j["script"] = source.script.name.empty() ? script_arg : source.script.name;
  j["mode"] = settings.policy->name;
  j["delta"] = delta_policy_name(settings.delta);
  j["thresholds"] = settings.thresholds;
  j["content"] = content_name(settings.content.kind);
  j["content_quality"] = settings.content.quality;
  if (reports_holes(*settings.policy)) {
    j["cadence"] = settings.cadence;
    j["latency_frames"] = latency_frames(*settings.policy, settings.cadence);
  }
  return j;
}

AnimateInputs read_animate_inputs(const CliArgs& a) {
  refuse_repeat_with_scene(a);
  AnimateInputs inputs;
  inputs.kind = &animate_kind(a);
  inputs.script_arg = a.has("--script") ? a.values("--script").at(0) : "";
  const std::string kind = inputs.kind->name;
  if (kind == "plane") {
    inputs.source = read_plane_form_source(a);
  } else if (kind == "scene") {
    inputs.source = read_scene_source(a);
  } else {
    throw UsageError("--mode " + kind + ": only oflab-cli animate plays it");
  }
  return inputs;
}

nlohmann::json animate_json(const AnimateInputs& inputs, const AnimationRun& run) {
  if (std::string(inputs.kind->name) == "scene") return scene_animate_json(inputs.source, run);
  return plane_animate_json(inputs.source, run, inputs.script_arg);
}

const std::map<std::string, int>& animate_options() {
  static const std::map<std::string, int> options = [] {
    std::map<std::string, int> all = run_options();
    all.insert({"--warp", 1});  // scenes only (read_scene_settings)
    all.insert({{"--mode", 1},
                {"--no-warm-up", 0},
                {"--repeat", 1},
                {"--frames-png", 0},
                {"--video", 1},
                {"--fps", 1},
                {"--vtk-series", 1},
                {"--compare-conventional", 0},
                {"--conventional-single-sample", 0},
                {"--epsilon", 1}});
    return all;
  }();
  return options;
}

int run_animate_command(const CommandArgs& args, std::ostream& out, std::ostream& err) {
  try {
    const CliArgs a(args, animate_options());
    return animate(a, out, err);
  } catch (const ScriptError& e) {
    err << "oflab-cli animate: " << e.what() << "\n";
    return 2;
  } catch (const ImageFileError& e) {
    err << "oflab-cli animate: --texture: " << e.what() << "\n";
    return 2;
  }
}

}  // namespace oflab
