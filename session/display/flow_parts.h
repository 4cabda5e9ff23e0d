// The instantaneous flow of the current scene, split into the parts the flow view can
// show (dissertation section 4.4; manual/flow-math.md section 2). Plain C++ over core:
// every value comes from core's planar_flow_coefficients, taylor_terms, taylor_flow_at,
// flow_at and exact_flow_at; nothing here re-derives the flow.
//
// Units: positions are centred pixels (Y down), flows pixels per second.
#pragma once

#include <string>
#include <vector>

#include "flow/basis.h"
#include "flow/flow_field.h"

namespace oflab {

enum class FlowPart {
  kFull,                  // the exact flow: projection of the 3D velocity (exact_flow_at)
  kTranslation,           // zeroth order: (tx, ty)
  kFirstOrder,            // the affine (Jacobian) terms alone
  kSecondOrder,           // the perspective terms alone: (px x + py y) (x, y)
  kExactMinusHomography,  // exact flow - flow of the Taylor homography (= the quadratic flow)
  kExactMinusAffine,      // exact flow - (translation + first order)
};
constexpr int kFlowPartCount = 6;

const char* flow_part_title(FlowPart part);  // for menus and captions, e.g. "Second order"
// Command-line key: "full", "translation", "first-order", "second-order",
// "exact-minus-homography", "exact-minus-affine".
const char* flow_part_key(FlowPart part);
// Parses a key; false (and *part unchanged) for anything else.
bool parse_flow_part(const std::string& key, FlowPart* part);

// Everything needed to evaluate the flow of one pose: the scene plus its coefficients
// about the principal point and their Taylor terms.
struct FlowContext {
  Camera camera;
  PlanePose pose;
  RigidMotion motion;
  PlanarFlowCoefficients coefficients;
  TaylorTerms terms;
};
// Preconditions: a valid camera and pose (plane_scene_problem is empty).
FlowContext make_flow_context(const Camera& camera, const PlanePose& pose,
                              const RigidMotion& motion);

// True when the ray through centred pixel p meets the plane rectangle in front of the eye,
// i.e. p lies in the plane's image and exact_flow_at is defined there.
bool sees_plane(const FlowContext& context, const Vec2& p);

// The chosen part of the flow at centred pixel p (pixels per second). The Full and the
// residual parts need sees_plane(context, p).
Vec2 flow_part_at(const FlowContext& context, FlowPart part, const Vec2& p);

struct FlowSample {
  Vec2 position;  // centred pixels
  Vec2 flow;      // pixels per second
};

// The part sampled on a grid of pixel centres `spacing_px` apart covering the image,
// keeping only the points inside the plane's image. Precondition: spacing_px >= 1.
std::vector<FlowSample> sample_flow_grid(const FlowContext& context, FlowPart part,
                                         double spacing_px);

// A streamline of the part's instantaneous field from `seed`: classical Runge-Kutta with
// `steps` steps over `duration_s` seconds. It stops early where it leaves the plane's image.
// Returns the visited centred positions, the seed first.
std::vector<Vec2> trace_streamline(const FlowContext& context, FlowPart part, const Vec2& seed,
                                   double duration_s, int steps);

// The arrow head that shows a streamline's direction: three points (one wing, the tip,
// the other wing) with the tip at the path's last point and the wings `length_px` back
// along its last step, 25 degrees either side. Empty when the path has fewer than two
// distinct points (no direction to show).
std::vector<Vec2> streamline_arrow_head(const std::vector<Vec2>& path, double length_px);

// Largest flow magnitude among the samples (0 for none).
double max_flow_magnitude(const std::vector<FlowSample>& samples);

}  // namespace oflab
