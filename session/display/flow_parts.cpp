#include "display/flow_parts.h"

#include <cmath>

namespace oflab {
namespace {

// Translation plus first order: the flow an affine warp reproduces.
TaylorTerms affine_terms(const TaylorTerms& t) {
  TaylorTerms only = taylor_order_terms(t, 1);
  only.v1 = t.v1;
  only.v2 = t.v2;
  return only;
}

}  // namespace

const char* flow_part_title(FlowPart part) {
  switch (part) {
    case FlowPart::kFull:
      return "Full (exact) flow";
    case FlowPart::kTranslation:
      return "Translation";
    case FlowPart::kFirstOrder:
      return "First order (affine)";
    case FlowPart::kSecondOrder:
      return "Second order (perspective)";
    case FlowPart::kExactMinusHomography:
      return "Exact - homography flow";
    case FlowPart::kExactMinusAffine:
      return "Exact - affine flow";
  }
  return "?";
}

const char* flow_part_key(FlowPart part) {
  switch (part) {
    case FlowPart::kFull:
      return "full";
    case FlowPart::kTranslation:
      return "translation";
    case FlowPart::kFirstOrder:
      return "first-order";
    case FlowPart::kSecondOrder:
      return "second-order";
    case FlowPart::kExactMinusHomography:
      return "exact-minus-homography";
    case FlowPart::kExactMinusAffine:
      return "exact-minus-affine";
  }
  return "?";
}

bool parse_flow_part(const std::string& key, FlowPart* part) {
  for (int k = 0; k < kFlowPartCount; ++k) {
    if (key == flow_part_key(static_cast<FlowPart>(k))) {
      *part = static_cast<FlowPart>(k);
      return true;
    }
  }
  return false;
}

FlowContext make_flow_context(const Camera& camera, const PlanePose& pose,
                              const RigidMotion& motion) {
  FlowContext context{camera, pose, motion, {}, {}};
  context.coefficients = planar_flow_coefficients(camera, pose, motion);
  context.terms = taylor_terms(context.coefficients);
  return context;
}

bool sees_plane(const FlowContext& context, const Vec2& p) {
  const Vec3 ray(p.x / context.camera.focal_px, p.y / context.camera.focal_px, 1.0);
  if (!(glm::dot(plane_vector(context.pose), ray) > 0.0)) return false;
  const Vec3 offset =
      plane_point_at_pixel(context.pose, context.camera.focal_px, p) - context.pose.point;
  const PlaneAxes axes = plane_axes(context.pose);
  return std::abs(glm::dot(offset, axes.right)) <= 0.5 * context.pose.size.x &&
         std::abs(glm::dot(offset, axes.up)) <= 0.5 * context.pose.size.y;
}

Vec2 flow_part_at(const FlowContext& context, FlowPart part, const Vec2& p) {
  switch (part) {
    case FlowPart::kFull:
      return exact_flow_at(context.camera, context.pose, context.motion, p);
    case FlowPart::kTranslation:
      return taylor_flow_at(taylor_order_terms(context.terms, 0), p);
    case FlowPart::kFirstOrder:
      return taylor_flow_at(taylor_order_terms(context.terms, 1), p);
    case FlowPart::kSecondOrder:
      return taylor_flow_at(taylor_order_terms(context.terms, 2), p);
    case FlowPart::kExactMinusHomography:
      // The Taylor homography's flow d/dt H1(t) p at t = 0 is the quadratic flow_at
      // (core/flow/homography.h); for a plane the difference is rounding only.
      return exact_flow_at(context.camera, context.pose, context.motion, p) -
             flow_at(context.coefficients, p);
    case FlowPart::kExactMinusAffine:
      return exact_flow_at(context.camera, context.pose, context.motion, p) -
             taylor_flow_at(affine_terms(context.terms), p);
  }
  return Vec2(0.0);
}

std::vector<FlowSample> sample_flow_grid(const FlowContext& context, FlowPart part,
                                         double spacing_px) {
  std::vector<FlowSample> samples;
  const double half_w = 0.5 * context.camera.width, half_h = 0.5 * context.camera.height;
  for (double y = -half_h + 0.5 * spacing_px; y < half_h; y += spacing_px) {
    for (double x = -half_w + 0.5 * spacing_px; x < half_w; x += spacing_px) {
      const Vec2 p(x, y);
      if (sees_plane(context, p)) samples.push_back({p, flow_part_at(context, part, p)});
    }
  }
  return samples;
}

std::vector<Vec2> trace_streamline(const FlowContext& context, FlowPart part, const Vec2& seed,
                                   double duration_s, int steps) {
  std::vector<Vec2> path{seed};
  if (!sees_plane(context, seed) || steps < 1) return path;
  const double h = duration_s / steps;
  auto field = [&](const Vec2& p) { return flow_part_at(context, part, p); };
  Vec2 p = seed;
  for (int i = 0; i < steps; ++i) {
    const Vec2 k1 = field(p);
    const Vec2 mid1 = p + 0.5 * h * k1;
    if (!sees_plane(context, mid1)) break;
    const Vec2 k2 = field(mid1);
    const Vec2 mid2 = p + 0.5 * h * k2;
    if (!sees_plane(context, mid2)) break;
    const Vec2 k3 = field(mid2);
    const Vec2 end = p + h * k3;
    if (!sees_plane(context, end)) break;
    const Vec2 k4 = field(end);
    p += (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    if (!sees_plane(context, p)) break;
    path.push_back(p);
  }
  return path;
}

std::vector<Vec2> streamline_arrow_head(const std::vector<Vec2>& path, double length_px) {
  if (path.size() < 2) return {};
  const Vec2 tip = path.back();
  const Vec2 step = tip - path[path.size() - 2];
  const double step_length = glm::length(step);
  if (!(step_length > 0.0)) return {};
  const Vec2 back = -step / step_length * length_px;
  const double c = std::cos(0.4363323129985824), s = std::sin(0.4363323129985824);  // 25 deg
  const Vec2 left(c * back.x - s * back.y, s * back.x + c * back.y);
  const Vec2 right(c * back.x + s * back.y, -s * back.x + c * back.y);
  return {tip + left, tip, tip + right};
}

double max_flow_magnitude(const std::vector<FlowSample>& samples) {
  double largest = 0.0;
  for (const FlowSample& s : samples) largest = std::max(largest, glm::length(s.flow));
  return largest;
}

}  // namespace oflab
