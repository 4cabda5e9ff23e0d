// `oflab-cli flow`'s report (see analysis/cli/flow_report.h).
#include "cli/flow_report.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "cli/explain_report.h"
#include "flow/basis.h"
#include "flow/homography.h"
#include "flow/inverse_flow.h"

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

// Frames `flow --explain` plays the two solutions forward, and the separation it reports.
constexpr int kExplainFrames = 1000;
constexpr double kExplainApartPx = 1.0;

// `flow --explain`: the coefficients `c` of the given pose and motion back to planes and
// motions (planes in front of the eye at the image of the plane's centre), which solution is
// the given one, how closely each maps forward to `c` again, and, with dt and the plane's
// corners, the frame at which the two solutions' corner images first differ by more than
// kExplainApartPx.
nlohmann::json explain_round_trip(const Camera& camera, const PlanePose& pose,
                                  const RigidMotion& motion, const PlanarFlowCoefficients& c,
                                  std::optional<double> dt, bool has_extent) {
  const Vec2 centre = project_centred(camera, pose.point);
  const InverseFlowSolutions r = solve_inverse_flow(c, camera.focal_px, centre);
  nlohmann::json e = explain_json(r, centre);
  // The given plane and motion as a solution: unit N with d = N.P > 0, V/d, Omega.
  Vec3 normal = glm::normalize(pose.normal);
  if (glm::dot(normal, pose.point) < 0.0) normal = -normal;
  const Vec3 v_over_d = eye_velocity(motion, pose) / glm::dot(normal, pose.point);
  nlohmann::json given = nullptr;
  double worst = 0.0;
  for (size_t i = 0; i < r.solutions.size(); ++i) {
    const PlanarMotionSolution& s = r.solutions[i];
    const SolutionScene scene = solution_scene(s, camera.focal_px, centre, motion.model);
    worst = std::max(
        worst, relative_coefficient_difference(
                   planar_flow_coefficients(camera, scene.pose, scene.motion), c, camera.focal_px));
    const double scale = std::max({glm::length(v_over_d), glm::length(motion.omega), 1e-300});
    const bool same_normal = !s.normal_known || glm::length(s.normal - normal) < 1e-6;
    if (same_normal && glm::length(s.v_over_d - v_over_d) < 1e-6 * scale &&
        glm::length(s.omega - motion.omega) < 1e-6 * scale) {
      given = static_cast<int>(i + 1);
    }
  }
  e["given_solution"] = given;
  e["round_trip_relative_error"] = worst;
  if (dt && has_extent && r.solutions.size() == 2) {
    std::array<Vec2, 4> corners;
    const auto world = plane_corners(pose);
    for (int i = 0; i < 4; ++i) corners[i] = project_centred(camera, world[i]);
    try {
      const FutureSeparation f =
          compare_futures(r.solutions[0], r.solutions[1], camera.focal_px, centre, corners,
                          motion.model, *dt, kExplainFrames, kExplainApartPx);
      e["futures"] = {
          {"dt", *dt},
          {"threshold_px", kExplainApartPx},
          {"max_frames", kExplainFrames},
          {"frames_played", f.frames_played},
          {"first_frame_apart",
           f.first_frame_apart < 0 ? nlohmann::json(nullptr) : nlohmann::json(f.first_frame_apart)},
          {"distance_px_at_frame_1", f.corner_distance_px.size() > 1
                                         ? nlohmann::json(f.corner_distance_px[1])
                                         : nlohmann::json(nullptr)}};
    } catch (const std::invalid_argument&) {
      e["futures"] = {{"dt", *dt},
                      {"not_played",
                       "the other solution's plane is behind the eye at a corner "
                       "of the plane's image"}};
    }
  }
  return e;
}

// --plane-point and --plane-normal, with --plane-up and --plane-size (both or neither: the
// plane's extent, which its corners need). Throws UsageError naming the option of the field
// plane_pose_problem names.
PlanePose read_plane_pose(const CliArgs& a) {
  PlanePose pose;
  pose.point = a.vec3("--plane-point");
  pose.normal = a.vec3("--plane-normal");
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
  return pose;
}

// --velocity, --omega (per unit time, their limits) and --motion (a motion model's name).
// Throws UsageError naming the option.
RigidMotion read_motion(const CliArgs& a) {
  RigidMotion motion;
  motion.velocity = a.vec3_in("--velocity", limits::kVelocity);
  motion.omega = a.vec3_in("--omega", limits::kAngularVelocity);
  const std::string model = a.text_or("--motion", motion_model_name(motion.model));
  if (!parse_motion_model(model.c_str(), &motion.model)) {
    throw UsageError("--motion: '" + model + "' is not one of " + motion_model_name_list());
  }
  return motion;
}

// The coefficients `c` and their planar basis terms, as the report's JSON.
void add_coefficients(nlohmann::json& j, const PlanarFlowCoefficients& c) {
  const PlanarBasisTerms b = to_planar_basis(taylor_terms(c));
  j["coefficients"] = {{"tx", c.tx},   {"ty", c.ty},   {"j11", c.j11}, {"j12", c.j12},
                       {"j21", c.j21}, {"j22", c.j22}, {"px", c.px},   {"py", c.py}};
  j["basis"] = {{"tx", b.tx},         {"ty", b.ty},       {"scale", b.scale},
                {"squash", b.squash}, {"shear", b.shear}, {"rotation", b.rotation},
                {"px", b.px},         {"py", b.py}};
}

// --dt: the Taylor and exact homographies over `dt` and, with the plane's extent, the corner
// errors of each approximation level (pixels). Throws UsageError when a corner of the plane
// is behind the camera now or after dt.
void add_homographies(nlohmann::json& j, const Camera& camera, const PlanePose& pose,
                      const RigidMotion& motion, const PlanarFlowCoefficients& c, double dt,
                      bool has_extent) {
  j["dt"] = dt;
  j["homography_taylor"] = matrix_json(taylor_homography(c, dt));
  j["homography_exact"] = matrix_json(exact_homography(camera, pose, motion, dt));
  if (!has_extent) return;
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

}  // namespace

FlowReport flow_report(const CliArgs& a) {
  const Vec2 image = a.vec2_in("--image", limits::kImageSize);
  FlowReport r;
  r.camera = make_camera(a.number_in("--focal", limits::kFocalLength), static_cast<int>(image.x),
                         static_cast<int>(image.y));
  const PlanePose pose = read_plane_pose(a);
  const bool has_extent = a.has("--plane-up") && a.has("--plane-size");
  const RigidMotion motion = read_motion(a);

  r.coefficients = planar_flow_coefficients(r.camera, pose, motion);
  nlohmann::json& j = r.json;
  j["units"] = "centred pixels (x right, y down, origin at the principal point), per unit time";
  j["motion"] = motion_model_name(motion.model);
  add_coefficients(j, r.coefficients);
  if (a.has("--dt")) {
    add_homographies(j, r.camera, pose, motion, r.coefficients, a.number("--dt"), has_extent);
  }
  if (a.has("--explain")) {
    j["explain"] = explain_round_trip(r.camera, pose, motion, r.coefficients,
                                      a.optional_number("--dt"), has_extent);
  }
  return r;
}

const std::map<std::string, int>& flow_options() {
  static const std::map<std::string, int> options = {
      {"--focal", 1},    {"--image", 2},  {"--plane-point", 3}, {"--plane-normal", 3},
      {"--velocity", 3}, {"--omega", 3},  {"--plane-up", 3},    {"--plane-size", 2},
      {"--dt", 1},       {"--motion", 1}, {"--explain", 0}};
  return options;
}

}  // namespace oflab
