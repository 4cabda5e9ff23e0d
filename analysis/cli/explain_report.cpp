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
    return "V is parallel to the normal: the two solutions of the general case coincide";
  }
  if (name == "fronto-parallel-along-normal") {
    return "a plane facing the eye squarely, moving along its normal: the two solutions of "
           "the general case coincide";
  }
  return "";
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
  out << solutions.size() << (solutions.size() == 1 ? " solution" : " solutions");
  if (j["degenerate"].is_null()) {
    out << " (general case: two planes with two motions make this same instantaneous flow; "
           "only the later frames tell them apart)\n";
  } else {
    const std::string name = j["degenerate"].get<std::string>();
    out << " (degenerate: " << name << ": " << case_text(name) << ")\n";
  }
  out << "Each plane is N.R = d with unit N pointing away from the eye and d > 0 unknown "
         "(depth up to scale);\nevery listed plane faces the camera: it is in front of the eye "
         "at centred pixel "
      << pixel << ".\n";
  const int mirrors = j["mirror_candidates_behind_eye"].get<int>();
  if (mirrors > 0) {
    out << "Left out: " << mirrors
        << " mirror candidate(s) (-N, -V/d), the same flow from a plane behind the eye.\n";
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

}  // namespace oflab
