#include "basis/basis_explorer.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "flow/homography.h"
#include "flow/plane.h"

namespace oflab {
namespace {

using P = PlanarBasisTerms;

constexpr double kPi = 3.14159265358979323846;

}  // namespace

const std::array<ExplorerTerm, kExplorerTermCount>& explorer_terms() {
  using namespace limits;
  static const std::array<ExplorerTerm, kExplorerTermCount> terms = {{
      {"tx", "translation in x", 0, &P::tx, &kTranslationRate, 200.0, 1},
      {"ty", "translation in y", 0, &P::ty, &kTranslationRate, 200.0, 1},
      {"scale", "uniform scaling (divergence / 2)", 1, &P::scale, &kFirstOrderRate, 1.0, 3},
      {"squash", "squash: y grows, x shrinks", 1, &P::squash, &kFirstOrderRate, 1.0, 3},
      {"shear", "shear (e_xy)", 1, &P::shear, &kFirstOrderRate, 1.0, 3},
      {"rotation", "rotation (curl / 2)", 1, &P::rotation, &kFirstOrderRate, 1.0, 3},
      {"px", "perspective in x", 2, &P::px, &kPerspectiveRate, 0.001, 6},
      {"py", "perspective in y", 2, &P::py, &kPerspectiveRate, 0.001, 6},
  }};
  return terms;
}

int find_explorer_term(const std::string& key) {
  for (int k = 0; k < kExplorerTermCount; ++k) {
    if (key == explorer_terms()[size_t(k)].key) return k;
  }
  return -1;
}

ExplorerTerms default_explorer_terms() {
  // tx ty scale squash shear rotation px py: drifting right and up, growing, turning, with
  // the perspective of a tilted plane. Its futures are 0.006 px apart after one frame and
  // first more than 1 px apart at frame 13.
  return {40.0, -20.0, 0.15, 0.05, 0.08, 0.25, 0.00015, -0.0001};
}

PlanarBasisTerms explorer_planar_basis(const ExplorerTerms& terms) {
  PlanarBasisTerms p;
  for (int k = 0; k < kExplorerTermCount; ++k)
    p.*explorer_terms()[size_t(k)].member = terms[size_t(k)];
  return p;
}

PlanarFlowCoefficients explorer_coefficients(const ExplorerTerms& terms) {
  return planar_coefficients(explorer_planar_basis(terms));
}

ExplorerTerms explorer_terms_of(const PlanarFlowCoefficients& coefficients) {
  const PlanarBasisTerms p = to_planar_basis(taylor_terms(reexpand(coefficients, Vec2(0.0, 0.0))));
  ExplorerTerms terms;
  for (int k = 0; k < kExplorerTermCount; ++k)
    terms[size_t(k)] = p.*explorer_terms()[size_t(k)].member;
  return terms;
}

std::string explorer_terms_problem(const ExplorerTerms& terms) {
  for (int k = 0; k < kExplorerTermCount; ++k) {
    const ExplorerTerm& term = explorer_terms()[size_t(k)];
    const std::string problem = term.limit->problem(terms[size_t(k)]);
    if (!problem.empty()) {
      return std::string("basis.terms.") + term.key + ": " + term.limit->what + " " + problem;
    }
  }
  return "";
}

ExplorerResult explore(const ExplorerTerms& terms, const Camera& camera) {
  ExplorerResult r;
  r.coefficients = explorer_coefficients(terms);
  r.inverse = solve_inverse_flow(r.coefficients, camera.focal_px);
  const double x = 0.25 * camera.width, y = 0.25 * camera.height;
  r.corners = {Vec2(-x, -y), Vec2(x, -y), Vec2(x, y), Vec2(-x, y)};
  if (r.inverse.solutions.size() != 2) {
    r.futures_note = r.inverse.solutions.size() == 1 ? "one solution: its future is the only one"
                                                     : "no plane is seen: nothing to play forward";
    return r;
  }
  try {
    r.futures = compare_futures(r.inverse.solutions[0], r.inverse.solutions[1], camera.focal_px,
                                Vec2(0.0, 0.0), r.corners, MotionModel::kScrew, kFutureFrameSeconds,
                                kFutureFrames, kFuturesApartPx);
    r.futures_played = true;
  } catch (const std::invalid_argument&) {
    r.futures_note = "a solution's plane is behind the eye at a corner of the picture";
  }
  return r;
}

std::string explorer_case_text(const InverseFlowSolutions& r) {
  switch (r.kind) {
    case InverseFlowCase::kGeneral:
      return r.solutions.size() == 2 ? "General case: two planes, moving differently, make "
                                       "exactly this flow."
                                     : "General case, but only one plane is in front of the eye "
                                       "(the other is seen edge-on).";
    case InverseFlowCase::kTranslationAlongNormal:
      return "Degenerate (translation along the normal): V is along N, the two solutions "
             "coincide.";
    case InverseFlowCase::kFrontoParallelAlongNormal:
      return "Degenerate (fronto-parallel along the normal): a plane facing the eye, moving "
             "along the line of sight: one solution.";
    case InverseFlowCase::kPureRotation:
      if (!r.solutions.empty() && r.solutions[0].omega == Vec3(0.0)) {
        return "No motion: every term is zero, and any plane at rest fits.";
      }
      return "Degenerate (pure rotation): V = 0, Omega only; any plane fits.";
  }
  return "";
}

std::string explorer_facing_text(const PlanarMotionSolution& s) {
  if (!s.normal_known) return "unknown";
  const double degrees = std::acos(std::min(1.0, std::abs(s.normal.z))) * 180.0 / kPi;
  if (degrees < 0.5) return "faces it squarely";
  return "turned " + std::to_string(int(std::lround(degrees))) + "\u00b0 away";
}

Vec2 explorer_view_of(const Vec3& p) {
  constexpr double kYaw = 0.9, kPitch = 0.45;  // radians
  const double x = std::cos(kYaw) * p.x - std::sin(kYaw) * p.z;
  const double z = std::sin(kYaw) * p.x + std::cos(kYaw) * p.z;
  return Vec2(x, std::cos(kPitch) * p.y + std::sin(kPitch) * z);
}

SolutionSketch explorer_sketch(const PlanarMotionSolution& s, double arrow) {
  // Only the direction of the centre ray matters: any camera with its principal point at the
  // centre gives the same plane.
  const SolutionScene scene = solution_scene(s, 1.0, Vec2(0.0, 0.0), MotionModel::kScrew);
  const Vec3 centre = scene.pose.point;
  const std::array<Vec3, 4> corners = plane_corners(scene.pose);
  SolutionSketch sketch;
  for (size_t k = 0; k < 4; ++k) sketch.corners[k] = explorer_view_of(corners[k]);
  sketch.centre = explorer_view_of(centre);
  sketch.normal_tip = explorer_view_of(centre + 0.5 * s.normal);
  sketch.velocity_tip = explorer_view_of(centre + arrow * s.v_over_d);
  sketch.spin_tip = explorer_view_of(arrow * s.omega);
  return sketch;
}

double explorer_arrow_scale(const std::vector<PlanarMotionSolution>& solutions) {
  double longest = 1e-12;
  for (const PlanarMotionSolution& s : solutions) {
    longest = std::max({longest, glm::length(s.v_over_d), glm::length(s.omega)});
  }
  return 0.8 / longest;
}

Mat3 explorer_deformation(const ExplorerTerms& terms) {
  // The flow's rates held constant make a one-parameter group of homographies, exp(t B);
  // composing core's first-order step over many short steps converges to it (the error of
  // each step is O(dt^2), so of the whole O(1 / kSteps)), without a matrix exponential here.
  constexpr int kSteps = 1024;
  const Mat3 step = taylor_homography(explorer_coefficients(terms), kDeformationSeconds / kSteps);
  Mat3 h(1.0);
  for (int k = 0; k < kSteps; ++k) h = step * h;
  return h / h[2][2];
}

GridChange explorer_grid_change(const ExplorerTerms& terms, const Camera& camera) {
  const Mat3 h = explorer_deformation(terms);
  const double x = 0.25 * camera.width, y = 0.25 * camera.height;
  const Vec2 before[4] = {Vec2(-x, -y), Vec2(x, -y), Vec2(x, y), Vec2(-x, y)};
  Vec2 after[4];
  for (int i = 0; i < 4; ++i) after[i] = apply_homography(h, before[i]);
  // The shoelace area of a quadrilateral in corner order.
  const auto area = [](const Vec2* q) {
    double twice = 0.0;
    for (int i = 0; i < 4; ++i) twice += q[i].x * q[(i + 1) % 4].y - q[(i + 1) % 4].x * q[i].y;
    return 0.5 * std::abs(twice);
  };
  const auto longer_over_shorter = [](double a, double b) {
    return std::max(a, b) / std::max(std::min(a, b), 1e-300) - 1.0;
  };
  GridChange change;
  change.shift_px = glm::length(apply_homography(h, Vec2(0.0, 0.0)));
  change.area = area(after) / area(before);
  const Vec2 middle = apply_homography(h, Vec2(x, 0.0)) - apply_homography(h, Vec2(-x, 0.0));
  change.turn_deg = std::atan2(middle.y, middle.x) * 180.0 / kPi;
  const double top = glm::length(after[1] - after[0]), bottom = glm::length(after[2] - after[3]);
  const double right = glm::length(after[2] - after[1]), left = glm::length(after[3] - after[0]);
  change.keystone = std::max(longer_over_shorter(top, bottom), longer_over_shorter(left, right));
  return change;
}

bool grid_change_field(const GridChange& change, const std::string& name, double* value) {
  const std::pair<const char*, double> fields[] = {{"shift_px", change.shift_px},
                                                   {"area", change.area},
                                                   {"turn_deg", change.turn_deg},
                                                   {"keystone", change.keystone}};
  for (const auto& [key, v] : fields) {
    if (name == key) {
      *value = v;
      return true;
    }
  }
  return false;
}

}  // namespace oflab
