// JSON and text of the inverse planar flow (analysis/cli/explain_report.h).
#include "cli/explain_report.h"

#include <algorithm>
#include <cmath>
#include <ostream>
#include <sstream>
#include <string>

namespace oflab {
namespace {

constexpr double kDegreesPerRadian = 57.29577951308232;

// Adding 0.0 turns -0 into 0, which reads better and means the same.
nlohmann::json vec_json(const Vec3& v) { return {v.x + 0.0, v.y + 0.0, v.z + 0.0}; }

std::string vec_text(const nlohmann::json& v) {
  std::ostringstream s;
  s << "(" << v[0].get<double>() << ", " << v[1].get<double>() << ", " << v[2].get<double>() << ")";
  return s.str();
}

// What each case means, for the text output.
const char* case_text(const std::string& name) {
  if (name == "pure-rotation") {
    return "V = 0: the flow is that of Omega alone, the same for every plane, so the plane is "
           "unobservable";
  }
  if (name == "translation-along-normal") {
    return "V is parallel to the normal to within 6.3e-5 rad: the two solutions of the "
           "general case coincide to that angle";
  }
  if (name == "fronto-parallel-along-normal") {
    return "a plane facing the eye squarely, moving along its normal to within 6.3e-5 rad: "
           "the two solutions of the general case coincide to that angle";
  }
  return "";
}

// The first line: how many solutions are seen at the check pixel, and the case.
void print_headline(const nlohmann::json& j, const std::string& pixel, std::ostream& out) {
  const size_t count = j["solutions"].size();
  const int edge_on = j["edge_on_at_front_pixel"].get<int>();
  out << count << (count == 1 ? " solution" : " solutions");
  if (edge_on > 0) out << " seen at centred pixel " << pixel;
  if (!j["degenerate"].is_null()) {
    const std::string name = j["degenerate"].get<std::string>();
    out << " (degenerate: " << name << ": " << case_text(name) << ")\n";
    return;
  }
  out << " (general case: two planes with two motions make this same instantaneous flow; ";
  if (edge_on == 1) out << "the other is seen edge-on at this pixel";
  if (edge_on == 2) out << "both are seen edge-on at this pixel";
  if (edge_on == 0) out << "only the later frames tell them apart";
  out << ")\n";
}

}  // namespace

nlohmann::json explain_json(const InverseFlowSolutions& result, const Vec2& front_pixel) {
  nlohmann::json j;
  j["units"] =
      "viewer frame (X right, Y down, Z forward), per unit time; plane N.R = d with unit N "
      "and unknown d > 0";
  j["front_pixel"] = {front_pixel.x, front_pixel.y};
  j["degenerate"] = result.kind == InverseFlowCase::kGeneral
                        ? nlohmann::json(nullptr)
                        : nlohmann::json(inverse_flow_case_name(result.kind));
  j["mirror_candidates_behind_eye"] = result.dropped_behind;
  j["edge_on_at_front_pixel"] = result.edge_on;
  j["solutions"] = nlohmann::json::array();
  for (const PlanarMotionSolution& s : result.solutions) {
    nlohmann::json o;
    o["omega"] = vec_json(s.omega);
    o["v_over_d"] = vec_json(s.v_over_d);
    if (s.normal_known) {
      o["normal"] = vec_json(s.normal);
      o["v_over_z0"] = vec_json(s.v_over_d * s.normal.z);
      o["depth_over_d"] = s.depth_over_d;
      o["slopes"] =
          std::abs(s.normal.z) > 1e-12
              ? nlohmann::json({-s.normal.x / s.normal.z + 0.0, -s.normal.y / s.normal.z + 0.0})
              : nlohmann::json(nullptr);
    } else {
      o["normal"] = o["v_over_z0"] = o["depth_over_d"] = o["slopes"] = nullptr;
    }
    j["solutions"].push_back(o);
  }
  return j;
}

void print_explain_text(const nlohmann::json& j, std::ostream& out) {
  const auto& solutions = j["solutions"];
  std::ostringstream at;
  at << "(" << j["front_pixel"][0].get<double>() << ", " << j["front_pixel"][1].get<double>()
     << ")";
  const std::string pixel = at.str();
  print_headline(j, pixel, out);
  out << "Each plane is N.R = d with unit N pointing away from the eye and d > 0 unknown "
         "(depth up to scale);\nevery listed plane faces the camera: it is in front of the eye "
         "at centred pixel "
      << pixel << ".\n";
  const int mirrors = j["mirror_candidates_behind_eye"].get<int>();
  if (mirrors > 0) {
    out << "Left out: " << mirrors
        << " mirror candidate(s) (-N, -V/d), the same flow from a plane behind the eye.\n";
  }
  const int edge_on = j["edge_on_at_front_pixel"].get<int>();
  if (edge_on > 0) {
    out << "Left out: " << edge_on
        << " plane(s) parallel to the line of sight through this pixel (seen edge-on, no depth "
           "there); give --at a pixel where it is seen.\n";
  }
  int index = 0;
  for (const auto& s : solutions) {
    out << "Solution " << ++index << "\n";
    if (s["normal"].is_null()) {
      out << "  structure: unobservable (any plane makes this flow)\n";
    } else {
      const double n3 = s["normal"][2].get<double>();
      out << "  structure: normal N = " << vec_text(s["normal"]) << ", "
          << std::acos(std::max(-1.0, std::min(1.0, n3))) * kDegreesPerRadian
          << " deg from the optical axis\n";
      if (s["slopes"].is_null()) {
        out << "             slopes: none (the plane is parallel to the optical axis)\n";
      } else {
        out << "             slopes dZ/dX = " << s["slopes"][0].get<double>()
            << ", dZ/dY = " << s["slopes"][1].get<double>() << "\n";
      }
      out << "             depth at " << pixel << " = " << s["depth_over_d"].get<double>()
          << " d\n";
    }
    out << "  motion:    V/d = " << vec_text(s["v_over_d"]);
    if (!s["v_over_z0"].is_null()) out << ", V/Z0 = " << vec_text(s["v_over_z0"]);
    out << " per unit time\n             Omega = " << vec_text(s["omega"])
        << " rad per unit time\n";
  }
}

nlohmann::json explain_report(const CliArgs& a) {
  const std::vector<double> k = a.numbers_in("--coefficients", limits::kFlowCoefficient);
  const double focal = a.number_in("--focal", limits::kFocalLength);
  const Vec2 at = a.has("--at") ? a.vec2("--at") : Vec2(0.0, 0.0);
  PlanarFlowCoefficients c;
  c.tx = k[0];
  c.ty = k[1];
  c.j11 = k[2];
  c.j12 = k[3];
  c.j21 = k[4];
  c.j22 = k[5];
  c.px = k[6];
  c.py = k[7];
  return explain_json(solve_inverse_flow(c, focal, at), at);
}

const std::map<std::string, int>& explain_options() {
  static const std::map<std::string, int> options = {
      {"--coefficients", 8}, {"--focal", 1}, {"--at", 2}};
  return options;
}

}  // namespace oflab
