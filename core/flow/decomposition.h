// Decompositions of a homography W (dissertation eq. 20 and eq. 55, corrected as in
// manual/theory.md#errata, items 18, 19, 26, 27; manual/flow-math.md section 5).
//
// W is first normalised to W33 = 1 and written [[a,b,c],[d,e,f],[g,h,1]]; A is its
// Jacobian at the source origin, A = [[a - c g, b - c h], [d - f g, e - f h]].
#pragma once

#include <string>
#include <vector>

#include "flow/geometry.h"

namespace oflab {

// Eq. 20: W = translation * linear * perspective, exactly, with
// translation = T(c, f), linear = diag(A, 1), perspective = [[1,0,0],[0,1,0],[g,h,1]].
struct TranslateLinearPerspective {
  Mat3 translation{1.0};
  Mat3 linear{1.0};
  Mat3 perspective{1.0};
};
// Precondition: W33 != 0 (the source origin is not sent to infinity); throws
// std::invalid_argument otherwise or when W has a non-finite entry.
TranslateLinearPerspective decompose_translate_linear_perspective(const Mat3& w);

// The Jacobian A of the normalised W at the source origin (same precondition).
glm::dmat2 origin_jacobian(const Mat3& w);

// The affine map that agrees with homography h to first order at point p: h(p) and h's
// Jacobian there, with a bottom row of exactly (0, 0, 1). Precondition: p is not on h's
// horizon (h's denominator at p is not 0).
Mat3 affine_part_at(const Mat3& h, const Vec2& p);

// The largest singular value of m's upper-left 2 x 2 block: the most an affine m stretches
// a length, in any direction (the sampling limit's measure of magnification).
double largest_singular_value(const Mat3& m);

// How much of W's scaling the cached perspective step takes (section 5.4.3):
// W_persp = [[D,0,0],[0,D,0],[g,h,1]] scales lengths by D at the source origin.
enum class DeltaPolicy {
  kOne,               // D = 1: the cache stays at texture resolution
  kAbsDet,            // D = |det A|: the cache is over-shrunk (area |det A|^2)
  kSqrtAbsDet,        // D = sqrt|det A|: all scaling in the cache, W_aff area-preserving
  kFourthRootAbsDet,  // D = |det A|^(1/4): area scaling split evenly
  kDissertation,      // D = sqrt|det A| when |det A| < 1, else 1 (never magnify the cache)
};

// The one vocabulary of Delta policies, in the order of the enum: delta_policy_name gives
// "1", "det", "sqrt", "fourth-root" or "dissertation" (the words of options, session and
// script files and JSON); parse_delta_policy accepts those (and "one" for "1") and returns
// false, leaving *policy unchanged, for anything else; delta_policy_name_list joins the
// names with `separator`: "1, det, sqrt, fourth-root, dissertation" for error messages,
// "1|det|sqrt|fourth-root|dissertation" for usage lines.
bool parse_delta_policy(const std::string& text, DeltaPolicy* policy);
const char* delta_policy_name(DeltaPolicy policy);
std::string delta_policy_name_list(const std::string& separator = ", ");
// Every policy, in the order of the enum (and of delta_policy_name_list).
const std::vector<DeltaPolicy>& delta_policies();

// D for a given |det A|; returns 1 when det A is 0 or not finite.
double delta_for(DeltaPolicy policy, double det_a);

// Corrected eq. 55: W = affine * perspective exactly, with the translation inside the
// affine part: perspective = [[D,0,0],[0,D,0],[g,h,1]],
// affine = [[A11/D, A12/D, c],[A21/D, A22/D, f],[0,0,1]].
struct AffinePerspectiveSplit {
  Mat3 affine{1.0};
  Mat3 perspective{1.0};
  double delta = 1.0;
};
// Same precondition as decompose_translate_linear_perspective.
AffinePerspectiveSplit split_affine_perspective(const Mat3& w, DeltaPolicy policy);

}  // namespace oflab
