// `oflab-cli slices`: the scene-shifting slices of a sideways-moving viewer (dissertation
// eq. 9 with the corrected asymptote k|V|/epsilon; core/scene_shifting/scene_shifting.h).
#include <iomanip>
#include <nlohmann/json.hpp>
#include <ostream>
#include <sstream>

#include "cli/cli_args.h"
#include "cli/commands.h"
#include "scene_shifting/scene_shifting.h"

namespace oflab {
namespace {

// The option each core parameter field comes from, for error messages.
std::string option_for_field(const std::string& field) {
  if (field == "speed") return "--speed";
  if (field == "focal_px") return "--focal";
  if (field == "near") return "--near";
  return "--epsilon";  // epsilon_px, and a slice count above the cap
}

SliceParameters read_parameters(const CliArgs& a) {
  SliceParameters p;
  p.speed = a.number("--speed");
  p.focal_px = a.number_in("--focal", limits::kFocalLength);
  p.epsilon_px = a.number("--epsilon");
  p.near = a.number_or("--near", 1.0);
  const SliceProblem problem = slice_parameters_problem(p);
  if (!problem.field.empty()) {
    throw UsageError(option_for_field(problem.field) + ": " + problem.message);
  }
  return p;
}

// Keys in the documented order: slices (near before far), then the asymptote.
nlohmann::ordered_json slices_report(const SliceParameters& p) {
  nlohmann::ordered_json slices = nlohmann::ordered_json::array();
  for (const Slice& s : scene_slices(p)) {
    nlohmann::ordered_json slice;
    slice["near"] = s.near;
    slice["far"] =
        is_background(s) ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(s.far);
    slices.push_back(slice);
  }
  nlohmann::ordered_json report;
  report["slices"] = slices;
  report["asymptote"] = slice_asymptote(p);
  return report;
}

// One table row per slice; widths and the edges' image speeds show the epsilon condition.
void print_text(const SliceParameters& p, std::ostream& stream) {
  std::ostringstream out;  // keeps the caller's stream formatting untouched
  out << "Scene slices for |V| = " << p.speed << " world units/frame, k = " << p.focal_px
      << " px, epsilon = " << p.epsilon_px << " px/frame\n";
  out << "Asymptote k|V|/epsilon = " << slice_asymptote(p)
      << " (beyond it every point moves less than epsilon per frame)\n";
  out << std::setw(6) << "slice" << std::setw(13) << "near" << std::setw(13) << "far"
      << std::setw(13) << "width"
      << "   image speed near .. far (px/frame)\n";
  const std::vector<Slice> slices = scene_slices(p);
  for (size_t i = 0; i < slices.size(); ++i) {
    const Slice& s = slices[i];
    const bool bg = is_background(s);
    out << std::setprecision(6) << std::setw(6) << i + 1 << std::setw(13) << s.near;
    if (bg) {
      out << std::setw(13) << "inf" << std::setw(13) << "inf";
    } else {
      out << std::setw(13) << s.far << std::setw(13) << s.far - s.near;
    }
    out << "   " << std::setprecision(4) << sideways_image_speed(p, s.near) << " .. "
        << sideways_image_speed(p, s.far) << (bg ? "  (background)" : "") << "\n";
  }
  stream << out.str();
}

}  // namespace

// Bad options are UsageErrors, which run_cli reports; nothing else goes to `err`.
int run_slices_command(const CommandArgs& args, std::ostream& out, std::ostream& /*err*/) {
  const CliArgs a(args,
                  {{"--speed", 1}, {"--focal", 1}, {"--epsilon", 1}, {"--near", 1}, {"--json", 0}});
  const SliceParameters p = read_parameters(a);
  if (a.has("--json")) {
    out << slices_report(p).dump(2) << "\n";
  } else {
    print_text(p, out);
  }
  return 0;
}

}  // namespace oflab
