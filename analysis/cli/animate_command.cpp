// `oflab-cli animate`: plays a motion script through the engine and reports, per frame
// (CSV) and in summary (text or JSON), what it did and what it cost.
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli/animate_options.h"
#include "cli/animate_scene.h"
#include "cli/animate_scene_shifting.h"
#include "runs/animation_run.h"
#include "cli/cli_args.h"
#include "cli/commands.h"
#include "formats/datasets.h"
#include "formats/image_io.h"
#include "formats/script_file.h"

namespace oflab {
namespace {

namespace fs = std::filesystem;

constexpr const char* kSceneOnlyOptions[] = {"--compare-conventional", "--near", "--guard-band",
                                             "--no-skip-hidden"};

void print_summary(const AnimationSummary& s, const std::string& script, const ReusePolicy& policy,
                   std::ostream& out) {
  out << "script " << script << ", mode " << policy.name << ", " << s.frames << " frames\n";
  for (int l = 0; l < kLevelCount; ++l) {
    out << "  " << std::setw(12) << std::left << level_name(static_cast<Level>(l)) << std::right
        << std::setw(6) << s.levels[l] << " frames (" << std::fixed << std::setprecision(1)
        << 100.0 * s.levels[l] / std::max(1, s.frames) << "%)\n";
  }
  out << std::setprecision(3) << "  time saved " << 100.0 * s.time_saved << "% (engine "
      << s.time_ms << " ms, re-render " << s.baseline_time_ms << " ms, same run)\n"
      << "  work saved " << 100.0 * s.work_saved << "% (pixels written " << s.pixels << " vs "
      << s.baseline_pixels << ")\n"
      << "  max measured error " << s.max_measured_error_px << " px, mean PSNR " << s.mean_psnr_db
      << " dB\n";
  if (s.invisible_frames) out << "  " << s.invisible_frames << " frames not visible\n";
}

int animate(const CliArgs& a, std::ostream& out, std::ostream& err) {
  if (a.text_or("--mode", "") == "scene-shifting") {
    if (!a.has("--scene")) throw UsageError("--mode scene-shifting: needs --scene NAME|FILE");
    return animate_scene_shifting(a, out, err);
  }
  if (a.has("--epsilon")) throw UsageError("--epsilon: needs --mode scene-shifting");
  if (a.has("--scene")) return animate_scene(a, out, err);
  for (const char* option : kSceneOnlyOptions) {
    if (a.has(option)) throw UsageError(std::string(option) + ": needs --scene NAME|FILE");
  }
  const std::string script_arg = a.values("--script").at(0);
  std::string script_path;
  try {
    script_path = resolve_script_path(script_arg);
  } catch (const std::runtime_error& e) {
    throw UsageError(std::string("--script: ") + e.what());
  }
  const MotionScript script = read_script_file(script_path);
  const std::string texture_path = a.text_or("--texture", default_texture_path());
  const Layer texture = make_layer(read_image(texture_path));
  AnimationOptions options;
  options.settings = read_engine_settings(a);
  const RunOutput output = read_run_output(a, err);
  output.apply_to(options);
  const std::string& dir = output.dir;  // empty without --out
  const AnimationRun run = run_animation(script, texture, options);
  if (!dir.empty()) {
    std::ofstream csv(fs::path(dir) / "frames.csv");
    write_frame_csv(csv, run);
    std::ofstream summary(fs::path(dir) / "summary.json");
    summary << summary_json(run.summary).dump(2) << "\n";
    if (!csv || !summary) throw UsageError("--out: cannot write into '" + dir + "'");
  }
  const std::string name = script.name.empty() ? script_arg : script.name;
  if (a.has("--json")) {
    nlohmann::json j = summary_json(run.summary);
    j["script"] = name;
    j["mode"] = options.settings.policy->name;
    j["delta"] = delta_policy_name(options.settings.delta);
    j["thresholds"] = options.settings.thresholds;
    out << j.dump(2) << "\n";
  } else {
    print_summary(run.summary, name, *options.settings.policy, out);
  }
  return 0;
}

}  // namespace

int run_animate_command(const CommandArgs& args, std::ostream& out, std::ostream& err) {
  try {
    const CliArgs a(args, {{"--script", 1},
                           {"--texture", 1},
                           {"--mode", 1},
                           {"--threshold", 1},
                           {"--thresholds", 4},
                           {"--delta", 1},
                           {"--sampling", 1},
                           {"--frames", 1},
                           {"--out", 1},
                           {"--force", 0},
                           {"--frames-png", 0},
                           {"--json", 0},
                           {"--quiet", 0},
                           {"--scene", 1},
                           {"--compare-conventional", 0},
                           {"--near", 1},
                           {"--guard-band", 1},
                           {"--no-skip-hidden", 0},
                           {"--epsilon", 1}});
    return animate(a, out, err);
  } catch (const UsageError& e) {
    err << "oflab-cli animate: " << e.what() << "\n";
    return 2;
  } catch (const ScriptError& e) {
    err << "oflab-cli animate: " << e.what() << "\n";
    return 2;
  } catch (const ImageFileError& e) {
    err << "oflab-cli animate: --texture: " << e.what() << "\n";
    return 2;
  }
}

}  // namespace oflab
