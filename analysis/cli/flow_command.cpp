// `oflab-cli flow`: prints the planar flow coefficients, the planar basis and, with --dt,
// the Taylor and exact homographies and the corner errors of each approximation level.
#include <cmath>
#include <nlohmann/json.hpp>
#include <ostream>

#include "cli/cli_args.h"
#include "cli/commands.h"
#include "flow/basis.h"
#include "flow/homography.h"

namespace oflab {
namespace {

nlohmann::json matrix_json(const Mat3& m) {
  nlohmann::json rows = nlohmann::json::array();
  for (int r = 0; r < 3; ++r) rows.push_back({entry(m, r, 0), entry(m, r, 1), entry(m, r, 2)});
  return rows;
}

// The option names the core pose fields correspond to, for error messages.
std::string option_for_field(const std::string& field) {
  if (field == "point") return "--plane-point";
  if (field == "normal") return "--plane-normal";
  if (field == "up") return "--plane-up";
  if (field == "size") return "--plane-size";
  return "--" + field;
}

nlohmann::json flow_report(const CliArgs& a) {
  const Vec2 image = a.vec2_in("--image", limits::kImageSize);
  const Camera camera = make_camera(a.number_in("--focal", limits::kFocalLength),
                                    static_cast<int>(image.x), static_cast<int>(image.y));

  PlanePose pose;
  pose.point = a.vec3("--plane-point");
  pose.normal = a.vec3("--plane-normal");
  const bool has_extent = a.has("--plane-up") && a.has("--plane-size");
  if (a.has("--plane-up") != a.has("--plane-size")) {
    throw UsageError(a.has("--plane-up") ? "--plane-size: required with --plane-up"
                                         : "--plane-up: required with --plane-size");
  }
  if (a.has("--plane-up")) {
    pose.up = a.vec3("--plane-up");
    pose.size = a.vec2_in("--plane-size", limits::kPlaneSize);
  } else if (glm::length(glm::cross(pose.normal, pose.up)) < 1e-9 * glm::length(pose.normal)) {
    pose.up = Vec3(1.0, 0.0, 0.0);  // any up works for the flow; corners need a real one
  }
  const PoseProblem problem = plane_pose_problem(pose);
  if (!problem.field.empty())
    throw UsageError(option_for_field(problem.field) + ": " + problem.message);

  RigidMotion motion;
  motion.velocity = a.vec3_in("--velocity", limits::kVelocity);
  motion.omega = a.vec3_in("--omega", limits::kAngularVelocity);
  const std::string model = a.text_or("--motion", motion_model_name(motion.model));
  if (!parse_motion_model(model.c_str(), &motion.model)) {
    throw UsageError("--motion: '" + model + "' is not one of " + motion_model_name_list());
  }

  const PlanarFlowCoefficients c = planar_flow_coefficients(camera, pose, motion);
  const PlanarBasisTerms b = to_planar_basis(taylor_terms(c));
  nlohmann::json j;
  j["units"] = "centred pixels (x right, y down, origin at the principal point), per unit time";
  j["motion"] = motion_model_name(motion.model);
  j["coefficients"] = {{"tx", c.tx},   {"ty", c.ty},   {"j11", c.j11}, {"j12", c.j12},
                       {"j21", c.j21}, {"j22", c.j22}, {"px", c.px},   {"py", c.py}};
  j["basis"] = {{"tx", b.tx},         {"ty", b.ty},       {"scale", b.scale},
                {"squash", b.squash}, {"shear", b.shear}, {"rotation", b.rotation},
                {"px", b.px},         {"py", b.py}};
  if (a.has("--dt")) {
    const double dt = a.number("--dt");
    j["dt"] = dt;
    j["homography_taylor"] = matrix_json(taylor_homography(c, dt));
    j["homography_exact"] = matrix_json(exact_homography(camera, pose, motion, dt));
    if (has_extent) {
      const PlanePose later = advance_pose(pose, rigid_step(motion, pose, dt));
      for (const Vec3& corner : plane_corners(later)) {
        if (corner.z <= 0.0) throw UsageError("--dt: a plane corner passes behind the camera");
      }
      for (const Vec3& corner : plane_corners(pose)) {
        if (corner.z <= 0.0) throw UsageError("--plane-size: a plane corner is behind the camera");
      }
      const ApproximationErrors e = approximation_corner_errors(camera, pose, motion, dt);
      j["corner_error_px"] = {
          {"none", e.none}, {"translate", e.translate}, {"affine", e.affine}, {"taylor", e.taylor}};
    }
  }
  return j;
}

void print_text(const nlohmann::json& j, std::ostream& out) {
  out << "Planar flow coefficients (" << j["units"].get<std::string>() << ")\n";
  for (const char* k : {"tx", "ty", "j11", "j12", "j21", "j22", "px", "py"}) {
    out << "  " << k << " = " << j["coefficients"][k].get<double>() << "\n";
  }
  out << "Planar basis\n";
  for (const char* k : {"scale", "squash", "shear", "rotation", "px", "py"}) {
    out << "  " << k << " = " << j["basis"][k].get<double>() << "\n";
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
}

}  // namespace

// Bad options are UsageErrors, which run_cli reports; nothing else goes to `err`.
int run_flow_command(const CommandArgs& args, std::ostream& out, std::ostream& /*err*/) {
  const CliArgs a(args, {{"--focal", 1},
                         {"--image", 2},
                         {"--plane-point", 3},
                         {"--plane-normal", 3},
                         {"--velocity", 3},
                         {"--omega", 3},
                         {"--plane-up", 3},
                         {"--plane-size", 2},
                         {"--dt", 1},
                         {"--motion", 1},
                         {"--json", 0}});
  const nlohmann::json j = flow_report(a);
  if (a.has("--json")) {
    out << j.dump(2) << "\n";
  } else {
    print_text(j, out);
  }
  return 0;
}

}  // namespace oflab
