// `oflab-cli flow`: prints the planar flow coefficients, the planar basis and, with --dt,
// the Taylor and exact homographies and the corner errors of each approximation level; with
// --explain, the round trip of the coefficients back to planes and motions.
#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <stdexcept>

#include "cli/cli_args.h"
#include "cli/commands.h"
#include "cli/explain_report.h"
#include "cli/flow_report.h"
#include "flow/basis.h"
#include "flow/homography.h"
#include "formats/atomic_file.h"
#include "formats/vtk_export.h"

namespace oflab {
namespace {

void print_explain_round_trip(const nlohmann::json& e, std::ostream& out) {
  out << "Explain: the coefficients back to planes and motions\n";
  print_explain_text(e, out);
  if (e["given_solution"].is_null()) {
    out << "None of the solutions is the given plane and motion (a bug: please report it)\n";
  } else {
    out << "Solution " << e["given_solution"].get<int>() << " is the given plane and motion\n";
  }
  out << "Each solution maps forward to the coefficients within "
      << e["round_trip_relative_error"].get<double>() << " (relative)\n";
  if (!e.contains("futures")) return;
  const auto& f = e["futures"];
  if (f.contains("not_played")) {
    out << "Not played forward: " << f["not_played"].get<std::string>() << "\n";
    return;
  }
  out << "Played forward (dt = " << f["dt"].get<double>() << "), the corner images of the two "
      << "solutions differ by " << f["distance_px_at_frame_1"].get<double>() << " px at frame 1";
  if (f["first_frame_apart"].is_null()) {
    out << " and by at most " << f["threshold_px"].get<double>() << " px in "
        << f["frames_played"].get<int>() << " frames\n";
  } else {
    out << " and first by more than " << f["threshold_px"].get<double>() << " px at frame "
        << f["first_frame_apart"].get<int>() << "\n";
  }
}

// --vtk FILE.vti with --vtk-step N (default kDefaultVtkGridStep) and --force: the file's
// name and step, checked before any work (the extension, the grid's limits, whether FILE
// may be written). Throws UsageError naming the option; empty without --vtk.
struct VtkOutput {
  std::string path;
  int step = kDefaultVtkGridStep;
};
VtkOutput read_vtk_output(const CliArgs& a, const Camera& camera) {
  VtkOutput v;
  if (!a.has("--vtk")) {
    if (a.has("--vtk-step")) throw UsageError("--vtk-step: needs --vtk FILE.vti");
    return v;
  }
  v.path = a.values("--vtk").at(0);
  const std::string ext = ".vti";
  if (v.path.size() <= ext.size() || v.path.compare(v.path.size() - ext.size(), ext.size(), ext)) {
    throw UsageError("--vtk: '" + v.path + "' does not end in .vti (VTK XML image data)");
  }
  if (a.has("--vtk-step")) {
    const double step = a.number("--vtk-step");
    const std::string problem = flow_grid_problem(camera, step);
    if (!problem.empty()) throw UsageError("--vtk-step: " + problem);
    v.step = static_cast<int>(step);
  }
  const std::string problem = flow_grid_problem(camera, v.step);
  if (!problem.empty()) throw UsageError("--vtk: the default --vtk-step " + problem);
  try {
    check_output_file(v.path, a.has("--force") ? Overwrite::kReplace : Overwrite::kRefuse);
  } catch (const FileWriteError& e) {
    throw UsageError(std::string("--vtk: ") + e.what());
  }
  return v;
}

// The report and, with --vtk, the flow field written for ParaView.
nlohmann::json flow_report_with_vtk(const CliArgs& a) {
  if (a.has("--force") && !a.has("--vtk")) throw UsageError("--force: needs --vtk FILE.vti");
  const FlowReport report = flow_report(a);
  const VtkOutput vtk = read_vtk_output(a, report.camera);
  if (!vtk.path.empty()) {
    write_file_atomically(vtk.path, flow_field_vti(report.camera, report.coefficients, vtk.step),
                          a.has("--force") ? Overwrite::kReplace : Overwrite::kRefuse);
  }
  return report.json;
}

// `value` as a reader expects it: a zero is printed "0", never "-0" (adding +0.0 turns a
// negative zero into a positive one and changes no other number).
double shown(double value) { return value + 0.0; }

void print_text(const nlohmann::json& j, std::ostream& out) {
  out << "Planar flow coefficients (" << j["units"].get<std::string>() << ")\n";
  for (const char* k : {"tx", "ty", "j11", "j12", "j21", "j22", "px", "py"}) {
    out << "  " << k << " = " << shown(j["coefficients"][k].get<double>()) << "\n";
  }
  out << "Planar basis\n";
  for (const char* k : {"scale", "squash", "shear", "rotation", "px", "py"}) {
    out << "  " << k << " = " << shown(j["basis"][k].get<double>()) << "\n";
  }
  for (const char* key : {"homography_taylor", "homography_exact"}) {
    if (!j.contains(key)) continue;
    out << key << " (dt = " << j["dt"].get<double>() << ")\n";
    for (const auto& row : j[key]) out << "  " << row.dump() << "\n";
  }
  if (j.contains("corner_error_px")) {
    out << "Largest corner error after dt, pixels\n";
    for (const char* k : {"none", "translate", "affine", "taylor"}) {
      out << "  " << k << " = " << j["corner_error_px"][k].get<double>() << "\n";
    }
  }
  if (j.contains("explain")) print_explain_round_trip(j["explain"], out);
}

}  // namespace

// Bad options are UsageErrors, which run_cli reports; nothing else goes to `err`.
int run_flow_command(const CommandArgs& args, std::ostream& out, std::ostream& /*err*/) {
  std::map<std::string, int> options = flow_options();
  options.insert({{"--vtk", 1}, {"--vtk-step", 1}, {"--force", 0}, {"--json", 0}});
  const CliArgs a(args, options);
  const nlohmann::json j = flow_report_with_vtk(a);
  if (a.has("--json")) {
    out << j.dump(2) << "\n";
  } else {
    print_text(j, out);
  }
  return 0;
}

}  // namespace oflab
