// The pieces of the warp kernels' row loops that the whole-polygon kernels
// (warp_kernels.cpp) and the trilinear row (trilinear_row.cpp) share: the source as the loops
// read it, the test that a sample's taps stay inside the source (the "fast range" of
// warp_kernels.h's pass 1), and the AVX2 steps of the perspective bilinear loops (positions of
// four pixels from one packed division, their 2 x 2 blends). Internal to core/image: one copy
// of each piece, so that the trilinear row's level-k samples are the bilinear kernel's bytes.
// Positions are in source pixels (inverse_map.h); "16.16" positions carry kBlendWeightBits
// fraction bits in int32 lanes.
#pragma once

#include <cstdint>
#include <cstdlib>

#include "image/bilinear_blend.h"  // kBlendWeightBits, and OFLAB_WARP_SSE2 with <emmintrin.h>
#include "image/image.h"
#include "image/inverse_map.h"

#if defined(OFLAB_WARP_SSE2) && defined(__GNUC__)
// The AVX2 loops are compiled for AVX2 with a function attribute (OFLAB_AVX2) and chosen at
// run time (use_avx2), so the build still runs on any x86-64.
#define OFLAB_WARP_AVX2 1
#define OFLAB_AVX2 __attribute__((target("avx2")))
#include <immintrin.h>
#endif

namespace oflab {
namespace warp_row {

// A source image as the row loops read it: pixel (x, y) (integer pixel indices, x to the
// right, y down) at pixels + y * stride + x. at() does not check its arguments: callers
// clamp them or prove them inside [0, max_x] x [0, max_y] (in_fast_range).
struct SourceView {
  const Pixel* pixels;
  std::int64_t stride;
  std::int64_t max_x;  // width - 1
  std::int64_t max_y;  // height - 1
  const Pixel* at(std::int64_t x, std::int64_t y) const { return pixels + y * stride + x; }
};

// The view of `image` (not empty; it must outlive the view).
inline SourceView source_view(const Image& image) {
  return SourceView{image.pixels().data(), image.width(), image.width() - 1, image.height() - 1};
}

// Bilinear fast loops do not use the exact floor: the perspective one may round it up by
// one, the affine one steps in 16.16 fixed point and may be off by one either way. The
// fast range keeps this margin on both sides, plus one column (row) for the second tap.
constexpr std::int64_t kBilinearLowMargin = 1;
constexpr std::int64_t kBilinearHighMargin = 2;

// Largest denominator for which in_fast_range compares by multiplication: (max + 1) * D
// then stays below 2^63 for images up to kMaxImageDimension (2^14) pixels across. The maps
// have D <= 2^41 (affine form) or about 2^37 (division form); larger D takes the slow path.
constexpr std::int64_t kMaxCompareDenominator = std::int64_t{1} << 48;

// True if the sample may take the fast path (no tap needs clamping: with kBilinear, the
// taps of the bilinear loops' positions, margins included). For D > 0,
// floor(N / D) >= low  <=>  N >= low * D  and  floor(N / D) <= top  <=>  N < (top + 1) * D,
// so no division is needed (this runs twice per row).
template <bool kBilinear>
bool in_fast_range(const SourceView& src, const MapSample& s) {
  if (s.d <= 0 || s.d >= kMaxCompareDenominator) return false;
  const std::int64_t low = (kBilinear ? kBilinearLowMargin : 0) * s.d;
  const std::int64_t high = kBilinear ? kBilinearHighMargin : 0;
  return s.nu >= low && s.nv >= low && s.nu < (src.max_x - high + 1) * s.d &&
         s.nv < (src.max_y - high + 1) * s.d;
}

// Largest step that double can hold exactly together with the running sums.
constexpr std::int64_t kMaxExactStep = std::int64_t{1} << 51;

// True if the map's steps along a row (the integer coefficients a, d, g of its numerators
// and denominator, inverse_map.h) are below kMaxExactStep in magnitude, so that the
// perspective loops may step them in double and stay exact; false sends the row's pixels
// to the clamped per-pixel path.
inline bool steps_exact_in_double(const InverseMap& m) {
  for (std::int64_t c : {m.a, m.d, m.g}) {
    if (c >= kMaxExactStep || c <= -kMaxExactStep) return false;
  }
  return true;
}

#if defined(OFLAB_WARP_AVX2)
// True on CPUs with AVX2, unless the environment variable OFLAB_WARP_NO_AVX2 is set (the
// tests run the SSE2 loops that way too). Read once per process.
inline bool use_avx2() {
  static const bool enabled =
      __builtin_cpu_supports("avx2") && std::getenv("OFLAB_WARP_NO_AVX2") == nullptr;
  return enabled;
}

// The blend of four pixels' taps, top = [A00 B00 A10 B10 | C00 D00 C10 D10] and bottom the
// row below, with weights from the low 16 bits of positions [u0 v0 u1 v1 | u2 v2 u3 v3]:
// the pixels' rounded channels as 16-bit lanes [A B | C D] (blend_detail::blend_rows).
OFLAB_AVX2 inline __m256i quad_lanes_from_taps(const __m256i& top, const __m256i& bottom,
                                               const __m256i& positions) {
  // Weights: the low 16 bits of u (bytes 0-1 and 8-9 of each half) and of v (4-5, 12-13),
  // each repeated over a pixel's four channels.
  const __m256i fx = _mm256_shuffle_epi8(
      positions, _mm256_setr_epi8(0, 1, 0, 1, 0, 1, 0, 1, 8, 9, 8, 9, 8, 9, 8, 9, 0, 1, 0, 1, 0, 1,
                                  0, 1, 8, 9, 8, 9, 8, 9, 8, 9));
  const __m256i fy = _mm256_shuffle_epi8(
      positions, _mm256_setr_epi8(4, 5, 4, 5, 4, 5, 4, 5, 12, 13, 12, 13, 12, 13, 12, 13, 4, 5, 4,
                                  5, 4, 5, 4, 5, 12, 13, 12, 13, 12, 13, 12, 13));
  // blend_detail::blend_rows, lane by lane.
  const __m256i zero = _mm256_setzero_si256();
  const __m256i ones = _mm256_set1_epi16(-1);
  const __m256i gx = _mm256_xor_si256(fx, ones);
  const __m256i gy = _mm256_xor_si256(fy, ones);
  const __m256i t = _mm256_add_epi16(_mm256_mulhi_epu16(_mm256_unpacklo_epi8(zero, top), gx),
                                     _mm256_mulhi_epu16(_mm256_unpackhi_epi8(zero, top), fx));
  const __m256i b = _mm256_add_epi16(_mm256_mulhi_epu16(_mm256_unpacklo_epi8(zero, bottom), gx),
                                     _mm256_mulhi_epu16(_mm256_unpackhi_epi8(zero, bottom), fx));
  const __m256i v = _mm256_add_epi16(_mm256_mulhi_epu16(t, gy), _mm256_mulhi_epu16(b, fy));
  return _mm256_srli_epi16(_mm256_add_epi16(v, _mm256_set1_epi16(128)), 8);
}

// Positions of four pixels [u0 v0 u1 v1 | u2 v2 u3 v3] in 16.16 fixed point (int32 lanes)
// -> the four blended pixels' rounded channels as 16-bit lanes [p0 p1 | p2 p3] (each pixel
// four lanes r g b a, values 0..255), before packing.
OFLAB_AVX2 inline __m256i blend_quad_lanes(const Pixel* pixels, std::int64_t stride,
                                           const __m256i& offset_weights,
                                           const __m256i& positions) {
  const __m256i whole = _mm256_srai_epi32(positions, kBlendWeightBits);
  const __m256i offsets = _mm256_madd_epi16(_mm256_packs_epi32(whole, whole), offset_weights);
  const auto low = static_cast<std::uint64_t>(_mm_cvtsi128_si64(_mm256_castsi256_si128(offsets)));
  const auto high =
      static_cast<std::uint64_t>(_mm_cvtsi128_si64(_mm256_extracti128_si256(offsets, 1)));
  const Pixel* pa = pixels + static_cast<std::uint32_t>(low);
  const Pixel* pb = pixels + (low >> 32);
  const Pixel* pc = pixels + static_cast<std::uint32_t>(high);
  const Pixel* pd = pixels + (high >> 32);
  using blend_detail::load_pair;
  const std::int64_t down = stride;
  const __m256i top = _mm256_inserti128_si256(
      _mm256_castsi128_si256(_mm_unpacklo_epi32(load_pair(pa), load_pair(pb))),
      _mm_unpacklo_epi32(load_pair(pc), load_pair(pd)), 1);
  const __m256i bottom = _mm256_inserti128_si256(
      _mm256_castsi128_si256(_mm_unpacklo_epi32(load_pair(pa + down), load_pair(pb + down))),
      _mm_unpacklo_epi32(load_pair(pc + down), load_pair(pd + down)), 1);
  return quad_lanes_from_taps(top, bottom, positions);
}

// Four pixels' samples a, b on two levels (16-bit lanes [p0 p1 | p2 p3], 0 .. 255) blended
// with spread scaled weights 128 w (w in [0, 255]): (a (256 - w) + b w + 128) / 256 per
// channel, rounded down, the bytes of blending the stored samples. As one rounding
// multiplication: a (256 - w) + b w + 128 = 256 a + ((b - a) w + 128), so the blend is
// a + floor(((b - a) w + 128) / 256), and mulhrs(b - a, 128 w) = floor(((b - a) 128 w +
// 2^14) / 2^15) is that quotient exactly (|b - a| <= 255 and 128 w <= 32640 fit 16 bits).
OFLAB_AVX2 inline __m256i lerp_lanes(const __m256i& a, const __m256i& b, const __m256i& weight) {
  return _mm256_add_epi16(a, _mm256_mulhrs_epi16(_mm256_sub_epi16(b, a), weight));
}

// 16-bit lanes [p0 p1 | p2 p3] of channels 0..255 -> the four pixels, stored to out[0..3].
OFLAB_AVX2 inline void store_quad(const __m256i& lanes, Pixel* out) {
  const __m256i packed = _mm256_permute4x64_epi64(_mm256_packus_epi16(lanes, lanes), 0x08);
  _mm_storeu_si128(reinterpret_cast<__m128i*>(out), _mm256_castsi256_si128(packed));
}

// The (1, stride) 16-bit pairs whose multiply-add with packed (u, v) gives v * stride + u.
OFLAB_AVX2 inline __m256i quad_offset_weights(const SourceView& src) {
  return _mm256_set1_epi32(static_cast<int>((static_cast<std::uint32_t>(src.stride) << 16) | 1u));
}

// Four pixels' numerators and denominators (lanes k .. k + 3), as PairStep (warp_kernels.cpp): one
// packed division gives the four reciprocals of D, and the quotients are products with
// them.
struct QuadStep {
  __m256d nu, nv, d;
  __m256d step_u, step_v, step_d;

  // Numerators `scale * (N + bias)` (exact: bias is 0 or 1/2, scale a power of two).
  OFLAB_AVX2 QuadStep(double n_u, double n_v, double den, double du, double dv, double dd,
                      double bias, double scale)
      : nu(_mm256_setr_pd((n_u + bias) * scale, (n_u + du + bias) * scale,
                          (n_u + 2 * du + bias) * scale, (n_u + 3 * du + bias) * scale)),
        nv(_mm256_setr_pd((n_v + bias) * scale, (n_v + dv + bias) * scale,
                          (n_v + 2 * dv + bias) * scale, (n_v + 3 * dv + bias) * scale)),
        d(_mm256_setr_pd(den, den + dd, den + 2 * dd, den + 3 * dd)),
        step_u(_mm256_set1_pd(4 * du * scale)),
        step_v(_mm256_set1_pd(4 * dv * scale)),
        step_d(_mm256_set1_pd(4 * dd)) {}

  // Truncated quotients of the four pixels as int32 lanes (floors if `floored`: the same
  // where they are not negative), then four pixels to the right.
  OFLAB_AVX2 void next(__m128i& u, __m128i& v, bool floored = false) {
    const __m256d r = _mm256_div_pd(_mm256_set1_pd(1.0), d);
    const __m256d qu = _mm256_mul_pd(nu, r), qv = _mm256_mul_pd(nv, r);
    u = _mm256_cvttpd_epi32(floored ? _mm256_floor_pd(qu) : qu);
    v = _mm256_cvttpd_epi32(floored ? _mm256_floor_pd(qv) : qv);
    nu = _mm256_add_pd(nu, step_u);
    nv = _mm256_add_pd(nv, step_v);
    d = _mm256_add_pd(d, step_d);
  }
};

// The 16.16 positions [u0 v0 u1 v1 | u2 v2 u3 v3] of the next four pixels.
OFLAB_AVX2 inline __m256i quad_positions(QuadStep& step, bool floored = false) {
  __m128i u, v;
  step.next(u, v, floored);
  return _mm256_inserti128_si256(_mm256_castsi128_si256(_mm_unpacklo_epi32(u, v)),
                                 _mm_unpackhi_epi32(u, v), 1);
}

// Calls quad(k, positions) for k = 0, 4, ..., total - 4 (total a multiple of 4) with the
// 16.16 positions of pixels k .. k + 3 from `step`. The next quad's positions are computed
// before the current quad's call, so that its blends never wait for the divider. `quad` is
// a lambda marked OFLAB_AVX2 (a lambda does not take its enclosing function's target).
template <typename Quad>
OFLAB_AVX2 inline void for_each_quad(QuadStep& step, int total, const Quad& quad) {
  if (total == 0) return;
  __m256i positions = quad_positions(step);
  for (int k = 0; k < total; k += 4) {
    const __m256i current = positions;
    positions = quad_positions(step);
    quad(k, current);
  }
}
#endif

}  // namespace warp_row
}  // namespace oflab
