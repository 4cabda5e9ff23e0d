// Scene shifting (Hofmann's layers; dissertation chapter 3, eq. 5, 6 and 9, with the
// asymptote of eq. 9 corrected, see manual/scene-shifting.md).
//
// The scene is cut into slices [near, far] of depth Z (along the viewing direction), each
// drawn into its own image layer. When the viewer moves sideways the image of a point at
// depth Z moves k|V|/Z pixels per frame, so one layer can be shifted as a whole as long as
// its near and far edges move by image speeds that differ by at most epsilon:
//   k|V|/Z - k|V|/(Z + W) <= epsilon  <=>  W <= epsilon Z^2 / (k|V| - epsilon Z)   (eq. 9)
// for Z below the asymptote Z_inf = k|V|/epsilon (the dissertation prints epsilon/(k|V|)).
// Beyond Z_inf every point moves less than epsilon per frame: one infinitely deep slice.
//
// Units: depths and viewer steps in world units, speeds in world units per frame, focal
// length k in pixels, epsilon and image errors in pixels (per frame where stated). Image
// positions are centred pixels (x right, y down, origin at the principal point, see
// core/flow/camera.h); the viewer frame is X right, Y down, Z forward.
#pragma once

#include <string>
#include <vector>

#include "flow/camera.h"
#include "flow/geometry.h"

namespace oflab {

// Largest number of slices scene_slices returns before it reports an error.
constexpr int kDefaultMaxSlices = 10000;

// The inputs of the slice calculus.
struct SliceParameters {
  double speed = 0.0;                  // |V|, world units per frame (>= 0), viewer moving sideways
  double focal_px = 0.0;               // k, pixels (> 0)
  double epsilon_px = 0.0;             // tolerance, pixels per frame (> 0)
  double near = 1.0;                   // depth of the nearest slice's near edge, world units (> 0)
  int max_slices = kDefaultMaxSlices;  // cap on the slice count, background included (>= 1)
};

// What is wrong with the parameters, naming the field ("speed", "focal_px", "epsilon_px",
// "near", "max_slices"); field is empty when they are usable. "max_slices" is also the
// field when the slicing would need more slices than the cap allows. Checks: finite values,
// speed >= 0, focal_px, epsilon_px, near > 0, max_slices >= 1, slice_count <= max_slices.
struct SliceProblem {
  std::string field;
  std::string message;
};
SliceProblem slice_parameters_problem(const SliceParameters& params);

// A slice [near, far) of depths; far is +infinity for the background slice.
struct Slice {
  double near = 0.0;
  double far = 0.0;
};

bool is_background(const Slice& slice);

// Image speed, pixels per frame, of a point at depth z for a viewer moving sideways:
// k|V|/z (eq. 5); 0 when z is +infinity. Precondition: z > 0.
double sideways_image_speed(const SliceParameters& params, double z);

// The asymptote Z_inf = k|V|/epsilon, world units: points beyond it move less than epsilon
// pixels per frame. 0 when the viewer stands still. Throws std::invalid_argument when the
// parameters are unusable (slice_parameters_problem, the slice-count check excepted).
double slice_asymptote(const SliceParameters& params);

// The widest slice starting at depth z (eq. 9, corrected): epsilon z^2 / (k|V| - epsilon z)
// for z below the asymptote, +infinity at or beyond it. At that width the image speeds of
// the two edges differ by exactly epsilon. Throws std::invalid_argument as slice_asymptote,
// or when z is not positive.
double max_slice_width(const SliceParameters& params, double z);

// Number of slices scene_slices returns, background included, without building them.
// Closed form: the far edge of each maximal slice moves exactly epsilon slower than its
// near edge, so the edge speeds run u0, u0 - eps, u0 - 2 eps, ... (u0 = k|V|/near): the
// sequence passes the asymptote after finitely many steps, ceil(u0/eps - 1) finite slices.
// Throws std::invalid_argument as slice_asymptote. Saturates at INT_MAX.
int slice_count(const SliceParameters& params);

// The slices from params.near outward, each maximal (its far edge is where the image speeds
// of its edges differ by exactly epsilon), the last one the background [Z_last, +inf) with
// Z_last the first boundary at or beyond the asymptote (within a relative 1e-9, so rounding
// never yields an absurdly deep last finite slice). When near is already at or beyond the
// asymptote, or the speed is zero, the result is the single slice [near, +inf).
// Throws std::invalid_argument for unusable parameters, including a count above
// params.max_slices (the message gives the count and suggests a larger epsilon or near).
std::vector<Slice> scene_slices(const SliceParameters& params);

// Index of the slice containing depth z (near <= z < far), or -1 when z < slices[0].near
// or the list is empty.
int slice_index_at_depth(const std::vector<Slice>& slices, double z);

// The depth a slice's layer is drawn and moved as: the harmonic mean of its edges,
// 2 near far / (near + far), and 2 near for the background. Image displacements go as 1/Z,
// so the layer then moves by the mean of its near and far edges' displacements and the
// error is split evenly: at most half the spread, epsilon/2 per frame at the design speed.
double representative_depth(const Slice& slice);

// A motion of the viewer over one frame, in the viewer frame at the start of the frame:
// translation in world units, rotation as an axis-angle vector in radians (positive Y turns
// the view towards +X). The scene moves relative to the viewer with velocity -translation
// and angular velocity -rotation.
struct ViewerStep {
  Vec3 translation{0.0, 0.0, 0.0};
  Vec3 rotation{0.0, 0.0, 0.0};
};

// The image transformation of a layer: centred pixel p -> scale p + translation
// (a uniform scaling about the principal point, then a shift).
struct SliceTransform {
  double scale = 1.0;
  Vec2 translation{0.0, 0.0};
};

Vec2 apply_slice_transform(const SliceTransform& t, const Vec2& p);

// The same map as a 3x3 homography on centred pixels.
Mat3 slice_transform_matrix(const SliceTransform& t);

// The exact finite transformation of a layer at depth Z = representative_depth(slice) for a
// viewer translation d = (dX, dY, dZ): a point (X, Y, Z) seen at p = k (X, Y)/Z is seen at
// k (X - dX, Y - dY)/(Z - dZ) = (Z p - k (dX, dY)) / (Z - dZ). Sideways (dZ = 0) this is a
// shift by -k (dX, dY)/Z (eq. 5: the image moves against the viewer); forward (dX = dY = 0)
// a scaling by Z/(Z - dZ) about the principal point (eq. 6).
// Throws std::invalid_argument when dZ >= Z (the viewer would reach the layer).
SliceTransform slice_transform(const Camera& camera, const Slice& slice, const Vec3& translation);

// Largest image distance, pixels, between where slice_transform puts the points of the
// slice and where they really go after the viewer translation, over every depth of the
// slice and every point of the camera's image rectangle. Exact: for a fixed depth the
// difference is affine in p (largest at a corner) and for a fixed p the true position runs
// along a segment as Z goes from near to far (largest at an edge).
// Throws std::invalid_argument when dZ >= slice.near.
double slice_transform_error(const Camera& camera, const Slice& slice, const Vec3& translation);

// True when the step turns the viewing direction (a rotation about the viewer's X or Y
// axis larger than 1e-12 radians). The slices are cut along the viewing direction, so after
// such a step they are no longer parallel to the image plane and every layer must be
// rebuilt, whatever its depth (dissertation section 3.6.1).
bool turns_view_direction(const ViewerStep& step);

// How far, pixels per frame, the optic flow of a slice departs from the shift and scaling
// of its representative depth, over the camera's image rectangle and the slice's depths.
// Each depth Z is a plane parallel to the image plane; its flow comes from
// planar_flow_coefficients with V = -translation, Omega = -rotation (per frame):
//   v = (tx, ty) + J (x, y) + (px x + py y)(x, y).
// The model is the shift (tx, ty) and the scaling rate (J11 + J22)/2 at the representative
// depth. A viewer translation leaves only the depth spread (zero for px, py and the off-
// diagonal J); a rotation adds px, py (turning) and an antisymmetric J (rolling) that no
// shift or scaling can follow. Upper bound: exact for translations; for rotations the
// quadratic part is bounded by max|px x + py y| max|(x, y)| over the rectangle.
double shift_scale_residual(const Camera& camera, const Slice& slice, const ViewerStep& step);

enum class SliceAction { kShift, kRebuild };

struct SliceDecision {
  SliceAction action = SliceAction::kShift;
  double residual_px = 0.0;            // shift_scale_residual of this step
  double accumulated_error_px = 0.0;   // after this frame: 0 when rebuilt, else before + residual
  bool view_direction_turned = false;  // the rebuild is forced by turns_view_direction
};

// For each slice, whether its layer can be shifted/scaled for this step or must be rebuilt
// (rendered again). A layer's displayed error grows by its residual every frame it is only
// shifted (by the triangle inequality the sum bounds the error; for steady sideways motion
// it is exact), so it is rebuilt when accumulated + residual would exceed epsilon_px, and
// always when the step turns the viewing direction. accumulated_error_px holds one value
// per slice (pixels, from the previous frame's decisions) or is empty for freshly built
// layers. Throws std::invalid_argument for a size mismatch, epsilon_px <= 0, or a camera
// that camera_problem rejects.
std::vector<SliceDecision> decide_slice_updates(const Camera& camera,
                                                const std::vector<Slice>& slices,
                                                const ViewerStep& step,
                                                const std::vector<double>& accumulated_error_px,
                                                double epsilon_px);

}  // namespace oflab
