// The basis explorer (issue 31, manual/gui.md): the eight planar-basis terms a moving plane
// can make (tx, ty, scale, squash, shear, rotation, px, py: core/flow/basis.h
// PlanarBasisTerms without its four terms that vanish for any plane) dialled by hand, the
// deformation they make, and what core makes of them backwards: every plane and motion with
// that flow (core/flow/inverse_flow.h, manual/theory.md section 10), and the two solutions
// played forward for one second.
//
// Frame and units as core's: centred pixels (Y down) about the principal point, seconds.
// Plain C++ over core: no Qt, no VTK.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "flow/basis.h"
#include "flow/camera.h"
#include "flow/inverse_flow.h"
#include "flow/limits.h"

namespace oflab {

constexpr int kExplorerTermCount = 8;
// The eight values in the order of explorer_terms(), each in its term's unit.
using ExplorerTerms = std::array<double, kExplorerTermCount>;

// One dial of the explorer: the registry the sliders, the session file, the lesson claims
// and the manual read.
struct ExplorerTerm {
  const char* key;                   // field of the session file: "tx", "scale", ...
  const char* description;           // a few words: "uniform scaling (divergence / 2)"
  int order;                         // 0, 1 or 2; its unit is order_unit(order)
  double PlanarBasisTerms::*member;  // where the value goes in core's planar basis
  const Limit* limit;                // what a file or a typed value may hold
  double slider_span;                // the slider runs from -slider_span to +slider_span
  int decimals;                      // decimals shown
};

// The eight terms, in the gallery's order (basis_catalog.h planar_catalog). Each key is the
// symbol of its gallery tile.
const std::array<ExplorerTerm, kExplorerTermCount>& explorer_terms();
// Index of the term with this key, or -1.
int find_explorer_term(const std::string& key);

// The values the explorer starts with: a tilted plane coming closer while it turns, whose
// two solutions are both in front of the eye and part after about half a second.
ExplorerTerms default_explorer_terms();

// The planar-basis terms (the four non-planar ones zero) and the eight planar flow
// coefficients, expanded about the principal point, of the dialled values.
PlanarBasisTerms explorer_planar_basis(const ExplorerTerms& terms);
PlanarFlowCoefficients explorer_coefficients(const ExplorerTerms& terms);
// The dialled values of a flow's planar basis (the flow of a scene, for instance).
ExplorerTerms explorer_terms_of(const PlanarFlowCoefficients& coefficients);

// "" when every value is within its term's limit; otherwise one phrase naming the field as a
// session file spells it: "basis.terms.tx: translation rate 2e+04 is outside
// -10000..10000 px/s".
std::string explorer_terms_problem(const ExplorerTerms& terms);

// One sentence naming the case of `r` (two planes, a degenerate case, no motion), as the
// explorer's panel on every front-end shows it above the solutions.
std::string explorer_case_text(const InverseFlowSolutions& r);
// How far a solution's plane is turned from facing the eye squarely, in words: "faces it
// squarely" (under 0.5 degrees), "turned 62° away" (whole degrees), "unknown" (pure
// rotation). UTF-8.
std::string explorer_facing_text(const PlanarMotionSolution& s);

// A solution's sketch: its plane (a unit square at distance d = 1 across N, centred on the
// line of sight through the principal point) and its motion, seen from a fixed view above,
// behind and to the left of the eye (turned 0.9 rad about Y, then tilted 0.45 rad about X;
// orthographic; x right and y down as the viewer frame's), in world units (d = 1).
struct SolutionSketch {
  std::array<Vec2, 4> corners;  // the plane's corners, in plane_corners' order
  Vec2 centre;                  // the plane's centre
  Vec2 normal_tip;              // centre + 0.5 N
  Vec2 velocity_tip;            // centre + arrow V/d
  Vec2 spin_tip;                // eye + arrow Omega (the eye is at the view's origin)
};
// Where the fixed view puts the viewer-frame point p.
Vec2 explorer_view_of(const Vec3& p);
// The sketch of `s`, its arrows `arrow` times V/d and Omega long. Precondition: s.normal_known.
SolutionSketch explorer_sketch(const PlanarMotionSolution& s, double arrow);
// One arrow scale for all of `solutions`: the longest of their V/d and Omega is 0.8 units.
double explorer_arrow_scale(const std::vector<PlanarMotionSolution>& solutions);

// How the explorer plays the two solutions forward: 30 frames of 1/30 s (one second), each
// solution's plane moving with constant V and Omega in the viewer frame (core's screw
// model), apart when a corner's two images are more than 1 px apart.
constexpr double kFutureFrameSeconds = 1.0 / 30.0;
constexpr int kFutureFrames = 30;
constexpr double kFuturesApartPx = 1.0;
// The drawn deformation is where the flow carries each point in this time, s.
constexpr double kDeformationSeconds = 1.0;

// Everything the explorer shows for one set of values.
struct ExplorerResult {
  PlanarFlowCoefficients coefficients;  // about the principal point
  InverseFlowSolutions inverse;         // solved with the check pixel at the principal point
  // The texture rectangle's corners (the middle half of the image in each direction),
  // centred pixels: the points the futures follow and the deformation draws.
  std::array<Vec2, 4> corners;
  // The two solutions played forward (only with two solutions, both planes in front of the
  // eye at every corner); futures_note says why not otherwise.
  bool futures_played = false;
  FutureSeparation futures;
  std::string futures_note;
};

// Solves and plays the dialled values for `camera` (its focal length and image size).
// Precondition: a valid camera and values within their limits (explorer_terms_problem "").
ExplorerResult explore(const ExplorerTerms& terms, const Camera& camera);

// Where the flow, its rates held constant, carries each point in kDeformationSeconds: a
// homography of centred pixels (core's taylor_homography over 1/1024 of the time, composed
// 1024 times: within 0.1 % of the exact exp(t B) for rates below 1/s), normalised so that
// entry (3,3) is 1.
Mat3 explorer_deformation(const ExplorerTerms& terms);

// What the deformation does to the texture rectangle (explorer_deformation applied to its
// corners and centre).
struct GridChange {
  double shift_px = 0.0;  // how far the centre moves, px
  double area = 1.0;      // deformed area over the undeformed one
  double turn_deg = 0.0;  // the turn of the horizontal middle line, degrees, clockwise on screen
  // How much longer the longer of two opposite edges is than the other, as a fraction (0
  // for a parallelogram): the mark of the perspective terms.
  double keystone = 0.0;
};
GridChange explorer_grid_change(const ExplorerTerms& terms, const Camera& camera);

// The grid change's fields by name: "shift_px", "area", "turn_deg", "keystone"; false (and
// *value unchanged) for another name.
bool grid_change_field(const GridChange& change, const std::string& name, double* value);

}  // namespace oflab
