// Fixed-point form of the inverse warp map (see inverse_map.h for the definition and the
// exactness argument).
#include "image/inverse_map.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace oflab {
namespace {

// Largest |coefficient| accepted: coefficients and their per-pixel steps (twice the
// coefficient) must fit in int64.
constexpr double kMaxCoefficient = 4611686018427387904.0;  // 2^62

// Affine form: fractional bits of the fixed-point position. 2^-41 pixel resolution; at
// least 17 are needed for the 11-bit bilinear weights plus a margin.
constexpr int kAffineMaxShift = 41;
constexpr int kAffineMinShift = 17;
// Largest |Nu|, |Nv| allowed over the region in the affine form.
constexpr double kAffineMaxNumerator = 1152921504606846976.0;  // 2^60
// Largest |Nu|, |Nv| in the division form: sums of integers stay exact in double below
// 2^53; this leaves a factor 4 for rounding of the region.
constexpr double kDivisionMaxNumerator = 2251799813685248.0;  // 2^51
// Smallest D accepted over the region in the division form: below it the rounding of
// the coefficients (at most 2^15 in D) would move the sampling position noticeably.
constexpr double kDivisionMinDenominator = 1048576.0;  // 2^20

std::int64_t quantise(double value, double scale) {
  const double scaled = std::nearbyint(value * scale);
  if (!(std::abs(scaled) < kMaxCoefficient)) {
    throw std::invalid_argument(
        "warp: the inverse map has coefficients too large for exact fixed-point sampling "
        "(minification far beyond the supported range)");
  }
  return static_cast<std::int64_t>(scaled);
}

}  // namespace

InverseMap make_inverse_map(const Mat3& m, const ConvexPolygon& region, bool affine_form) {
  // Coefficients of the map in the doubled coordinates X = 2x, Y = 2y (see header).
  const double a = entry(m, 0, 0), b = entry(m, 0, 1), c = 2.0 * entry(m, 0, 2);
  const double d = entry(m, 1, 0), e = entry(m, 1, 1), f = 2.0 * entry(m, 1, 2);
  const double g = entry(m, 2, 0), h = entry(m, 2, 1), i = 2.0 * entry(m, 2, 2);

  double numerator_max = 0.0;
  double denominator_min = HUGE_VAL;
  double denominator_max = 0.0;
  for (const Vec2& p : region.vertices()) {
    const double X = 2.0 * p.x;
    const double Y = 2.0 * p.y;
    numerator_max =
        std::max({numerator_max, std::abs(a * X + b * Y + c), std::abs(d * X + e * Y + f)});
    const double D = g * X + h * Y + i;
    denominator_min = std::min(denominator_min, D);
    denominator_max = std::max(denominator_max, D);
  }
  numerator_max = std::max(numerator_max, 1.0);

  InverseMap map;
  if (affine_form) {
    if (g != 0.0 || h != 0.0 || entry(m, 2, 2) != 1.0) {
      throw std::invalid_argument("warp: the affine kernel needs a bottom row (0, 0, 1)");
    }
    // D = 2 * 2^s = 2^shift, numerators scale by 2^s = 2^(shift - 1). Wrapping
    // arithmetic makes a*X + b*Y + c exact whenever its true value fits, so only the
    // coefficients, their per-pixel steps 2a and 2d, and the numerators over the region
    // need bounds: with |2a| < 2^62 and |N| <= 2^60 stepping never overflows.
    const double linear_max = std::max({std::abs(a), std::abs(b), std::abs(d), std::abs(e)});
    const double constant_max = std::max(std::abs(c), std::abs(f));
    auto fits = [&](int shift) {
      return std::ldexp(numerator_max, shift - 1) <= kAffineMaxNumerator &&
             std::ldexp(linear_max, shift) < kMaxCoefficient &&
             std::ldexp(constant_max, shift - 1) < kMaxCoefficient;
    };
    int shift = kAffineMaxShift;
    while (shift > kAffineMinShift && !fits(shift)) --shift;
    if (!fits(shift)) {
      throw std::invalid_argument(
          "warp: minification beyond the supported range (about 2^40) for exact "
          "fixed-point sampling");
    }
    const double scale = std::ldexp(1.0, shift - 1);
    map.a = quantise(a, scale), map.b = quantise(b, scale), map.c = quantise(c, scale);
    map.d = quantise(d, scale), map.e = quantise(e, scale), map.f = quantise(f, scale);
    map.g = 0, map.h = 0, map.i = std::int64_t{1} << shift;
    map.affine_shift = shift;
    return map;
  }

  if (!(denominator_min > 0.0)) {
    throw std::invalid_argument(
        "warp: the homography's inverse has a non-positive denominator over the warped "
        "region (the region reaches the horizon line)");
  }
  // Largest power of two keeping D <= 2^37 and |N| <= 2^51 over the region.
  const double limit =
      std::min(kMaxDivisionDenominator / denominator_max, kDivisionMaxNumerator / numerator_max);
  const double scale = std::ldexp(1.0, std::ilogb(limit));
  if (!(denominator_min * scale >= kDivisionMinDenominator)) {
    throw std::invalid_argument(
        "warp: the denominator varies too much over the warped region for exact sampling "
        "(the region is too close to the horizon line)");
  }
  map.a = quantise(a, scale), map.b = quantise(b, scale), map.c = quantise(c, scale);
  map.d = quantise(d, scale), map.e = quantise(e, scale), map.f = quantise(f, scale);
  map.g = quantise(g, scale), map.h = quantise(h, scale), map.i = quantise(i, scale);
  map.affine_shift = -1;
  return map;
}

}  // namespace oflab
