// `oflab-cli policies`: the engine's reuse policies (core/engine/reuse_policy.h), the values
// of `oflab-cli animate --mode`, one per line as "name  summary" followed by indented lines
// saying which system each models and where it breaks, or as JSON:
//   {"policies": [{"name", "summary", "models", "breaks", "schedule" ("threshold" or
//   "cadence"), "warp" ("per-layer", "per-pixel-depth" or "node-images"), "latency_frames"
//   (at the default cadence, EngineSettings::cadence: latency_frames), "scenes_only" (true for
//   a policy a single plane cannot play: needs_scene)},
//   ...],
//   "interpolation_latency_frames": 1} in registry order; the last is what frame
//   generation's interpolation between two renders scores (DLSS 3, FSR 3; view-interpolation
//   at cadence 2), for comparison.
#include <algorithm>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <ostream>
#include <sstream>
#include <string>

#include "cli/cli_args.h"
#include "cli/commands.h"
#include "engine/engine.h"
#include "engine/reuse_policy.h"

namespace oflab {
namespace {

// Frame generation (DLSS 3, FSR 3) interpolates between two rendered frames, so it can show
// a frame only once the next one is rendered: one frame late (latency_frames of an
// interpolating policy at cadence 2).
constexpr int kInterpolationLatencyFrames = 1;

void print_text(std::ostream& stream) {
  std::size_t width = 0;
  for (const ReusePolicy& p : reuse_policies()) width = std::max(width, std::string(p.name).size());
  std::ostringstream out;  // keeps the caller's stream formatting untouched
  for (const ReusePolicy& p : reuse_policies()) {
    out << std::left << std::setw(static_cast<int>(width)) << p.name << "  " << p.summary << "\n"
        << std::string(width + 2, ' ') << "models: " << p.models << "\n"
        << std::string(width + 2, ' ') << "breaks: " << p.breaks << "\n";
  }
  out << "Latency: every policy but view-interpolation extrapolates from the last render (0\n"
         "frames of delay); view-interpolation waits for the next render, cadence - 1 frames\n"
         "late (at the default cadence "
      << EngineSettings{}.cadence << ": "
      << latency_frames(reuse_policy("view-interpolation"), EngineSettings{}.cadence)
      << "), as frame generation's interpolation (DLSS 3, FSR 3) shows each frame "
      << kInterpolationLatencyFrames << " frame late.\n";
  stream << out.str();
}

}  // namespace

nlohmann::ordered_json policies_json() {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const ReusePolicy& p : reuse_policies()) {
    nlohmann::ordered_json entry;
    entry["name"] = p.name;
    entry["summary"] = p.summary;
    entry["models"] = p.models;
    entry["breaks"] = p.breaks;
    entry["schedule"] = p.schedule == Schedule::kCadence ? "cadence" : "threshold";
    entry["warp"] = frame_warp_name(p.frame_warp);
    entry["latency_frames"] = latency_frames(p, EngineSettings{}.cadence);
    entry["scenes_only"] = needs_scene(p);
    list.push_back(entry);
  }
  nlohmann::ordered_json report;
  report["policies"] = list;
  report["interpolation_latency_frames"] = kInterpolationLatencyFrames;
  return report;
}

// Bad options are UsageErrors, which run_cli reports; nothing else goes to `err`.
int run_policies_command(const CommandArgs& args, std::ostream& out, std::ostream& /*err*/) {
  const CliArgs a(args, {{"--json", 0}});
  if (a.has("--json")) {
    out << policies_json().dump(2) << "\n";
  } else {
    print_text(out);
  }
  return 0;
}

}  // namespace oflab
