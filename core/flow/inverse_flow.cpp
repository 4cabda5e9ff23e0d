// The planar flow coefficients back to planes and motions (manual/theory.md section 10).
#include "flow/inverse_flow.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace oflab {
namespace {

// Eigenvalues (descending) and orthonormal eigenvectors of a symmetric 3x3 matrix, by cyclic
// Jacobi rotations: backward stable, so V diag(values) V^T reproduces the matrix to rounding.
struct SymmetricEigen {
  std::array<double, 3> values;
  std::array<Vec3, 3> vectors;
};

SymmetricEigen symmetric_eigen(const Mat3& m) {
  double a[3][3];
  double v[3][3] = {{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}};
  double norm2 = 0.0;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      a[r][c] = entry(m, r, c);
      norm2 += a[r][c] * a[r][c];
    }
  }
  for (int sweep = 0; sweep < 64; ++sweep) {
    const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    if (off <= 1e-36 * norm2 || off == 0.0) break;
    for (int p = 0; p < 2; ++p) {
      for (int q = p + 1; q < 3; ++q) {
        if (a[p][q] == 0.0) continue;
        // The rotation in the (p, q) plane that zeroes a[p][q] (the smaller of the two angles).
        const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
        const double t =
            std::abs(theta) > 1e150
                ? 0.5 / theta
                : std::copysign(1.0, theta) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
        const double cs = 1.0 / std::sqrt(t * t + 1.0);
        const double sn = t * cs;
        // a <- J^T a J and v <- v J, J the identity with J[p][p] = J[q][q] = cs, J[p][q] = sn,
        // J[q][p] = -sn.
        for (int k = 0; k < 3; ++k) {
          const double akp = a[k][p], akq = a[k][q];
          a[k][p] = cs * akp - sn * akq;
          a[k][q] = sn * akp + cs * akq;
        }
        for (int k = 0; k < 3; ++k) {
          const double apk = a[p][k], aqk = a[q][k];
          a[p][k] = cs * apk - sn * aqk;
          a[q][k] = sn * apk + cs * aqk;
        }
        for (int k = 0; k < 3; ++k) {
          const double vkp = v[k][p], vkq = v[k][q];
          v[k][p] = cs * vkp - sn * vkq;
          v[k][q] = sn * vkp + cs * vkq;
        }
      }
    }
  }
  int order[3] = {0, 1, 2};
  for (int i = 0; i < 3; ++i) {
    for (int j = i + 1; j < 3; ++j) {
      if (a[order[j]][order[j]] > a[order[i]][order[i]]) std::swap(order[i], order[j]);
    }
  }
  SymmetricEigen e;
  for (int i = 0; i < 3; ++i) {
    const int k = order[i];
    e.values[i] = a[k][k];
    e.vectors[i] = Vec3(v[0][k], v[1][k], v[2][k]);
  }
  return e;
}

bool finite_coefficients(const PlanarFlowCoefficients& c) {
  for (double x : {c.tx, c.ty, c.j11, c.j12, c.j21, c.j22, c.px, c.py, c.origin.x, c.origin.y}) {
    if (!std::isfinite(x)) return false;
  }
  return true;
}

Vec3 ray_through(const Vec2& pixel, double focal_px) {
  return Vec3(pixel.x / focal_px, pixel.y / focal_px, 1.0);
}

void check_inverse_flow_inputs(const PlanarFlowCoefficients& c, double focal_px,
                               const Vec2& front_pixel) {
  if (!(focal_px > 0.0) || !std::isfinite(focal_px)) {
    throw std::invalid_argument("focal length must be a positive finite number of pixels");
  }
  if (!finite_coefficients(c) || !std::isfinite(front_pixel.x) || !std::isfinite(front_pixel.y)) {
    throw std::invalid_argument("flow coefficients and the check pixel must be finite");
  }
}

// The flow matrix of the coefficients (re-expanded about the principal point) split into its
// rotation w (the antisymmetric part, [w]x) and the eigen-decomposition of its symmetric part.
struct FlowMatrixParts {
  Vec3 rotation;
  SymmetricEigen symmetric;
};

FlowMatrixParts flow_matrix_parts(const PlanarFlowCoefficients& c, double f) {
  const PlanarFlowCoefficients k = (c.origin == Vec2(0.0, 0.0)) ? c : reexpand(c, Vec2(0.0, 0.0));
  // The flow matrix up to a multiple of the identity (manual/flow-math.md section 2, read
  // backwards), with B33 set to 0.
  const Mat3 b = mat3_from_rows({k.j11, k.j12, k.tx / f}, {k.j21, k.j22, k.ty / f},
                                {-f * k.px, -f * k.py, 0.0});
  const Mat3 bt = glm::transpose(b);
  const Mat3 sym = 0.5 * (b + bt);
  const Mat3 anti = 0.5 * (b - bt);
  const Vec3 w(entry(anti, 2, 1), entry(anti, 0, 2), entry(anti, 1, 0));  // [w]x = anti
  return {w, symmetric_eigen(sym)};
}

// `v` with each component of magnitude at most kRoundingNoise * `scale` set to 0: what the
// eigen-decomposition leaves in place of an exact zero (3.5e-18 instead of 0 for a plane
// facing the eye squarely) is rounding, and a component that small is no information.
constexpr double kRoundingNoise = 1e-13;

Vec3 without_rounding_noise(Vec3 v, double scale) {
  for (int i = 0; i < 3; ++i) {
    if (std::abs(v[i]) <= kRoundingNoise * scale) v[i] = 0.0;
  }
  return v;
}

// One candidate (V/d, unit N) as the plane in front of the eye along ray `rho`, with the
// rotation that makes the flow with `w` (`scale` the flow matrix's, for rounding noise):
// false when the plane is seen edge-on there (no solution). A normal facing away is mirrored
// through the eye, V/d with it.
bool solution_in_front(Vec3 velocity, Vec3 normal, const Vec3& w, const Vec3& rho, double scale,
                       PlanarMotionSolution& s) {
  normal = without_rounding_noise(normal, 1.0);
  velocity = without_rounding_noise(velocity, glm::length(velocity));
  const double facing = glm::dot(normal, rho);
  if (std::abs(facing) <= 1e-12 * glm::length(rho)) return false;  // edge-on at the check pixel
  if (facing < 0.0) {  // the mirror image through the eye is the one in front
    normal = -normal;
    velocity = -velocity;
  }
  s.normal = normal;
  s.v_over_d = velocity;
  s.omega = without_rounding_noise(w - 0.5 * glm::cross(normal, velocity), scale);
  s.depth_over_d = 1.0 / std::abs(facing);
  return true;
}
}  // namespace

const char* inverse_flow_case_name(InverseFlowCase kind) {
  switch (kind) {
    case InverseFlowCase::kGeneral:
      return "general";
    case InverseFlowCase::kTranslationAlongNormal:
      return "translation-along-normal";
    case InverseFlowCase::kFrontoParallelAlongNormal:
      return "fronto-parallel-along-normal";
    case InverseFlowCase::kPureRotation:
      return "pure-rotation";
  }
  return "general";
}

InverseFlowSolutions solve_inverse_flow(const PlanarFlowCoefficients& c, double focal_px,
                                        const Vec2& front_pixel) {
  check_inverse_flow_inputs(c, focal_px, front_pixel);
  const double f = focal_px;
  const FlowMatrixParts parts = flow_matrix_parts(c, f);
  const Vec3& w = parts.rotation;
  const SymmetricEigen& e = parts.symmetric;
  // The symmetric part of (V/d) N^T has eigenvalues s1 >= 0 = s2 >= s3: subtract the middle.
  const double s1 = e.values[0] - e.values[1];
  const double s3 = e.values[2] - e.values[1];
  const double g = s1 - s3;  // |V/d| (N is a unit vector)
  const double scale = std::sqrt(2.0 * glm::dot(w, w) + s1 * s1 + s3 * s3);

  InverseFlowSolutions out;
  if (scale == 0.0 || g <= kInverseFlowTolerance * scale) {
    out.kind = InverseFlowCase::kPureRotation;
    PlanarMotionSolution s;
    s.normal_known = false;
    s.omega = w;
    out.solutions.push_back(s);
    return out;
  }
  // With unit u = V/|V| and N at angle phi: s1 = g (1 + cos phi)/2, s3 = -g (1 - cos phi)/2,
  // e1 is along u + N and e3 along u - N, so u = alpha e1 + beta e3 and N = alpha e1 - beta e3
  // with alpha = sqrt(s1/g), beta = sqrt(-s3/g); the sign of e3 is free, which swaps the roles
  // of u and N: the second solution.
  const double alpha = std::sqrt(s1 / g);
  const double beta = std::sqrt(-s3 / g);
  const Vec3 plus = alpha * e.vectors[0] + beta * e.vectors[2];
  const Vec3 minus = alpha * e.vectors[0] - beta * e.vectors[2];
  const bool one_solution = std::min(s1, -s3) <= kInverseFlowTolerance * g;
  out.kind = one_solution ? InverseFlowCase::kTranslationAlongNormal : InverseFlowCase::kGeneral;

  const Vec3 rho = ray_through(front_pixel, f);
  const std::pair<Vec3, Vec3> candidates[2] = {{plus, minus}, {minus, plus}};
  for (int i = 0; i < (one_solution ? 1 : 2); ++i) {
    PlanarMotionSolution s;
    if (!solution_in_front(g * candidates[i].first, glm::normalize(candidates[i].second), w, rho,
                           scale, s)) {
      out.edge_on += 1;
      continue;
    }
    out.solutions.push_back(s);
    out.dropped_behind += 1;
  }
  if (one_solution && !out.solutions.empty()) {
    const Vec3 n = out.solutions[0].normal;
    if (std::abs(n.x) <= kInverseFlowTolerance && std::abs(n.y) <= kInverseFlowTolerance) {
      out.kind = InverseFlowCase::kFrontoParallelAlongNormal;
    }
  }
  return out;
}

double relative_coefficient_difference(const PlanarFlowCoefficients& c,
                                       const PlanarFlowCoefficients& reference, double focal_px) {
  const double f = focal_px;
  const double a[8] = {c.tx / f, c.ty / f, c.j11, c.j12, c.j21, c.j22, f * c.px, f * c.py};
  const double b[8] = {reference.tx / f, reference.ty / f, reference.j11,    reference.j12,
                       reference.j21,    reference.j22,    f * reference.px, f * reference.py};
  double difference = 0.0, size = 0.0;
  for (int i = 0; i < 8; ++i) {
    difference = std::max(difference, std::abs(a[i] - b[i]));
    size = std::max(size, std::abs(b[i]));
  }
  return size == 0.0 ? difference : difference / size;
}

SolutionScene solution_scene(const PlanarMotionSolution& s, double focal_px,
                             const Vec2& centre_pixel, MotionModel model, double distance) {
  const Vec3 normal = s.normal_known ? s.normal : Vec3(0.0, 0.0, 1.0);
  const Vec3 rho = ray_through(centre_pixel, focal_px);
  SolutionScene scene;
  scene.pose.point = distance * rho / glm::dot(normal, rho);
  scene.pose.normal = normal;
  // Any up across the normal: of Y-up and X, the one further from the normal.
  scene.pose.up =
      std::abs(normal.y) < std::abs(normal.x) ? Vec3(0.0, -1.0, 0.0) : Vec3(1.0, 0.0, 0.0);
  scene.pose.size = Vec2(1.0, 1.0);
  const Vec3 v = distance * s.v_over_d;
  scene.motion.omega = s.omega;
  scene.motion.model = model;
  scene.motion.velocity =
      model == MotionModel::kSpinAboutCentre ? v + glm::cross(s.omega, scene.pose.point) : v;
  return scene;
}

FutureSeparation compare_futures(const PlanarMotionSolution& a, const PlanarMotionSolution& b,
                                 double focal_px, const Vec2& centre_pixel,
                                 const std::array<Vec2, 4>& corner_pixels, MotionModel model,
                                 double dt, int max_frames, double threshold_px) {
  struct World {
    SolutionScene scene;
    std::array<Vec3, 4> points;
  };
  World worlds[2];
  const PlanarMotionSolution* solutions[2] = {&a, &b};
  for (int w = 0; w < 2; ++w) {
    const Vec3 normal = solutions[w]->normal_known ? solutions[w]->normal : Vec3(0.0, 0.0, 1.0);
    if (!(glm::dot(normal, ray_through(centre_pixel, focal_px)) > 0.0)) {
      throw std::invalid_argument("the centre pixel does not see the solution's plane in front");
    }
    worlds[w].scene = solution_scene(*solutions[w], focal_px, centre_pixel, model);
    for (int i = 0; i < 4; ++i) {
      const Vec3 rho = ray_through(corner_pixels[i], focal_px);
      const double facing = glm::dot(normal, rho);
      if (!(facing > 0.0)) {
        throw std::invalid_argument("a corner pixel does not see the solution's plane in front");
      }
      worlds[w].points[i] = rho / facing;  // distance 1, as in solution_scene
    }
  }
  FutureSeparation out;
  const auto separation = [&]() {
    std::array<std::array<Vec2, 4>, 2> images;
    for (int w = 0; w < 2; ++w) {
      for (int i = 0; i < 4; ++i) {
        const Vec3& p = worlds[w].points[i];
        images[w][i] = focal_px * Vec2(p.x / p.z, p.y / p.z);
      }
    }
    out.corner_images_px.push_back(images);
    double worst = 0.0;
    for (int i = 0; i < 4; ++i) worst = std::max(worst, glm::length(images[0][i] - images[1][i]));
    return worst;
  };
  out.corner_distance_px.push_back(separation());
  for (int frame = 1; frame <= max_frames; ++frame) {
    bool visible = true;
    for (World& w : worlds) {
      const RigidStep step = rigid_step(w.scene.motion, w.scene.pose, dt);
      for (Vec3& p : w.points) {
        p = step.rotation * p + step.translation;
        visible = visible && p.z > 1e-6;
      }
      w.scene.pose = advance_pose(w.scene.pose, step);
    }
    if (!visible) break;
    out.frames_played = frame;
    out.corner_distance_px.push_back(separation());
    if (out.first_frame_apart < 0 && out.corner_distance_px.back() > threshold_px) {
      out.first_frame_apart = frame;
    }
  }
  return out;
}

}  // namespace oflab
