// The inverse warp map in exact integer form: the single definition of "where does output
// pixel (x, y) sample the source", shared by the fast kernels (which step through it
// incrementally) and by the per-pixel reference in the tests (which evaluates it
// directly). Because every quantity is an integer, stepping and direct evaluation give
// bit-identical results, and nearest sampling has no rounding ties to break.
//
// Definition. Let X = 2x + 1 and Y = 2y + 1 (twice the centre of output pixel (x, y),
// see core/image/image.h). With the integer coefficients below,
//     Nu = a*X + b*Y + c,   Nv = d*X + e*Y + f,   D = g*X + h*Y + i,
// the sampling position is (Nu / D, Nv / D) in source pixel-index space: the source
// point M^-1(x + 0.5, y + 0.5) for nearest sampling, and that point minus (0.5, 0.5) for
// bilinear sampling (so that integers are source pixel centres). The coefficients are
// the entries of the exact inverse matrix scaled by a power of two and rounded to
// integers; the position error this causes is below 1e-6 pixel for every supported
// matrix (checked in warp_test).
//  - nearest: source pixel (floor(Nu / D), floor(Nv / D)), each clamped to the image;
//    the kernels reproduce this exactly;
//  - bilinear: taps floor(.) and floor(.) + 1 (clamped), weights from the fractions; the
//    kernels' bilinear loops step a 16.16 fixed-point copy of the position, within
//    2^-12 pixel of it (core/image/warp_kernels.cpp).
#pragma once

#include <cstdint>

#include "flow/geometry.h"
#include "image/polygon.h"

namespace oflab {

struct InverseMap {
  std::int64_t a = 0, b = 0, c = 0;
  std::int64_t d = 0, e = 0, f = 0;
  std::int64_t g = 0, h = 0, i = 1;
  // >= 0 for the affine form: g = h = 0 and D = i = 2^affine_shift, so floor(N / D) is
  // N >> affine_shift. -1 for the division form used by the perspective kernel.
  int affine_shift = -1;
};

// The three integers (Nu, Nv, D) at output pixel (x, y), computed exactly (wrapping
// 64-bit arithmetic whose true result is known to fit).
struct MapSample {
  std::int64_t nu = 0;
  std::int64_t nv = 0;
  std::int64_t d = 1;
};

inline MapSample evaluate(const InverseMap& m, int x, int y) {
  const std::uint64_t X = static_cast<std::uint64_t>(2 * static_cast<std::int64_t>(x) + 1);
  const std::uint64_t Y = static_cast<std::uint64_t>(2 * static_cast<std::int64_t>(y) + 1);
  auto lin = [&](std::int64_t p, std::int64_t q, std::int64_t r) {
    return static_cast<std::int64_t>(static_cast<std::uint64_t>(p) * X +
                                     static_cast<std::uint64_t>(q) * Y +
                                     static_cast<std::uint64_t>(r));
  };
  return MapSample{lin(m.a, m.b, m.c), lin(m.d, m.e, m.f), lin(m.g, m.h, m.i)};
}

// floor(n / d) for d > 0, exact.
inline std::int64_t floor_div(std::int64_t n, std::int64_t d) {
  std::int64_t q = n / d;
  if ((n % d != 0) && (n < 0)) --q;
  return q;
}

// Largest denominator D the division form allows: for |floor| < 2^15 (source images up
// to kMaxImageDimension pixels) and 0 < D < 2^39, the correctly rounded double quotient
// double(Nu) / double(D) has the same floor as the exact quotient (a quotient can only
// round up onto an integer k if k*D - Nu < k*D*2^-53, i.e. D > 2^39 / 2). Kept at 2^37
// over the warped region to leave a margin for rounding of the region itself.
constexpr double kMaxDivisionDenominator = 137438953472.0;  // 2^37

// Builds the integer map for `dest_to_sample` (output pixel coordinates -> sampling
// position, already including the output offset and, for bilinear, the -0.5 shift),
// sized for the pixels of `region` (the part of the output that will be sampled, in
// output pixel coordinates). `affine_form` selects the shift form; it requires a bottom
// row (0, 0, 1). Throws std::invalid_argument if the map cannot be represented exactly
// over the region (a minification beyond about 2^40, or a denominator that is not
// positive over the region).
InverseMap make_inverse_map(const Mat3& dest_to_sample, const ConvexPolygon& region,
                            bool affine_form);

}  // namespace oflab
