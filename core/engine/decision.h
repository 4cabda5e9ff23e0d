// The decision procedure of Algorithm 1 (dissertation sections 5.4.5 and 5.6.1), corrected
// as documented in manual/animation.md ("The decision rule") and manual/theory.md#errata,
// items 22-25.
//
// Terms. The frame-to-frame image motion of a plane splits into four terms:
//   0 translation, 1 first order (affine), 2 second order (perspective px, py), and
//   3 higher order (what the first-order Taylor homography H1 misses over one frame).
// Levels. Each update level handles the terms below it and neglects the rest:
//   none neglects 0-3; translate neglects 1-3; affine neglects 2-3; perspective
//   neglects 3; re-render neglects nothing.
// Every measure is in pixels of the output image: the largest displacement, over the
// corners of the displayed polygon, that a term causes in one frame.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "flow/camera.h"
#include "flow/flow_field.h"
#include "flow/motion.h"
#include "flow/plane.h"

namespace oflab {

enum class Level { kNone = 0, kTranslate = 1, kAffine = 2, kPerspective = 3, kRerender = 4 };
constexpr int kLevelCount = 5;
constexpr int kTermCount = 4;

// The one vocabulary of levels. level_name is the identifier written in files and JSON
// ("none", "translate", "affine", "perspective", "rerender"); level_title is the word for
// tables, charts and prose (the same, except "re-render"). parse_level accepts the names
// only and returns false, leaving *level unchanged, for anything else.
const char* level_name(Level level);
const char* level_title(Level level);
bool parse_level(const std::string& text, Level* level);

// A set of levels, indexed by static_cast<int>(Level).
using LevelSet = std::array<bool, kLevelCount>;
constexpr LevelSet kAllLevels{true, true, true, true, true};

using TermArray = std::array<double, kTermCount>;

// Per-frame flow measures (pixels per frame) of the four terms, from the planar flow
// coefficients re-expanded about `expansion_point` (centred pixels), evaluated at the
// displayed polygon's corners (centred pixels):
//   flow_0 = |(tx, ty)|,  flow_1 = max |J d|,  flow_2 = max |(px dx + py dy) d|,
//   flow_3 = max |acc/2 - (px dx + py dy) v|   (the H1 residual over one frame),
// with d = corner - expansion_point, v the flow and acc the image acceleration at the corner.
// Precondition: valid camera and pose; corners not empty.
struct FlowMeasures {
  TermArray flow{};
  Vec2 expansion_point{0.0};
  double size = 0.0;  // largest |d| over the corners, pixels
};
FlowMeasures measure_flow(const Camera& camera, const PlanePose& pose, const RigidMotion& motion,
                          const std::vector<Vec2>& corners_centred);

// The flow measures of section 5.4.5 and Algorithm 1 as printed, with only the fixes
// without which they cannot be computed (errata 22-24, manual/policies.md): absolute values,
// and a_i taken as the derivative parts J_ij (a1 - 1, a2, a3, a4 - 1). The coefficients are
// those of eq. 51 at the principal point (not re-expanded), t is one frame, and
//   size   = max(width, height) of the axis-aligned bounding box of the corners, pixels;
//   flow_0 = max(|tx|, |ty|);
//   flow_1 = max(|J11|, |J12|, |J21|, |J22|) size;
//   flow_2 = max(|px|, |py|) size^2 t;
//   flow_3 = |Omega|^2 size^2 t   (Omega in radians per frame; its units are not pixels).
// Preconditions as measure_flow (valid camera and pose; corners centred pixels, not empty).
TermArray measure_printed_flow(const Camera& camera, const PlanePose& pose,
                               const RigidMotion& motion, const std::vector<Vec2>& corners_centred);

// Algorithm 1's cascade as printed: each term tested against its own threshold, the highest
// term k with accumulated[k] + flow[k] > thresholds[k] picks level k + 1 (3: re-render,
// 2: perspective, 1: affine, 0: translate); none when no term exceeds its threshold.
Level printed_cascade(const TermArray& accumulated, const TermArray& flow,
                      const TermArray& thresholds);

// Chooses the update level from the accumulated errors and this frame's flow. A level is
// acceptable when the sum, over the terms it neglects, of (accumulated + flow) stays within
// that level's threshold; the lowest acceptable level wins and re-render is always
// acceptable. thresholds[L] belongs to level L+1's lower neighbour: thresholds[0] is the
// budget of "none", [1] of "translate", [2] of "affine", [3] of "perspective".
// Levels missing from `allowed` are never chosen (the affine policy leaves out
// perspective); re-render is chosen when no allowed level is acceptable, allowed or not.
Level choose_level(const TermArray& accumulated, const TermArray& flow, const TermArray& thresholds,
                   const LevelSet& allowed);
// The same, with a second test: level L (none..perspective) is acceptable only when
// pending[L], the exact error it would leave (pixels), also stays within thresholds[L].
Level choose_level(const TermArray& accumulated, const TermArray& flow, const TermArray& thresholds,
                   const LevelSet& allowed, const TermArray& pending);

// The error a level leaves pending: the sum of (accumulated + flow) over its neglected terms.
double neglected_error(const TermArray& accumulated, const TermArray& flow, Level level);

}  // namespace oflab
