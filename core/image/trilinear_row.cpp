// The trilinear row (trilinear_row.h): bilinear samples on two mip levels blended with 8-bit
// weights (Williams 83, dissertation section 7.5.5). The AVX2 loop takes its positions, taps
// and blends from warp_row_loop.h, the pieces of the bilinear kernel's own AVX2 loop, so that
// level k's samples are that kernel's bytes.
#include "image/trilinear_row.h"

#include <algorithm>
#include <cstring>
#include <vector>

#include "image/warp_kernels.h"   // run_bilinear_row
#include "image/warp_row_loop.h"  // also provides OFLAB_WARP_AVX2 and <immintrin.h>

namespace oflab {
namespace {

using namespace warp_row;  // the row loops' shared pieces

#if defined(OFLAB_WARP_AVX2)
// Four pixels of a segment end (positions [u0 v0 u1 v1 | u2 v2 u3 v3] in 16.16, floors,
// possibly outside the source) with each tap clamped to the source, as warp_kernels.cpp's
// sample_clamped clamps it.
OFLAB_AVX2 inline __m256i clamped_quad_lanes(const SourceView& src, const __m256i& positions) {
  alignas(32) std::int32_t at[8];
  _mm256_store_si256(reinterpret_cast<__m256i*>(at), _mm256_srai_epi32(positions, 16));
  alignas(32) std::uint32_t top[8], bottom[8];
  for (int j = 0; j < 4; ++j) {
    const std::int64_t x0 = std::clamp<std::int64_t>(at[2 * j], 0, src.max_x);
    const std::int64_t x1 = std::clamp<std::int64_t>(at[2 * j] + std::int64_t{1}, 0, src.max_x);
    const std::int64_t y0 = std::clamp<std::int64_t>(at[2 * j + 1], 0, src.max_y);
    const std::int64_t y1 = std::clamp<std::int64_t>(at[2 * j + 1] + std::int64_t{1}, 0, src.max_y);
    const int slot = 4 * (j / 2) + j % 2;  // [A00 B00 A10 B10 | C00 D00 C10 D10]
    std::memcpy(&top[slot], src.at(x0, y0), 4);
    std::memcpy(&top[slot + 2], src.at(x1, y0), 4);
    std::memcpy(&bottom[slot], src.at(x0, y1), 4);
    std::memcpy(&bottom[slot + 2], src.at(x1, y1), 4);
  }
  return quad_lanes_from_taps(_mm256_load_si256(reinterpret_cast<const __m256i*>(top)),
                              _mm256_load_si256(reinterpret_cast<const __m256i*>(bottom)),
                              positions);
}

// Four pixels' samples a, b on two levels (16-bit lanes [p0 p1 | p2 p3]) blended with
// weights w[0..3] in [0, 256]: (a (256 - w) + b w + 128) / 256 per channel, the bytes of
// blending the stored samples (a (256 - w) + b w <= 255 * 256: no overflow).
OFLAB_AVX2 inline __m256i lerp_lanes(const __m256i& a, const __m256i& b, const std::uint16_t* w) {
  std::int64_t four;
  std::memcpy(&four, w, sizeof(four));
  const __m256i spread = _mm256_setr_epi8(0, 1, 0, 1, 0, 1, 0, 1, 2, 3, 2, 3, 2, 3, 2, 3, 4, 5, 4,
                                          5, 4, 5, 4, 5, 6, 7, 6, 7, 6, 7, 6, 7);
  const __m256i weight = _mm256_shuffle_epi8(_mm256_set1_epi64x(four), spread);
  const __m256i sum =
      _mm256_add_epi16(_mm256_mullo_epi16(a, _mm256_sub_epi16(_mm256_set1_epi16(256), weight)),
                       _mm256_mullo_epi16(b, weight));
  return _mm256_srli_epi16(_mm256_add_epi16(sum, _mm256_set1_epi16(128)), 8);
}

// The same on two mip levels at once, blended: `src` is level k and `next` level k + 1,
// sampled at the positions derived from level k's: u_{k+1} = u_k / 2 - 1/4 (pixel-centre
// coordinates; in 16.16 a shift and a subtraction, within one unit of 2^-16 of the truncated
// exact position). Level k's fast range keeps level k + 1's taps inside it:
// 1 <= u_k < w_k - 1 gives 1/4 <= u_{k+1} < ceil(w_k / 2) - 5/4. The two samples are
// blended by lerp_lanes.
OFLAB_AVX2 int perspective_trilinear_quads(const SourceView& src, const SourceView& next,
                                           const std::uint16_t* weights, Pixel* out, int count,
                                           double nu, double nv, double d, double du, double dv,
                                           double dd) {
  const __m256i offset_weights = quad_offset_weights(src);
  const __m256i next_offset_weights = quad_offset_weights(next);
  const __m256i quarter = _mm256_set1_epi32(1 << (kBlendWeightBits - 2));
  const Pixel* const pixels = src.pixels;
  const Pixel* const next_pixels = next.pixels;
  const std::int64_t stride = src.stride;
  const std::int64_t next_stride = next.stride;
  QuadStep step(nu, nv, d, du, dv, dd, 0.0, 1 << kBlendWeightBits);
  const int total = count & ~3;
  for_each_quad(step, total, [=](int k, const __m256i& positions) OFLAB_AVX2 {
    const __m256i a = blend_quad_lanes(pixels, stride, offset_weights, positions);
    const __m256i b = blend_quad_lanes(next_pixels, next_stride, next_offset_weights,
                                       _mm256_sub_epi32(_mm256_srai_epi32(positions, 1), quarter));
    store_quad(lerp_lanes(a, b, weights + k), out + k);
  });
  return total;
}

// Pixels 0 .. count - 1 of a trilinear segment whose taps may leave either level (the ends
// of a span, and what the quads leave over): the positions of perspective_trilinear_quads
// (the same products, floored), every tap clamped to its level as clamped_quad_lanes clamps
// it, so each pixel's bytes are the fast loop's wherever both apply.
OFLAB_AVX2 void perspective_trilinear_clamped(const SourceView& src, const SourceView& next,
                                              const std::uint16_t* weights, Pixel* out, int count,
                                              double nu, double nv, double d, double du, double dv,
                                              double dd) {
  const __m256i quarter = _mm256_set1_epi32(1 << (kBlendWeightBits - 2));
  QuadStep step(nu, nv, d, du, dv, dd, 0.0, 1 << kBlendWeightBits);
  for (int k = 0; k < count; k += 4) {
    const int n = std::min(4, count - k);
    const __m256i positions = quad_positions(step, true);
    const __m256i a = clamped_quad_lanes(src, positions);
    const __m256i b =
        clamped_quad_lanes(next, _mm256_sub_epi32(_mm256_srai_epi32(positions, 1), quarter));
    std::uint16_t w[4] = {0, 0, 0, 0};
    std::copy(weights + k, weights + k + n, w);
    Pixel four[4];
    store_quad(lerp_lanes(a, b, w), four);
    std::copy(four, four + n, out + k);
  }
}
#endif

}  // namespace

void run_trilinear_row(const InverseMap& map, const Image& source, const InverseMap& next_map,
                       const Image& next_source, int y, int x_begin, int x_end,
                       const std::uint16_t* weights, Pixel* out) {
#if defined(OFLAB_WARP_AVX2)
  const bool fast_allowed = use_avx2() && steps_exact_in_double(map);
#else
  const bool fast_allowed = false;  // the SSE2 build runs the two levels one after the other
#endif
  if (!fast_allowed) {
    thread_local std::vector<Pixel> upper;
    upper.resize(static_cast<std::size_t>(std::max(x_end - x_begin, 0)));
    run_bilinear_row(map, source, y, x_begin, x_end, out);
    run_bilinear_row(next_map, next_source, y, x_begin, x_end, upper.data());
    for (int k = 0; k < x_end - x_begin; ++k) {
      const Pixel a = out[k], b = upper[static_cast<std::size_t>(k)];
      const int w = weights[k];
      auto channel = [&](std::uint8_t Pixel::*c) {
        return static_cast<std::uint8_t>((a.*c * (256 - w) + b.*c * w + 128) >> 8);
      };
      out[k] =
          Pixel{channel(&Pixel::r), channel(&Pixel::g), channel(&Pixel::b), channel(&Pixel::a)};
    }
    return;
  }
#if defined(OFLAB_WARP_AVX2)
  const SourceView src = source_view(source);
  const SourceView next = source_view(next_source);
  // Pixels from .. to - 1 with clamped taps, at once.
  const auto ends = [&](int from, int to) {
    if (from >= to) return;
    const MapSample s = evaluate(map, from, y);
    perspective_trilinear_clamped(src, next, weights + (from - x_begin), out + (from - x_begin),
                                  to - from, static_cast<double>(s.nu), static_cast<double>(s.nv),
                                  static_cast<double>(s.d), static_cast<double>(2 * map.a),
                                  static_cast<double>(2 * map.d), static_cast<double>(2 * map.g));
  };
  int begin = x_begin, end = x_end;
  while (begin < end && !in_fast_range<true>(src, evaluate(map, begin, y))) ++begin;
  while (end > begin && !in_fast_range<true>(src, evaluate(map, end - 1, y))) --end;
  ends(x_begin, begin);
  ends(end, x_end);
  if (begin >= end) return;
  const MapSample s = evaluate(map, begin, y);
  const int done =
      perspective_trilinear_quads(src, next, weights + (begin - x_begin), out + (begin - x_begin),
                                  end - begin, static_cast<double>(s.nu), static_cast<double>(s.nv),
                                  static_cast<double>(s.d), static_cast<double>(2 * map.a),
                                  static_cast<double>(2 * map.d), static_cast<double>(2 * map.g));
  ends(begin + done, end);
#endif
}

}  // namespace oflab
