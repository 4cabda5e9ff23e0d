// Scene shifting: the slice calculus of dissertation eq. 9 (asymptote corrected to
// k|V|/epsilon), the layer transformations of eq. 5 and 6, and the per-frame update
// decision through the planar flow of fronto-parallel planes (core/flow/flow_field.h).
#include "scene_shifting/scene_shifting.h"

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "flow/flow_field.h"

namespace oflab {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// A boundary whose image speed is within this relative amount of epsilon counts as being on
// the asymptote; without it, rounding in u0 - n eps could leave a speed of 1e-16 eps and a
// last finite slice 1e16 times deeper than the asymptote.
constexpr double kAsymptoteTolerance = 1e-9;

// A turn below this many radians per frame is numerical noise, not a change of direction.
constexpr double kTurnTolerance = 1e-12;

// Every check of slice_parameters_problem except the slice count.
SliceProblem basic_problem(const SliceParameters& p) {
  if (!std::isfinite(p.speed) || p.speed < 0.0) {
    return {"speed", "viewer speed |V| must be a finite number >= 0 (world units per frame)"};
  }
  if (!std::isfinite(p.focal_px) || p.focal_px <= 0.0) {
    return {"focal_px", "focal length must be a positive number of pixels"};
  }
  if (!std::isfinite(p.epsilon_px) || p.epsilon_px <= 0.0) {
    return {"epsilon_px", "tolerance epsilon must be a positive number of pixels per frame"};
  }
  if (!std::isfinite(p.near) || p.near <= 0.0) {
    return {"near", "near depth must be a positive number of world units"};
  }
  if (p.max_slices < 1) return {"max_slices", "the slice cap must be at least 1"};
  return {};
}

void require_usable(const SliceParameters& p) {
  const SliceProblem problem = basic_problem(p);
  if (!problem.field.empty()) {
    throw std::invalid_argument("scene slices: " + problem.field + ": " + problem.message);
  }
}

// Image speed u = k|V|/z of boundary i: u0 - i epsilon (exact in the image-speed domain,
// so no error accumulates along the sequence).
double boundary_speed(const SliceParameters& p, double index) {
  return sideways_image_speed(p, p.near) - index * p.epsilon_px;
}

bool at_or_beyond_asymptote(const SliceParameters& p, double speed) {
  return speed <= p.epsilon_px * (1.0 + kAsymptoteTolerance);
}

// Number of finite slices as a double (may exceed any int, or be +infinity when k|V|/near
// overflows).
double finite_slice_count(const SliceParameters& p) {
  const double u0 = sideways_image_speed(p, p.near);
  if (at_or_beyond_asymptote(p, u0)) return 0.0;
  double n = std::ceil((u0 - p.epsilon_px * (1.0 + kAsymptoteTolerance)) / p.epsilon_px);
  // Far beyond any cap (and beyond exact integers in a double): no need to settle rounding.
  if (!(n < 1e12)) return n;
  // Settle rounding in the division with the same test scene_slices uses.
  while (n > 1.0 && at_or_beyond_asymptote(p, boundary_speed(p, n - 1.0))) n -= 1.0;
  while (!at_or_beyond_asymptote(p, boundary_speed(p, n))) n += 1.0;
  return n;
}

std::string count_message(const SliceParameters& p, double count) {
  std::ostringstream s;
  s << "the slicing needs ";
  if (count < 1e15) {
    s << static_cast<long long>(count);
  } else {
    s << "more than 1e15";
  }
  s << " slices from near depth " << p.near << ", more than the cap of " << p.max_slices
    << "; use a larger epsilon or near depth";
  return s.str();
}

// Flow coefficients of the plane Z = 1 parallel to the image plane. For a plane Z = z the
// translation part scales with 1/z and the rotation part does not depend on z, since
// B = [Omega]x + V (0, 0, 1/z)^T; planar_flow_coefficients is linear in B.
PlanarFlowCoefficients unit_depth_flow(const Camera& camera, const Vec3& velocity,
                                       const Vec3& omega) {
  PlanePose pose;
  pose.point = Vec3(0.0, 0.0, 1.0);
  pose.normal = Vec3(0.0, 0.0, 1.0);
  RigidMotion motion;
  motion.velocity = velocity;
  motion.omega = omega;
  return planar_flow_coefficients(camera, pose, motion);
}

PlanarFlowCoefficients combine(const PlanarFlowCoefficients& rot,
                               const PlanarFlowCoefficients& trans, double inv_depth) {
  PlanarFlowCoefficients c;
  c.tx = rot.tx + inv_depth * trans.tx;
  c.ty = rot.ty + inv_depth * trans.ty;
  c.j11 = rot.j11 + inv_depth * trans.j11;
  c.j12 = rot.j12 + inv_depth * trans.j12;
  c.j21 = rot.j21 + inv_depth * trans.j21;
  c.j22 = rot.j22 + inv_depth * trans.j22;
  c.px = rot.px + inv_depth * trans.px;
  c.py = rot.py + inv_depth * trans.py;
  return c;
}

// The corners of the camera's image rectangle in centred pixels.
std::array<Vec2, 4> image_corners(const Camera& camera) {
  const double x0 = -camera.cx, x1 = camera.width - camera.cx;
  const double y0 = -camera.cy, y1 = camera.height - camera.cy;
  return {Vec2(x0, y0), Vec2(x1, y0), Vec2(x1, y1), Vec2(x0, y1)};
}

// Upper bound over the image rectangle of |flow(c, p) - (shift + rate p)|: the affine part
// is exact at the corners (a convex norm of an affine map), the quadratic part is bounded by
// max|px x + py y| max|p|, both also reached at corners.
double residual_bound(const PlanarFlowCoefficients& c, const Vec2& shift, double rate,
                      const std::array<Vec2, 4>& corners) {
  double affine = 0.0, linear = 0.0, radius = 0.0;
  for (const Vec2& p : corners) {
    const Vec2 r(c.tx - shift.x + (c.j11 - rate) * p.x + c.j12 * p.y,
                 c.ty - shift.y + c.j21 * p.x + (c.j22 - rate) * p.y);
    affine = std::max(affine, glm::length(r));
    linear = std::max(linear, std::abs(c.px * p.x + c.py * p.y));
    radius = std::max(radius, glm::length(p));
  }
  return affine + linear * radius;
}

}  // namespace

SliceProblem slice_parameters_problem(const SliceParameters& params) {
  SliceProblem problem = basic_problem(params);
  if (!problem.field.empty()) return problem;
  const double count = finite_slice_count(params) + 1.0;
  if (count > params.max_slices) return {"max_slices", count_message(params, count)};
  return {};
}

bool is_background(const Slice& slice) { return std::isinf(slice.far); }

double sideways_image_speed(const SliceParameters& params, double z) {
  if (std::isinf(z)) return 0.0;
  return params.focal_px * params.speed / z;
}

double slice_asymptote(const SliceParameters& params) {
  require_usable(params);
  return params.focal_px * params.speed / params.epsilon_px;
}

double max_slice_width(const SliceParameters& params, double z) {
  require_usable(params);
  if (!(z > 0.0)) throw std::invalid_argument("max_slice_width: depth must be positive");
  const double denominator = params.focal_px * params.speed - params.epsilon_px * z;
  if (denominator <= 0.0) return kInfinity;
  return params.epsilon_px * z * z / denominator;
}

int slice_count(const SliceParameters& params) {
  require_usable(params);
  const double count = finite_slice_count(params) + 1.0;
  return count >= static_cast<double>(INT_MAX) ? INT_MAX : static_cast<int>(count);
}

std::vector<Slice> scene_slices(const SliceParameters& params) {
  const SliceProblem problem = slice_parameters_problem(params);
  if (!problem.field.empty()) {
    throw std::invalid_argument("scene slices: " + problem.field + ": " + problem.message);
  }
  const double s = params.focal_px * params.speed;
  std::vector<Slice> slices;
  double near = params.near;
  for (int i = 0;; ++i) {
    if (at_or_beyond_asymptote(params, boundary_speed(params, i))) {
      slices.push_back({near, kInfinity});
      return slices;
    }
    // Far edge: where its image speed is exactly epsilon below the near edge's.
    const double far = s / boundary_speed(params, i + 1.0);
    slices.push_back({near, far});
    near = far;
  }
}

int slice_index_at_depth(const std::vector<Slice>& slices, double z) {
  for (size_t i = 0; i < slices.size(); ++i) {
    if (z >= slices[i].near && z < slices[i].far) return static_cast<int>(i);
  }
  return -1;
}

double representative_depth(const Slice& slice) {
  if (is_background(slice)) return 2.0 * slice.near;
  return 2.0 * slice.near * slice.far / (slice.near + slice.far);
}

Vec2 apply_slice_transform(const SliceTransform& t, const Vec2& p) {
  return t.scale * p + t.translation;
}

Mat3 slice_transform_matrix(const SliceTransform& t) {
  return mat3_from_rows({t.scale, 0.0, t.translation.x}, {0.0, t.scale, t.translation.y},
                        {0.0, 0.0, 1.0});
}

SliceTransform slice_transform(const Camera& camera, const Slice& slice, const Vec3& translation) {
  const double z = representative_depth(slice);
  const double remaining = z - translation.z;
  if (!(remaining > 0.0)) {
    throw std::invalid_argument("slice_transform: the viewer step reaches the layer's depth");
  }
  SliceTransform t;
  t.scale = z / remaining;
  t.translation = -camera.focal_px * Vec2(translation.x, translation.y) / remaining;
  return t;
}

double slice_transform_error(const Camera& camera, const Slice& slice, const Vec3& translation) {
  if (!(slice.near - translation.z > 0.0)) {
    throw std::invalid_argument("slice_transform_error: the viewer step reaches the slice");
  }
  const SliceTransform t = slice_transform(camera, slice, translation);
  const Vec2 shift = camera.focal_px * Vec2(translation.x, translation.y);
  double worst = 0.0;
  for (const Vec2& p : image_corners(camera)) {
    const Vec2 shown = apply_slice_transform(t, p);
    for (const double z : {slice.near, slice.far}) {
      const Vec2 truth = std::isinf(z) ? p : (z * p - shift) / (z - translation.z);
      worst = std::max(worst, glm::length(truth - shown));
    }
  }
  return worst;
}

bool turns_view_direction(const ViewerStep& step) {
  return std::hypot(step.rotation.x, step.rotation.y) > kTurnTolerance;
}

double shift_scale_residual(const Camera& camera, const Slice& slice, const ViewerStep& step) {
  // The scene moves against the viewer.
  const PlanarFlowCoefficients rot = unit_depth_flow(camera, Vec3(0.0), -step.rotation);
  const PlanarFlowCoefficients trans = unit_depth_flow(camera, -step.translation, Vec3(0.0));
  const PlanarFlowCoefficients model = combine(rot, trans, 1.0 / representative_depth(slice));
  const Vec2 shift(model.tx, model.ty);
  const double rate = 0.5 * (model.j11 + model.j22);
  const std::array<Vec2, 4> corners = image_corners(camera);
  // Every coefficient is affine in 1/Z, so the worst depth is an edge (1/far = 0 for the
  // background).
  double worst = 0.0;
  for (const double inv_depth : {1.0 / slice.near, is_background(slice) ? 0.0 : 1.0 / slice.far}) {
    worst = std::max(worst, residual_bound(combine(rot, trans, inv_depth), shift, rate, corners));
  }
  return worst;
}

std::vector<SliceDecision> decide_slice_updates(const Camera& camera,
                                                const std::vector<Slice>& slices,
                                                const ViewerStep& step,
                                                const std::vector<double>& accumulated_error_px,
                                                double epsilon_px) {
  if (*camera_problem(camera)) {
    throw std::invalid_argument(std::string("decide_slice_updates: ") + camera_problem(camera));
  }
  if (!std::isfinite(epsilon_px) || epsilon_px <= 0.0) {
    throw std::invalid_argument(
        "decide_slice_updates: epsilon must be a positive number of pixels");
  }
  if (!accumulated_error_px.empty() && accumulated_error_px.size() != slices.size()) {
    throw std::invalid_argument(
        "decide_slice_updates: need one accumulated error per slice (or none)");
  }
  const bool turned = turns_view_direction(step);
  std::vector<SliceDecision> decisions(slices.size());
  for (size_t i = 0; i < slices.size(); ++i) {
    const double before = accumulated_error_px.empty() ? 0.0 : accumulated_error_px[i];
    if (!std::isfinite(before) || before < 0.0) {
      throw std::invalid_argument(
          "decide_slice_updates: accumulated errors must be finite and >= 0");
    }
    SliceDecision& d = decisions[i];
    d.residual_px = shift_scale_residual(camera, slices[i], step);
    d.view_direction_turned = turned;
    const bool rebuild = turned || before + d.residual_px > epsilon_px;
    d.action = rebuild ? SliceAction::kRebuild : SliceAction::kShift;
    d.accumulated_error_px = rebuild ? 0.0 : before + d.residual_px;
  }
  return decisions;
}

}  // namespace oflab
