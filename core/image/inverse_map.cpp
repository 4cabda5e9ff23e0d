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

// The map's coefficients in the doubled coordinates X = 2x, Y = 2y (see header), and the
// extremes of its numerators and denominator over the region's vertices.
struct DoubledMap {
  double a, b, c, d, e, f, g, h, i;
  double numerator_max;  // largest |Nu|, |Nv|, at least 1
  double denominator_min;
  double denominator_max;
};

DoubledMap doubled_map(const Mat3& m, const ConvexPolygon& region) {
  DoubledMap k;
  k.a = entry(m, 0, 0), k.b = entry(m, 0, 1), k.c = 2.0 * entry(m, 0, 2);
  k.d = entry(m, 1, 0), k.e = entry(m, 1, 1), k.f = 2.0 * entry(m, 1, 2);
  k.g = entry(m, 2, 0), k.h = entry(m, 2, 1), k.i = 2.0 * entry(m, 2, 2);
  k.numerator_max = 0.0;
  k.denominator_min = HUGE_VAL;
  k.denominator_max = 0.0;
  for (const Vec2& p : region.vertices()) {
    const double X = 2.0 * p.x;
    const double Y = 2.0 * p.y;
    k.numerator_max = std::max(
        {k.numerator_max, std::abs(k.a * X + k.b * Y + k.c), std::abs(k.d * X + k.e * Y + k.f)});
    const double D = k.g * X + k.h * Y + k.i;
    k.denominator_min = std::min(k.denominator_min, D);
    k.denominator_max = std::max(k.denominator_max, D);
  }
  k.numerator_max = std::max(k.numerator_max, 1.0);
  return k;
}

// The shift form of the affine kernels. Precondition: the bottom row of the map is (0, 0, 1).
InverseMap shift_form(const DoubledMap& k) {
  // D = 2 * 2^s = 2^shift, numerators scale by 2^s = 2^(shift - 1). Wrapping
  // arithmetic makes a*X + b*Y + c exact whenever its true value fits, so only the
  // coefficients, their per-pixel steps 2a and 2d, and the numerators over the region
  // need bounds: with |2a| < 2^62 and |N| <= 2^60 stepping never overflows.
  const double linear_max = std::max({std::abs(k.a), std::abs(k.b), std::abs(k.d), std::abs(k.e)});
  const double constant_max = std::max(std::abs(k.c), std::abs(k.f));
  auto fits = [&](int shift) {
    return std::ldexp(k.numerator_max, shift - 1) <= kAffineMaxNumerator &&
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
  InverseMap map;
  map.a = quantise(k.a, scale), map.b = quantise(k.b, scale), map.c = quantise(k.c, scale);
  map.d = quantise(k.d, scale), map.e = quantise(k.e, scale), map.f = quantise(k.f, scale);
  map.g = 0, map.h = 0, map.i = std::int64_t{1} << shift;
  map.affine_shift = shift;
  return map;
}

// The division form, for the perspective kernel.
InverseMap division_form(const DoubledMap& k) {
  if (!(k.denominator_min > 0.0)) {
    throw std::invalid_argument(
        "warp: the homography's inverse has a non-positive denominator over the warped "
        "region (the region reaches the horizon line)");
  }
  // Largest power of two keeping D <= 2^37 and |N| <= 2^51 over the region.
  const double limit = std::min(kMaxDivisionDenominator / k.denominator_max,
                                kDivisionMaxNumerator / k.numerator_max);
  const double scale = std::ldexp(1.0, std::ilogb(limit));
  if (!(k.denominator_min * scale >= kDivisionMinDenominator)) {
    throw std::invalid_argument(
        "warp: the denominator varies too much over the warped region for exact sampling "
        "(the region is too close to the horizon line)");
  }
  InverseMap map;
  map.a = quantise(k.a, scale), map.b = quantise(k.b, scale), map.c = quantise(k.c, scale);
  map.d = quantise(k.d, scale), map.e = quantise(k.e, scale), map.f = quantise(k.f, scale);
  map.g = quantise(k.g, scale), map.h = quantise(k.h, scale), map.i = quantise(k.i, scale);
  map.affine_shift = -1;
  return map;
}
}  // namespace

InverseMap make_inverse_map(const Mat3& m, const ConvexPolygon& region, bool affine_form) {
  const DoubledMap k = doubled_map(m, region);
  if (!affine_form) return division_form(k);
  if (k.g != 0.0 || k.h != 0.0 || entry(m, 2, 2) != 1.0) {
    throw std::invalid_argument("warp: the affine kernel needs a bottom row (0, 0, 1)");
  }
  return shift_form(k);
}

}  // namespace oflab
