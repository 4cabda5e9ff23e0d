// From the eight planar flow coefficients back to the world: every plane and rigid motion
// that produce a given instantaneous planar flow (the inverse of planar_flow_coefficients;
// the decomposition of the continuous homography, manual/theory.md section 10).
//
// Frame and units as in core/flow/flow_field.h: the viewer frame (X right, Y down, Z
// forward), centred pixels, the caller's unit of time. A solution is a plane N.R = d with
// unit normal N and an unknown distance d > 0, and a motion (V, Omega) such that the
// flow matrix [Omega]x + (V/d) N^T reproduces the coefficients. Depth is known only up to
// the scale d: the image of a world scaled by k (positions and V times k) is the same, so
// a solution gives N, V/d and Omega, never d or V alone.
//
// The coefficients fix the flow matrix only up to a multiple of the identity (J11 and J22
// are the differences B11 - B33 and B22 - B33). That multiple is fixed because the
// symmetric part of (V/d) N^T, ((V/d) N^T + N (V/d)^T) / 2, always has a zero middle
// eigenvalue. Its other two eigenvalues and eigenvectors give V/d and N up to swapping their
// roles, which is the planar ambiguity: in general two different planes, moving
// differently, make exactly the same instantaneous flow.
#pragma once

#include <array>
#include <vector>

#include "flow/flow_field.h"

namespace oflab {

// Which of the named cases the coefficients fall in.
enum class InverseFlowCase {
  kGeneral,                    // V not parallel to N: two solutions
  kTranslationAlongNormal,     // V parallel (or opposite) to N: the two coincide, one solution
  kFrontoParallelAlongNormal,  // the same with N along the optical axis: a plane facing the
                               // eye squarely, moving straight towards or away from it
  kPureRotation,               // V = 0 (or no motion at all): Omega only; the plane is
                               // unobservable and any plane is a solution
};

// The case's name in output: "general", "translation-along-normal",
// "fronto-parallel-along-normal", "pure-rotation".
const char* inverse_flow_case_name(InverseFlowCase kind);

// Relative tolerance of the case tests: an eigenvalue of the flow matrix's symmetric part
// counts as zero when it is at most this times the scale of the flow matrix (its
// Frobenius norm with the identity multiple removed), and a normal counts as along the
// optical axis when |N1| and |N2| are at most this. Coefficients that are degenerate up to
// rounding are named; coefficients a little further off give two solutions very close to
// each other. Near these cases the solutions are sensitive: a relative change e of the
// coefficients moves N and V/d by about sqrt(e) (1e-8 for rounding errors), while each
// solution still maps forward to the coefficients to rounding.
// In angles: the two non-zero eigenvalues are |V/d| (1 + cos phi)/2 and -|V/d| (1 - cos phi)/2
// for the angle phi between V and N, so translation-along-normal is named while phi (or
// pi - phi) is at most kInverseFlowAngleTolerance = 2 sqrt(kInverseFlowTolerance) = 6.3e-5 rad
// (0.0036 deg); the one solution given then stands for two that differ by less than that.
constexpr double kInverseFlowTolerance = 1e-9;
constexpr double kInverseFlowAngleTolerance = 6.324555320336759e-5;  // 2 sqrt(1e-9), rad

// One plane and motion consistent with the coefficients.
struct PlanarMotionSolution {
  // Unit plane normal N, oriented so that d = N.R > 0 on the plane: it points from the eye
  // towards the plane, so the eye sees the side that -N points to. (0, 0, 0) for the pure
  // rotation case, whose plane is unobservable (normal_known is then false).
  Vec3 normal{0.0, 0.0, 0.0};
  bool normal_known = true;
  // V/d, per unit time (V in the viewer frame as in core/flow/motion.h: the velocity of the
  // body point at the eye). Zero for the pure rotation case.
  Vec3 v_over_d{0.0, 0.0, 0.0};
  // Omega, radians per unit time, about the eye.
  Vec3 omega{0.0, 0.0, 0.0};
  // Depth of the plane point seen at the check pixel (solve_inverse_flow's front_pixel), in
  // units of d: d / (N.rho), rho = (x/f, y/f, 1). Positive for every returned solution;
  // 0 when the normal is unknown.
  double depth_over_d = 0.0;
};

struct InverseFlowSolutions {
  InverseFlowCase kind = InverseFlowCase::kGeneral;
  // Two solutions in the general case, one otherwise (one fewer for each candidate seen
  // edge-on at the check pixel, see edge_on), each with its plane in front of the eye at the
  // check pixel. Their order carries no meaning.
  std::vector<PlanarMotionSolution> solutions;
  // Mirror candidates left out because their plane is behind the eye at the check pixel:
  // each solution's mirror image through the eye, (-N, -V/d, Omega), makes the same flow
  // matrix but lies behind the eye. One per solution: 2 in the general case, 1 with one
  // solution, 0 for a pure rotation or a candidate seen edge-on.
  int dropped_behind = 0;
  // Candidates left out because their plane is seen edge-on at the check pixel (N.rho = 0
  // to 1e-12: the line of sight through it is parallel to the plane, which is therefore
  // neither in front nor behind there, and neither is its mirror). They are true solutions
  // seen at other pixels. That happens, for instance, for a sideways translation of a plane
  // facing the eye (tx alone) at the principal point: the other solution's plane is
  // parallel to the optical axis; and for a spin about a plane point seen at the check
  // pixel: V is then across that line of sight, and so is the other solution's normal.
  int edge_on = 0;
};

// Every (N, V/d, Omega) whose flow, through planar_flow_coefficients, equals `c`, keeping
// only planes in front of the eye at the centred pixel `front_pixel` (the depth of the
// plane point seen there is positive). Use a pixel where the plane is seen, such as the
// expansion point of the coefficients or the image of the plane's centre.
// Units: c in centred pixels per unit time (any expansion point: c is re-expanded about the
// principal point first); focal_px in pixels; results per unit time.
// Preconditions: focal_px > 0 and finite, every coefficient finite (throws
// std::invalid_argument otherwise).
InverseFlowSolutions solve_inverse_flow(const PlanarFlowCoefficients& c, double focal_px,
                                        const Vec2& front_pixel = Vec2(0.0, 0.0));

// How far apart two sets of coefficients are, as one relative number: the largest
// difference of the eight, each in the units of the flow matrix (tx/f, ty/f, J, f px, f py,
// all per unit time), over the largest of `reference`'s eight in those units (the plain
// difference when `reference` is all zero). Both must be expanded about the same point;
// focal_px > 0.
double relative_coefficient_difference(const PlanarFlowCoefficients& c,
                                       const PlanarFlowCoefficients& reference, double focal_px);

// A pose and motion that realise `s` with the plane's distance d = `distance` (world
// units, > 0): the pose's point is the plane point seen at centred pixel `centre_pixel`, its
// normal s.normal ((0, 0, 1) when unknown), its up any direction across the normal, its size
// 1 x 1; the motion has the given model, with velocity V = distance * s.v_over_d for screw
// and rt, and V_c = V + Omega x P for centre (so that its instantaneous flow is the
// solution's). Preconditions: the plane is in front of the eye at centre_pixel
// (N.rho > 0), distance > 0.
struct SolutionScene {
  PlanePose pose;
  RigidMotion motion;
};
SolutionScene solution_scene(const PlanarMotionSolution& s, double focal_px,
                             const Vec2& centre_pixel, MotionModel model, double distance = 1.0);

// Two solutions played forward: the four image points `corner_pixels` (centred pixels at
// time 0, where the plane is seen) are put on each solution's plane, each plane moves
// frame by frame with its own motion (core's rigid_step and advance_pose, `model`,
// constant V and Omega in the viewer frame, time step dt per frame), and the frames'
// largest distance between the two images of the same corner is recorded.
struct FutureSeparation {
  // Largest corner distance in pixels at frames 0, 1, ..., frames_played (frame 0 is 0:
  // both start from the same image points).
  std::vector<double> corner_distance_px;
  // The corners' images at the same frames, centred pixels: [frame][solution a = 0, b = 1]
  // [corner, in the order of corner_pixels].
  std::vector<std::array<std::array<Vec2, 4>, 2>> corner_images_px;
  // The first frame whose distance exceeds the threshold; -1 when none did.
  int first_frame_apart = -1;
  // Frames played: max_frames, or fewer when a corner of either plane came within 1e-6 d
  // of the eye's plane Z = 0 or passed behind it (the image is then undefined).
  int frames_played = 0;
};
// Preconditions: both planes in front of the eye at centre_pixel and at every corner pixel
// (throws std::invalid_argument otherwise); dt > 0; max_frames >= 0; threshold_px >= 0.
// Time in the unit of the solutions' rates. A solution with an unknown normal (pure
// rotation) is played on the plane Z = d, which does not change its image.
FutureSeparation compare_futures(const PlanarMotionSolution& a, const PlanarMotionSolution& b,
                                 double focal_px, const Vec2& centre_pixel,
                                 const std::array<Vec2, 4>& corner_pixels, MotionModel model,
                                 double dt, int max_frames, double threshold_px);

}  // namespace oflab
