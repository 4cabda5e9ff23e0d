// The mip level of each pixel along a row of a perspective warp. See mip_row_levels.h.
#include "image/mip_row_levels.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "image/bilinear_blend.h"  // OFLAB_WARP_SSE2
#include "image/warp_kernels.h"    // warp_avx2_enabled

#if defined(OFLAB_WARP_SSE2) && defined(__GNUC__)
#include <immintrin.h>
#define OFLAB_MIP_AVX2 1
#endif

namespace oflab {
namespace {

// Knots: the pixels t = 0, kKnotStep, 2 kKnotStep, ... and the last pixel of the segment.
constexpr int kKnotStep = kMipLevelKnotStep;

// Pixel t of the row segment (t = x - x_begin): P = p + t pb, R = r + t rb with
// pb = (beta1, beta0), rb = (-beta1, beta0), and D = d + t dd, all scaled by powers of two
// (D by s = 2^-k with d = D(x_begin) s in [1/2, 1), P and R by s^2): sigma(M) / D^2 is
// unchanged and exact in double.
struct RowTerms {
  double px = 0.0, py = 0.0, rx = 0.0, ry = 0.0;
  double beta0 = 0.0, beta1 = 0.0;
  double d = 1.0, dd = 0.0;
};

RowTerms row_terms(const Mat3& h, int y, int x_begin) {
  auto e = [&](int r, int c) { return entry(h, r, c); };
  const double px = x_begin + 0.5, py = y + 0.5;
  const double d = e(2, 0) * px + e(2, 1) * py + e(2, 2);
  const double nu = e(0, 0) * px + e(0, 1) * py + e(0, 2);
  const double nv = e(1, 0) * px + e(1, 1) * py + e(1, 2);
  const double m00 = e(0, 0) * d - nu * e(2, 0), m01 = e(0, 1) * d - nu * e(2, 1);
  const double m10 = e(1, 0) * d - nv * e(2, 0), m11 = e(1, 1) * d - nv * e(2, 1);
  int exponent = 0;
  std::frexp(d, &exponent);
  const double s = std::ldexp(1.0, -exponent), s2 = s * s;
  RowTerms terms;
  terms.px = (m00 + m11) * s2;
  terms.py = (m01 - m10) * s2;
  terms.rx = (m00 - m11) * s2;
  terms.ry = (m01 + m10) * s2;
  terms.beta0 = (e(0, 1) * e(2, 0) - e(0, 0) * e(2, 1)) * s2;  // d m01 / dx
  terms.beta1 = (e(1, 1) * e(2, 0) - e(1, 0) * e(2, 1)) * s2;  // d m11 / dx
  terms.d = d * s;
  terms.dd = e(2, 0) * s;
  return terms;
}

// Pixel t's index in double: round(256 clamp(log2(sigma / D^2), 0, top)).
std::uint16_t level_index(const RowTerms& c, double top, int t) {
  const double u = t * c.beta1, v = t * c.beta0;
  const double px = c.px + u, py = c.py + v, rx = c.rx - u, ry = c.ry + v;
  const double p = std::sqrt(px * px + py * py), r = std::sqrt(rx * rx + ry * ry);
  const double d = c.d + t * c.dd;
  const double level = std::log2(0.5 * (p + r) / (d * d));
  if (!(level > 0.0)) return 0;  // magnification, no scaling, or NaN
  return static_cast<std::uint16_t>(256.0 * std::min(level, top) + 0.5);
}

// True if the segment's terms are well conditioned for float: each of P's and R's terms
// (|p| + T |beta| per component, T = count - 1) at most 16 times the smallest |P| over the
// segment, and D's at most 8 times its smallest value. A float term t b + c is then within
// 3 * 2^-24 of its size, so sigma / D^2 is within about 1.5e-5 relative and the level within
// 2e-5 (1/200 of a weight step) with the float steps below.
bool float_conditioned(const RowTerms& c, int count) {
  const double last = count - 1;
  const double slope = std::abs(c.beta0) + std::abs(c.beta1);
  const double size =
      std::abs(c.px) + std::abs(c.py) + std::abs(c.rx) + std::abs(c.ry) + 2.0 * last * slope;
  const double b2 = c.beta0 * c.beta0 + c.beta1 * c.beta1;
  // The point of the segment P(t) = p + t (beta1, beta0) nearest the origin.
  const double nearest =
      b2 > 0.0 ? std::clamp(-(c.px * c.beta1 + c.py * c.beta0) / b2, 0.0, last) : 0.0;
  const double px = c.px + nearest * c.beta1, py = c.py + nearest * c.beta0;
  const double smallest_p = std::sqrt(px * px + py * py);
  const double smallest_d = std::min(c.d, c.d + last * c.dd);
  return smallest_p > 0.0 && size <= 16.0 * smallest_p && smallest_d > 0.0 &&
         std::abs(c.d) + last * std::abs(c.dd) <= 8.0 * smallest_d;
}

// The smallest |q + t v| over t in [0, last].
double smallest_norm(double qx, double qy, double vx, double vy, double last) {
  const double v2 = vx * vx + vy * vy;
  const double t = v2 > 0.0 ? std::clamp(-(qx * vx + qy * vy) / v2, 0.0, last) : 0.0;
  const double x = qx + t * vx, y = qy + t * vy;
  return std::sqrt(x * x + y * y);
}

// An upper bound, in levels, of how far the level L(t) = log2(f(t) / D(t)^2) + const
// (f = |P| + |R|) is from its linear interpolation between knots kKnotStep pixels apart or
// closer, over the segment's pixels 0 .. count - 1: (kKnotStep^2 / 8) max |L''|, with
// ln 2 |L''| <= f'' / f + (f' / f)^2 + 2 (D' / D)^2, |f'| <= 2 |beta|, f'' <= |beta|^2 (1 / |P|
// + 1 / |R|) (|P(t)|'' = (|beta|^2 - (P.beta)^2 / |P|^2) / |P|, the same for R), f >= |P| + |R|,
// each at its smallest over the segment. Infinity where P or R may vanish (f has a kink
// there).
double interpolation_error(const RowTerms& c, int count) {
  const double last = count - 1;
  const double b2 = c.beta0 * c.beta0 + c.beta1 * c.beta1;
  const double p = smallest_norm(c.px, c.py, c.beta1, c.beta0, last);
  const double r = smallest_norm(c.rx, c.ry, -c.beta1, c.beta0, last);
  const double d = std::min(c.d, c.d + last * c.dd);
  if (!(p > 0.0 && r > 0.0 && d > 0.0)) return std::numeric_limits<double>::infinity();
  const double f = p + r, slope = c.dd / d;
  const double second =
      (b2 * (1.0 / p + 1.0 / r) / f + 4.0 * b2 / (f * f) + 2.0 * slope * slope) / std::log(2.0);
  return kKnotStep * kKnotStep / 8.0 * second;
}

// The interpolated levels are used where interpolation_error is at most this (half a
// weight step): with the knots' own float error (2e-5 levels) each index is then within one
// step of the exact level's.
constexpr double kMaxInterpolationError = 0.5 / 256.0;

#if defined(OFLAB_MIP_AVX2)
// AVX2 with FMA: each t b + c, x x + y y and the series' steps one fused multiply-add (one
// rounding instead of two, and a shorter dependency chain: the pass takes about a fifth less).
#define OFLAB_MIP_TARGET __attribute__((target("avx2,fma")))

// 128 log2(x) + 1/2 for normal x > 0 (the rounded level index of x = sigma^2 / D^4 before
// truncation; x in [1, 2^30] clamped per pixel, in [2^-100, 2^100] at knots): x = m 2^e with m in
// [sqrt(1/2), sqrt(2)) (the exponent split at sqrt(1/2)'s bits), log2(m) = (2 / ln 2) atanh(z), z =
// (m - 1) / (m + 1) with |z| <= 0.1716 by its odd series to z^7 (tail below 5e-8), evaluated in two
// halves (a short dependency chain: the loop's iterations then overlap). Within 1e-6 of a level in
// float, plus the float rounding of the result (at most 2^-11 of a step for levels below 64 in
// size: 2e-6 of a level).
OFLAB_MIP_TARGET inline __m256 level_index_ps(__m256 x) {
  const __m256i offset = _mm256_set1_epi32(0x3f3504f3);  // sqrt(1/2)
  const __m256i shifted = _mm256_sub_epi32(_mm256_castps_si256(x), offset);
  const __m256 exponent = _mm256_cvtepi32_ps(_mm256_srai_epi32(shifted, 23));
  const __m256 m = _mm256_castsi256_ps(
      _mm256_add_epi32(_mm256_and_si256(shifted, _mm256_set1_epi32(0x7fffff)), offset));
  const __m256 one = _mm256_set1_ps(1.0f);
  const __m256 z = _mm256_div_ps(_mm256_sub_ps(m, one), _mm256_add_ps(m, one));
  const __m256 z2 = _mm256_mul_ps(z, z);
  const __m256 z4 = _mm256_mul_ps(z2, z2);
  // 1 + z^2 / 3 + z^4 (1 / 5 + z^2 / 7)
  const __m256 low = _mm256_fmadd_ps(z2, _mm256_set1_ps(1.0f / 3.0f), one);
  const __m256 high = _mm256_fmadd_ps(z2, _mm256_set1_ps(1.0f / 7.0f), _mm256_set1_ps(1.0f / 5.0f));
  const __m256 series = _mm256_fmadd_ps(z4, high, low);
  // 128 (e + (2 / ln 2) z series) + 1/2
  const __m256 whole = _mm256_fmadd_ps(exponent, _mm256_set1_ps(128.0f), _mm256_set1_ps(0.5f));
  const __m256 scaled_z = _mm256_mul_ps(z, _mm256_set1_ps(128.0f * 2.88539008f));
  return _mm256_fmadd_ps(scaled_z, series, whole);
}

// The row's terms in float for ratio_ps, P and R halved (so that S below is sigma^2).
struct FloatTerms {
  __m256 b0, b1, px, py, rx, ry, d, dd;
};

OFLAB_MIP_TARGET FloatTerms float_terms(const RowTerms& c) {
  return FloatTerms{_mm256_set1_ps(static_cast<float>(0.5 * c.beta0)),
                    _mm256_set1_ps(static_cast<float>(0.5 * c.beta1)),
                    _mm256_set1_ps(static_cast<float>(0.5 * c.px)),
                    _mm256_set1_ps(static_cast<float>(0.5 * c.py)),
                    _mm256_set1_ps(static_cast<float>(0.5 * c.rx)),
                    _mm256_set1_ps(static_cast<float>(0.5 * c.ry)),
                    _mm256_set1_ps(static_cast<float>(c.d)),
                    _mm256_set1_ps(static_cast<float>(c.dd))};
}

// sigma^2 / D^4 at the eight pixels t (offsets in the segment): with P and R halved, S =
// |P|^2 + |R|^2 + 2 |P| |R| = sigma^2 (one square root); half its log2 is the level.
OFLAB_MIP_TARGET inline __m256 ratio_ps(const FloatTerms& f, const __m256& t) {
  const __m256 px = _mm256_fmadd_ps(t, f.b1, f.px), py = _mm256_fmadd_ps(t, f.b0, f.py);
  const __m256 rx = _mm256_fnmadd_ps(t, f.b1, f.rx), ry = _mm256_fmadd_ps(t, f.b0, f.ry);
  const __m256 d = _mm256_fmadd_ps(t, f.dd, f.d);
  const __m256 p2 = _mm256_fmadd_ps(px, px, _mm256_mul_ps(py, py));
  const __m256 r2 = _mm256_fmadd_ps(rx, rx, _mm256_mul_ps(ry, ry));
  const __m256 cross = _mm256_sqrt_ps(_mm256_mul_ps(p2, r2));
  const __m256 s = _mm256_fmadd_ps(cross, _mm256_set1_ps(2.0f), _mm256_add_ps(p2, r2));
  const __m256 d2 = _mm256_mul_ps(d, d);
  return _mm256_div_ps(s, _mm256_mul_ps(d2, d2));
}

// Eight indices (int32 lanes) stored to out[0 .. n - 1] (n <= 8; a short block through a
// scratch block).
OFLAB_MIP_TARGET inline void store_indices(const __m256i& index, std::uint16_t* out, int n) {
  const __m256i packed = _mm256_permute4x64_epi64(_mm256_packus_epi32(index, index), 0x08);
  if (n >= 8) {
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out), _mm256_castsi256_si128(packed));
  } else {
    std::uint16_t last[8];
    _mm_storeu_si128(reinterpret_cast<__m128i*>(last), _mm256_castsi256_si128(packed));
    std::copy(last, last + n, out);
  }
}

// Pixels 0 .. count - 1 in float, eight a step. Precondition: float_conditioned(c, count).
OFLAB_MIP_TARGET void levels_avx2(const RowTerms& c, int top, int count, std::uint16_t* out) {
  const FloatTerms f = float_terms(c);
  const __m256 one = _mm256_set1_ps(1.0f);
  const __m256 most = _mm256_set1_ps(std::ldexp(1.0f, 2 * top));  // sigma^2 / D^4 at the top
  __m256 t = _mm256_setr_ps(0.0f, 1.0f, 2.0f, 3.0f, 4.0f, 5.0f, 6.0f, 7.0f);
  for (int k = 0; k < count; k += 8) {
    // sigma^2 / D^4 clamped to [1, 4^top] (a NaN to 1): half its log2 is the clamped level.
    const __m256 ratio = _mm256_min_ps(_mm256_max_ps(ratio_ps(f, t), one), most);
    t = _mm256_add_ps(t, _mm256_set1_ps(8.0f));
    store_indices(_mm256_cvttps_epi32(level_index_ps(ratio)), out + k, count - k);
  }
}

// The segment's knots' values 256 L + 1/2 (unclamped levels L, level_index_ps) into
// knots[0 .. (count - 1) / kKnotStep + 1], knot j at pixel min(kKnotStep j, count - 1).
// Returns false if a knot's sigma^2 / D^4 is outside [2^-100, 2^100] or not a number (the
// caller then takes every pixel).
OFLAB_MIP_TARGET bool knot_values(const RowTerms& c, int count, float* knots) {
  const FloatTerms f = float_terms(c);
  const int last = count - 1, knot_count = last / kKnotStep + 2;
  const __m256 lowest = _mm256_set1_ps(std::ldexp(1.0f, -100));
  const __m256 highest = _mm256_set1_ps(std::ldexp(1.0f, 100));
  const __m256 end = _mm256_set1_ps(static_cast<float>(last));
  __m256 t = _mm256_setr_ps(0.0f, 8.0f, 16.0f, 24.0f, 32.0f, 40.0f, 48.0f, 56.0f);
  int bad = 0;
  for (int j = 0; j < knot_count; j += 8) {
    const __m256 ratio = ratio_ps(f, _mm256_min_ps(t, end));
    t = _mm256_add_ps(t, _mm256_set1_ps(8.0f * kKnotStep));
    // Ordered comparisons: a NaN fails both.
    bad |= ~_mm256_movemask_ps(_mm256_and_ps(_mm256_cmp_ps(ratio, lowest, _CMP_GE_OQ),
                                             _mm256_cmp_ps(ratio, highest, _CMP_LE_OQ))) &
           0xff;
    _mm256_storeu_ps(knots + j, level_index_ps(ratio));
  }
  return bad == 0;
}

// Eight pixels' values from knot j on: knots[j] + (knots[j + 1] - knots[j]) i / kKnotStep
// (i = 0 .. 7), clamped to [low, high] and truncated.
OFLAB_MIP_TARGET inline __m256i interpolated_indices(const float* knots, const __m256& eighths,
                                                     const __m256& low, const __m256& high) {
  const __m256 base = _mm256_broadcast_ss(knots), next = _mm256_broadcast_ss(knots + 1);
  const __m256 value = _mm256_fmadd_ps(_mm256_sub_ps(next, base), eighths, base);
  return _mm256_cvttps_epi32(_mm256_min_ps(_mm256_max_ps(value, low), high));
}

// Pixels 0 .. count - 1 from the knots (knot_values): between knots j and j + 1 the values
// linearly interpolated, clamped to [1/2, 256 top + 1/2] and truncated; two intervals of
// kKnotStep pixels a step.
OFLAB_MIP_TARGET void interpolate_levels(const float* knots, int top, int count,
                                         std::uint16_t* out) {
  static_assert(kKnotStep == 8, "one interval per vector");
  const __m256 eighths = _mm256_setr_ps(0.0f, 0.125f, 0.25f, 0.375f, 0.5f, 0.625f, 0.75f, 0.875f);
  const __m256 low = _mm256_set1_ps(0.5f);
  const __m256 high = _mm256_set1_ps(256.0f * static_cast<float>(top) + 0.5f);
  const int last = count - 1;
  int j = 0;
  for (; kKnotStep * (j + 2) <= last; j += 2) {  // knots j + 1 and j + 2 a whole step on
    const __m256i first = interpolated_indices(knots + j, eighths, low, high);
    const __m256i second = interpolated_indices(knots + j + 1, eighths, low, high);
    const __m256i packed = _mm256_permute4x64_epi64(_mm256_packus_epi32(first, second), 0xd8);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(out + kKnotStep * j), packed);
  }
  const __m256 steps = _mm256_setr_ps(0.0f, 1.0f, 2.0f, 3.0f, 4.0f, 5.0f, 6.0f, 7.0f);
  for (; kKnotStep * j <= last; ++j) {
    const int first = kKnotStep * j;
    const int span = std::min(kKnotStep, last - first);  // pixels to knot j + 1 (0 at the end)
    const float slope = span == kKnotStep ? (knots[j + 1] - knots[j]) * (1.0f / kKnotStep)
                        : span > 0        ? (knots[j + 1] - knots[j]) / static_cast<float>(span)
                                          : 0.0f;
    const __m256 value = _mm256_fmadd_ps(_mm256_set1_ps(slope), steps, _mm256_set1_ps(knots[j]));
    const __m256 clamped = _mm256_min_ps(_mm256_max_ps(value, low), high);
    store_indices(_mm256_cvttps_epi32(clamped), out + first, std::min(kKnotStep, count - first));
  }
}
#endif

}  // namespace

void mip_row_levels_scalar(const Mat3& dest_to_source, int top, int y, int x_begin, int x_end,
                           std::uint16_t* out) {
  const RowTerms terms = row_terms(dest_to_source, y, x_begin);
  for (int t = 0; t < x_end - x_begin; ++t) out[t] = level_index(terms, top, t);
}

void mip_row_levels(const Mat3& dest_to_source, int top, int y, int x_begin, int x_end,
                    std::uint16_t* out) {
  const RowTerms terms = row_terms(dest_to_source, y, x_begin);
#if defined(OFLAB_MIP_AVX2)
  static const bool has_fma = __builtin_cpu_supports("fma");  // every AVX2 CPU we know of
  const int count = x_end - x_begin;
  if (warp_avx2_enabled() && has_fma && float_conditioned(terms, count)) {
    if (count >= 2 * kKnotStep && interpolation_error(terms, count) <= kMaxInterpolationError) {
      thread_local std::vector<float> knots;
      knots.resize(static_cast<std::size_t>((count - 1) / kKnotStep + 2 + 7));
      if (knot_values(terms, count, knots.data())) {
        interpolate_levels(knots.data(), top, count, out);
        return;
      }
    }
    levels_avx2(terms, top, count, out);
    return;
  }
#endif
  for (int t = 0; t < x_end - x_begin; ++t) out[t] = level_index(terms, top, t);
}

}  // namespace oflab
