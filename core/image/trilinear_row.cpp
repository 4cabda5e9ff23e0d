// The trilinear row (trilinear_row.h): bilinear samples on two mip levels blended with 8-bit
// weights (Williams 83, dissertation section 7.5.5). The AVX2 loop takes its positions, taps
// and blends from warp_row_loop.h, the pieces of the bilinear kernel's own AVX2 loop, so that
// level k's samples are that kernel's bytes.
#include "image/trilinear_row.h"

#include <algorithm>
#include <cstring>
#include <vector>

#include "image/mip_pyramid.h"    // kMipBorder
#include "image/warp_kernels.h"   // run_bilinear_row
#include "image/warp_row_loop.h"  // also provides OFLAB_WARP_AVX2 and <immintrin.h>

namespace oflab {
namespace {

using namespace warp_row;  // the row loops' shared pieces

#if defined(OFLAB_WARP_AVX2)
// Four pixels of a segment end (positions [u0 v0 u1 v1 | u2 v2 u3 v3] in 16.16, floors,
// possibly outside the source) with each tap clamped to the source, as warp_kernels.cpp's
// sample_clamped clamps it: the whole parts (arithmetic shift, so |part| < 2^15) and the
// next ones clamped lane by lane, the taps fetched by two gathers in the order
// quad_lanes_from_taps takes ([A00 B00 A10 B10 | C00 D00 C10 D10], 00 = (x0, y0), 10 =
// (x1, y0); offsets below 2^28, kMaxImageDimension squared).
OFLAB_AVX2 inline __m256i clamped_quad_lanes(const SourceView& src, const __m256i& positions) {
  const auto max_x = static_cast<int>(src.max_x), max_y = static_cast<int>(src.max_y);
  const __m256i most = _mm256_setr_epi32(max_x, max_y, max_x, max_y, max_x, max_y, max_x, max_y);
  const __m256i zero = _mm256_setzero_si256();
  const __m256i whole = _mm256_srai_epi32(positions, kBlendWeightBits);
  const __m256i low = _mm256_min_epi32(_mm256_max_epi32(whole, zero), most);
  const __m256i high =
      _mm256_min_epi32(_mm256_max_epi32(_mm256_add_epi32(whole, _mm256_set1_epi32(1)), zero), most);
  // [x0 of A B, x1 of A B | x0 of C D, x1 of C D], then y0 and y1 of [A B A B | C D C D].
  const __m256i x = _mm256_blend_epi32(_mm256_shuffle_epi32(low, _MM_SHUFFLE(2, 0, 2, 0)),
                                       _mm256_shuffle_epi32(high, _MM_SHUFFLE(2, 0, 2, 0)), 0xcc);
  const __m256i y0 = _mm256_shuffle_epi32(low, _MM_SHUFFLE(3, 1, 3, 1));
  const __m256i y1 = _mm256_shuffle_epi32(high, _MM_SHUFFLE(3, 1, 3, 1));
  const __m256i stride = _mm256_set1_epi32(static_cast<int>(src.stride));
  const auto* base = reinterpret_cast<const int*>(src.pixels);
  const __m256i top =
      _mm256_i32gather_epi32(base, _mm256_add_epi32(_mm256_mullo_epi32(y0, stride), x), 4);
  const __m256i bottom =
      _mm256_i32gather_epi32(base, _mm256_add_epi32(_mm256_mullo_epi32(y1, stride), x), 4);
  return quad_lanes_from_taps(top, bottom, positions);
}

// The first n (1 .. 4) of four pixels' lanes ([p0 p1 | p2 p3], 0 .. 255) stored to
// out[0 .. n - 1] (a masked store: nothing past them is written).
OFLAB_AVX2 inline void store_first(const __m256i& lanes, int n, Pixel* out) {
  const __m256i packed = _mm256_permute4x64_epi64(_mm256_packus_epi16(lanes, lanes), 0x08);
  const __m128i mask = _mm_cmpgt_epi32(_mm_set1_epi32(n), _mm_setr_epi32(0, 1, 2, 3));
  _mm_maskstore_epi32(reinterpret_cast<int*>(out), mask, _mm256_castsi256_si128(packed));
}

// Eight weights w in [0, 255] (16-bit lanes) as lerp_lanes takes them: 128 w, below 2^15.
OFLAB_AVX2 inline __m128i scaled_weights(const __m128i& weights) {
  return _mm_slli_epi16(weights, 7);
}

// The weights of an index octet (256 lower + weight per lane), scaled.
OFLAB_AVX2 inline __m128i octet_weights(const __m128i& octet) {
  return scaled_weights(_mm_and_si128(octet, _mm_set1_epi16(255)));
}

// Four scaled weights (16-bit lanes 0 .. 3 of `four`) spread over their pixels' channels.
OFLAB_AVX2 inline __m256i spread_weights(const __m128i& four) {
  const __m256i spread = _mm256_setr_epi8(0, 1, 0, 1, 0, 1, 0, 1, 2, 3, 2, 3, 2, 3, 2, 3, 4, 5, 4,
                                          5, 4, 5, 4, 5, 6, 7, 6, 7, 6, 7, 6, 7);
  return _mm256_shuffle_epi8(_mm256_broadcastq_epi64(four), spread);
}

// The scaled weights of an octet's two quads (16-bit lanes 0 .. 3 and 4 .. 7 of `eight`),
// each spread over its pixels' channels as spread_weights spreads them: one broadcast of the
// octet, one byte shuffle a quad.
OFLAB_AVX2 inline void spread_octet_weights(const __m128i& eight, __m256i& first, __m256i& second) {
  const __m256i wide = _mm256_broadcastsi128_si256(eight);
  first =
      _mm256_shuffle_epi8(wide, _mm256_setr_epi8(0, 1, 0, 1, 0, 1, 0, 1, 2, 3, 2, 3, 2, 3, 2, 3, 4,
                                                 5, 4, 5, 4, 5, 4, 5, 6, 7, 6, 7, 6, 7, 6, 7));
  second = _mm256_shuffle_epi8(
      wide, _mm256_setr_epi8(8, 9, 8, 9, 8, 9, 8, 9, 10, 11, 10, 11, 10, 11, 10, 11, 12, 13, 12, 13,
                             12, 13, 12, 13, 14, 15, 14, 15, 14, 15, 14, 15));
}

using warp_row::lerp_lanes;  // the overload on spread weights, beside this one

// The same with the weights w[0..3] (in [0, 255]).
OFLAB_AVX2 inline __m256i lerp_lanes(const __m256i& a, const __m256i& b, const std::uint16_t* w) {
  return lerp_lanes(
      a, b, spread_weights(scaled_weights(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(w)))));
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
    store_first(lerp_lanes(a, b, w), n, out + k);
  }
}

// A level pair's two sources as the level rows read them: level k and level k + 1 (level k
// again on the top level, whose weights are 0: its taps then stay inside level k). With
// border > 0 (both levels have bordered copies) the views read the bordered copies (pixels at
// their level's pixel (0, 0), max_x and max_y the level's own) and the corners are the
// copies' pixel (0, 0), level pixel (-border, -border).
struct LevelPairView {
  SourceView src, next;
  __m256i offset_weights, next_offset_weights;
  int border;
  const Pixel* src_corner;
  const Pixel* next_corner;
};

// Level k's view and its bordered copy's corner, or null if it has no fitting copy.
inline const Pixel* bordered_view(const MipLevelMaps& levels, std::size_t k, SourceView& view) {
  const Image& level = *levels.images[k];
  const Image* copy = k < levels.bordered.size() ? levels.bordered[k] : nullptr;
  view = source_view(level);
  if (copy == nullptr || copy->width() != level.width() + 2 * kMipBorder ||
      copy->height() != level.height() + 2 * kMipBorder) {
    return nullptr;
  }
  view.pixels = copy->pixels().data() + kMipBorder * copy->width() + kMipBorder;
  view.stride = copy->width();
  return copy->pixels().data();
}

OFLAB_AVX2 LevelPairView level_pair_view(const MipLevelMaps& levels, int k) {
  const int top = static_cast<int>(levels.images.size()) - 1;
  LevelPairView view{};
  const Pixel* src_corner = bordered_view(levels, static_cast<std::size_t>(k), view.src);
  const Pixel* next_corner =
      bordered_view(levels, static_cast<std::size_t>(std::min(k + 1, top)), view.next);
  if (src_corner != nullptr && next_corner != nullptr) {
    view.border = kMipBorder;
    view.src_corner = src_corner;
    view.next_corner = next_corner;
  } else {  // both levels as they are
    view.src = source_view(*levels.images[static_cast<std::size_t>(k)]);
    view.next = source_view(*levels.images[static_cast<std::size_t>(std::min(k + 1, top))]);
  }
  view.offset_weights = quad_offset_weights(view.src);
  view.next_offset_weights = quad_offset_weights(view.next);
  return view;
}

// True if the taps of the sample (level k's positions, with the fast range's margins) and
// those of level k + 1 derived from it stay within the border of a bordered pair: level k's
// positions in [1 - border, max + border - 1) (in_fast_range<true> with each margin lowered
// by the border). With border 2, floored positions u_k in [-2, w_k + 1) have their taps in
// [-2, w_k + 1] and u_{k + 1} = u_k / 2 - 1/4 in [-5/4, w_k / 2 + 1/4), taps in
// [-2, ceil(w_k / 2) + 1]: both inside their copies.
inline bool in_border_range(const LevelPairView& view, const MapSample& s) {
  if (view.border == 0 || s.d <= 0 || s.d >= kMaxCompareDenominator) return false;
  const std::int64_t low = (kBilinearLowMargin - view.border) * s.d;
  const std::int64_t high = kBilinearHighMargin - view.border;
  return s.nu >= low && s.nv >= low && s.nu < (view.src.max_x - high + 1) * s.d &&
         s.nv < (view.src.max_y - high + 1) * s.d;
}

// Four pixels at floored 16.16 positions within in_border_range, sampled on both bordered
// levels and blended: the taps read from the corners, every whole part shifted by the
// border (the fractions, the low 16 bits, unchanged), so each tap is the texel that
// clamped_quad_lanes clamps it to and the bytes are perspective_trilinear_clamped's.
OFLAB_AVX2 inline __m256i border_quad(const LevelPairView& view, const __m256i& positions,
                                      const __m256i& weight) {
  const __m256i shift = _mm256_set1_epi32(view.border << kBlendWeightBits);
  const __m256i quarter = _mm256_set1_epi32(1 << (kBlendWeightBits - 2));
  const __m256i a = blend_quad_lanes(view.src_corner, view.src.stride, view.offset_weights,
                                     _mm256_add_epi32(positions, shift));
  const __m256i b = blend_quad_lanes(
      view.next_corner, view.next.stride, view.next_offset_weights,
      _mm256_add_epi32(_mm256_sub_epi32(_mm256_srai_epi32(positions, 1), quarter), shift));
  return lerp_lanes(a, b, weight);
}

// Four pixels at 16.16 positions (level k's fast range) sampled on both levels and blended
// with spread weights, as perspective_trilinear_quads samples them.
OFLAB_AVX2 inline __m256i trilinear_quad(const LevelPairView& view, const __m256i& positions,
                                         const __m256i& weight) {
  const __m256i quarter = _mm256_set1_epi32(1 << (kBlendWeightBits - 2));
  const __m256i a =
      blend_quad_lanes(view.src.pixels, view.src.stride, view.offset_weights, positions);
  const __m256i b = blend_quad_lanes(view.next.pixels, view.next.stride, view.next_offset_weights,
                                     _mm256_sub_epi32(_mm256_srai_epi32(positions, 1), quarter));
  return lerp_lanes(a, b, weight);
}

// Two quads' lanes packed at once ([q0 p0 p1, q1 p0 p1 | q0 p2 p3, q1 p2 p3]) and stored as
// eight pixels to out[0 .. 7].
OFLAB_AVX2 inline void store_octet(const __m256i& lanes0, const __m256i& lanes1, Pixel* out) {
  const __m256i packed = _mm256_packus_epi16(lanes0, lanes1);
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(out),
                      _mm256_permute4x64_epi64(packed, _MM_SHUFFLE(3, 1, 2, 0)));
}

// Eight pixels within the border range with indices index[0 .. 7], sampled by border_quad at
// floored positions from `step` (left at the ninth pixel).
OFLAB_AVX2 inline void border_octet(const LevelPairView& view, const std::uint16_t* index,
                                    Pixel* out, QuadStep& step) {
  const __m128i weights = octet_weights(_mm_loadu_si128(reinterpret_cast<const __m128i*>(index)));
  const __m256i first = quad_positions(step, true);
  const __m256i second = quad_positions(step, true);
  __m256i w0, w1;
  spread_octet_weights(weights, w0, w1);
  store_octet(border_quad(view, first, w0), border_quad(view, second, w1), out);
}

// Pixels of level k's fast range (with border_first, after a first octet within the border
// range, sampled by border_quad) sampled eight at a time with their indices (256 lower +
// weight, index[i] pixel i's) while all eight have lower level k: with weights all 0 level k
// alone (lerp_lanes' bytes for weight 0), else both levels. Returns the pixels done, a
// multiple of 8 at most count; the rest starts with an octet holding another lower level or
// is shorter than eight. `step` starts at the first pixel and is left at the first pixel not
// done.
OFLAB_AVX2 int trilinear_octets(const LevelPairView& view, const std::uint16_t* index, int k,
                                Pixel* out, int count, QuadStep& step, bool border_first) {
  // The view's fields as locals, so that the stores to `out` do not make the loop reload them.
  const Pixel* const pixels = view.src.pixels;
  const Pixel* const next_pixels = view.next.pixels;
  const std::int64_t stride = view.src.stride, next_stride = view.next.stride;
  const __m256i offset_weights = view.offset_weights;
  const __m256i next_offset_weights = view.next_offset_weights;
  const __m256i quarter = _mm256_set1_epi32(1 << (kBlendWeightBits - 2));
  const __m128i lower = _mm_set1_epi16(static_cast<short>(k));
  // Four pixels at `positions` on both levels, blended with the spread weights.
  const auto both = [=](const __m256i& positions, const __m256i& weight) OFLAB_AVX2 {
    const __m256i a = blend_quad_lanes(pixels, stride, offset_weights, positions);
    const __m256i b = blend_quad_lanes(next_pixels, next_stride, next_offset_weights,
                                       _mm256_sub_epi32(_mm256_srai_epi32(positions, 1), quarter));
    return lerp_lanes(a, b, weight);
  };
  int i = 0;
  if (border_first) {
    border_octet(view, index, out, step);
    i = 8;
  }
  __m256i positions = quad_positions(step);
  for (; i + 8 <= count; i += 8) {
    const __m128i octet = _mm_loadu_si128(reinterpret_cast<const __m128i*>(index + i));
    if (_mm_movemask_epi8(_mm_cmpeq_epi16(_mm_srli_epi16(octet, 8), lower)) != 0xffff) break;
    const __m128i weights = octet_weights(octet);
    // The two quads written out (no array, no loop), so that their lanes stay in registers;
    // each quad's successor's positions are found before its blends.
    const __m256i first = positions;
    const __m256i second = quad_positions(step);
    __m256i lanes0, lanes1;
    if (_mm_testz_si128(weights, weights)) {
      lanes0 = blend_quad_lanes(pixels, stride, offset_weights, first);
      positions = quad_positions(step);
      lanes1 = blend_quad_lanes(pixels, stride, offset_weights, second);
    } else {
      __m256i w0, w1;
      spread_octet_weights(weights, w0, w1);
      lanes0 = both(first, w0);
      positions = quad_positions(step);
      lanes1 = both(second, w1);
    }
    store_octet(lanes0, lanes1, out + i);
  }
  // Back one quad, to the first pixel not done: the sums are integers below 2^53 times
  // powers of two (steps_exact_in_double), so this is exactly the step quad_step_at gives.
  step.nu = _mm256_sub_pd(step.nu, step.step_u);
  step.nv = _mm256_sub_pd(step.nv, step.step_v);
  step.d = _mm256_sub_pd(step.d, step.step_d);
  return i;
}

// The first count (1 .. 8) pixels of level k's fast range with indices `index` (lanes 0 ..
// count - 1): a short quad's unused lanes take its first pixel's position (inside the range),
// and only its pixels are stored. kBorder: pixels in in_border_range instead, sampled by
// border_quad at floored positions.
template <bool kBorder>
OFLAB_AVX2 void trilinear_few(const LevelPairView& view, const __m128i& index, Pixel* out,
                              int count, QuadStep step) {
  const __m128i weights = octet_weights(index);
  for (int q = 0; q * 4 < count; ++q) {
    const int n = std::min(4, count - 4 * q);
    __m256i positions = quad_positions(step, kBorder);
    if (n < 4) {
      alignas(32) static const std::int32_t kFirst[3][8] = {
          {0, 1, 0, 1, 0, 1, 0, 1}, {0, 1, 2, 3, 0, 1, 0, 1}, {0, 1, 2, 3, 4, 5, 0, 1}};
      positions = _mm256_permutevar8x32_epi32(
          positions, _mm256_load_si256(reinterpret_cast<const __m256i*>(kFirst[n - 1])));
    }
    const __m256i w = spread_weights(q == 0 ? weights : _mm_unpackhi_epi64(weights, weights));
    store_first(kBorder ? border_quad(view, positions, w) : trilinear_quad(view, positions, w), n,
                out + 4 * q);
  }
}

// The quad steps of `map` from pixel x of row y (as run_trilinear_row starts them).
OFLAB_AVX2 QuadStep quad_step_at(const InverseMap& map, int x, int y) {
  const MapSample s = evaluate(map, x, y);
  return QuadStep(static_cast<double>(s.nu), static_cast<double>(s.nv), static_cast<double>(s.d),
                  static_cast<double>(2 * map.a), static_cast<double>(2 * map.d),
                  static_cast<double>(2 * map.g), 0.0, 1 << kBlendWeightBits);
}

// How many of the lanes of `index`, from lane 0 on, hold lower level k (at most `limit`).
OFLAB_AVX2 inline int leading_lower(const __m128i& index, int k, int limit) {
  const auto same = static_cast<unsigned>(_mm_movemask_epi8(
      _mm_cmpeq_epi16(_mm_srli_epi16(index, 8), _mm_set1_epi16(static_cast<short>(k)))));
  const int lanes = same == 0xffffu ? 8 : __builtin_ctz(~same) / 2;
  return std::min(lanes, limit);
}

// The pixels from x (lower level k, outside level k's fast range) that share k, stay outside
// it, and are (or are not, as x) within the border range: by border_quad, else with clamped
// taps. Returns how many (1 .. 8).
OFLAB_AVX2 int outside_fast_range(const LevelPairView& view, const InverseMap& map,
                                  const __m128i& octet, int k, int x, int y, int x_end, Pixel* o) {
  const int limit = leading_lower(octet, k, x_end - x);
  const bool border = in_border_range(view, evaluate(map, x, y));
  int n = 1;
  for (; n < limit; ++n) {
    const MapSample s = evaluate(map, x + n, y);
    if (in_fast_range<true>(view.src, s) || in_border_range(view, s) != border) break;
  }
  if (border) {
    trilinear_few<true>(view, octet, o, n, quad_step_at(map, x, y));
    return n;
  }
  alignas(16) std::uint16_t weights[8];
  _mm_store_si128(reinterpret_cast<__m128i*>(weights), _mm_and_si128(octet, _mm_set1_epi16(255)));
  const MapSample s = evaluate(map, x, y);
  perspective_trilinear_clamped(view.src, view.next, weights, o, n, static_cast<double>(s.nu),
                                static_cast<double>(s.nv), static_cast<double>(s.d),
                                static_cast<double>(2 * map.a), static_cast<double>(2 * map.d),
                                static_cast<double>(2 * map.g));
  return n;
}

// True if the octet from x (outside level k's fast range) can open the octet loop on a
// bordered pair: its eight pixels share k and lie within the border range (an interval, as
// the fast range: its ends suffice), and pixel x + 8 is in the fast range.
OFLAB_AVX2 bool opens_with_border(const LevelPairView& view, const InverseMap& map,
                                  const __m128i& octet, int k, int x, int y, int x_end) {
  return view.border > 0 && x + 8 < x_end && leading_lower(octet, k, 8) == 8 &&
         in_border_range(view, evaluate(map, x, y)) &&
         in_border_range(view, evaluate(map, x + 7, y)) &&
         in_fast_range<true>(view.src, evaluate(map, x + 8, y));
}

// run_trilinear_levels_row's loop (trilinear_row.h): from pixel x, the lower level k of x;
// if x's taps leave level k, the pixels from x that share k and leave it
// (outside_fast_range), unless a bordered pair's octet opens the octet loop there; else
// level k's fast range from x (an interval: the source's inner box and its image under the
// projective map are convex), the octets of trilinear_octets and the few pixels of the next
// octet that still have level k, on a bordered pair up to the border range's end.
OFLAB_AVX2 void levels_row(const MipLevelMaps& levels, const std::uint16_t* indices, int y,
                           int x_begin, int x_end, Pixel* out) {
  LevelPairView view{};  // level pair `viewed`'s, kept while the segments stay on it
  int viewed = -1;
  for (int x = x_begin; x < x_end;) {
    const std::uint16_t* index = indices + (x - x_begin);
    const __m128i octet = _mm_loadu_si128(reinterpret_cast<const __m128i*>(index));
    const int k = index[0] >> 8;
    const InverseMap& map = levels.maps[static_cast<std::size_t>(k)];
    if (k != viewed) view = level_pair_view(levels, k), viewed = k;
    Pixel* o = out + (x - x_begin);
    const bool border_first = !in_fast_range<true>(view.src, evaluate(map, x, y));
    if (border_first && !opens_with_border(view, map, octet, k, x, y, x_end)) {
      x += outside_fast_range(view, map, octet, k, x, y, x_end, o);
      continue;
    }
    int fast_end = x_end;  // with border_first at least x + 9
    while (fast_end > x + 1 && !in_fast_range<true>(view.src, evaluate(map, fast_end - 1, y))) {
      --fast_end;
    }
    QuadStep step = quad_step_at(map, x, y);
    x += trilinear_octets(view, index, k, o, fast_end - x, step, border_first);
    // The rest of the interval: [x, fast_end) is in the fast range, and so in the border range.
    int end = fast_end;
    if (view.border > 0) {
      end = x_end;
      while (end > x && !in_border_range(view, evaluate(map, end - 1, y))) --end;
    }
    if (x >= end) continue;
    const __m128i rest = _mm_loadu_si128(reinterpret_cast<const __m128i*>(indices + (x - x_begin)));
    const int few = leading_lower(rest, k, end - x);
    if (few > 0) {
      if (view.border > 0) {
        trilinear_few<true>(view, rest, out + (x - x_begin), few, step);
      } else {
        trilinear_few<false>(view, rest, out + (x - x_begin), few, step);
      }
      x += few;
    }
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

bool run_trilinear_levels_row(const MipLevelMaps& levels, const std::uint16_t* indices, int y,
                              int x_begin, int x_end, Pixel* out) {
#if defined(OFLAB_WARP_AVX2)
  if (!use_avx2()) return false;
  for (const InverseMap& map : levels.maps) {
    if (!steps_exact_in_double(map)) return false;
  }
  levels_row(levels, indices, y, x_begin, x_end, out);
  return true;
#else
  (void)levels, (void)indices, (void)y, (void)x_begin, (void)x_end, (void)out;
  return false;
#endif
}

}  // namespace oflab
