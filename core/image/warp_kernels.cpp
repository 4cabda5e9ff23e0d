// Affine and perspective warp kernels, nearest and bilinear (dissertation appendix A.1,
// errata 28-30 fixed). See warp_kernels.h for the scheme and inverse_map.h for the exact
// definition of the sampling position that every nearest loop here reproduces bit for
// bit; the bilinear loops stay within a few thousandths of a pixel of it.
#include "image/warp_kernels.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "image/bilinear_blend.h"  // also provides OFLAB_WARP_SSE2 and <emmintrin.h>
#include "image/scan_conversion.h"
#include "image/thread_pool.h"
#include "image/warp_row_loop.h"  // also provides OFLAB_WARP_AVX2 and <immintrin.h>

namespace oflab {
namespace {

using namespace warp_row;  // the row loops' shared pieces

// Longest run an affine bilinear loop steps in 16.16 fixed point before it restarts from
// the exact 64-bit position: the rounding of the step then moves the position by at most
// 32 * 2^-17 = 2^-12 pixel, at most a quarter level of difference in the result.
// (Only the SIMD loops step in runs: the portable build, e.g. WebAssembly, leaves it unused.)
[[maybe_unused]] constexpr int kMaxApproximateRun = 64;

// Floor of the sampling position of `s` and its fraction in units of 2^-16, from the
// map's form: a shift for the affine form (D = 2^shift); for the division form the
// correctly rounded double quotient, whose floor is exact (inverse_map.h), with the
// fraction truncated from it (within 2^-16 of the exact fraction's truncation).
struct SplitPosition {
  std::int64_t whole;
  std::uint32_t fraction;
};

SplitPosition split_position(std::int64_t n, std::int64_t d, int affine_shift) {
  if (affine_shift >= 0) {
    return {n >> affine_shift,
            static_cast<std::uint32_t>(n >> (affine_shift - kBlendWeightBits)) & kBlendWeightMask};
  }
  const double q = static_cast<double>(n) / static_cast<double>(d);
  const double whole = std::floor(q);
  const auto fraction = static_cast<std::uint32_t>((q - whole) * (1 << kBlendWeightBits));
  return {static_cast<std::int64_t>(whole), std::min(fraction, kBlendWeightMask)};
}

// Sample with clamping, for the pixels at the ends of a span: exact for nearest, the
// same weights as the fast loops (to 2^-16) for bilinear.
template <bool kBilinear>
Pixel sample_clamped(const SourceView& src, const MapSample& s, int affine_shift) {
  const SplitPosition u = split_position(s.nu, s.d, affine_shift);
  const SplitPosition v = split_position(s.nv, s.d, affine_shift);
  if constexpr (!kBilinear) {
    return *src.at(std::clamp<std::int64_t>(u.whole, 0, src.max_x),
                   std::clamp<std::int64_t>(v.whole, 0, src.max_y));
  } else {
    const std::int64_t x0 = std::clamp<std::int64_t>(u.whole, 0, src.max_x);
    const std::int64_t x1 = std::clamp<std::int64_t>(u.whole + 1, 0, src.max_x);
    const std::int64_t y0 = std::clamp<std::int64_t>(v.whole, 0, src.max_y);
    const std::int64_t y1 = std::clamp<std::int64_t>(v.whole + 1, 0, src.max_y);
    return blend_taps(src.at(x0, y0), src.at(x1, y0), src.at(x0, y1), src.at(x1, y1), u.fraction,
                      v.fraction);
  }
}

#if defined(OFLAB_WARP_SSE2)
// Pixel offsets v * stride + u of two source pixels [u_a v_a u_b v_b] (int32 lanes, all
// below 2^15 since images are at most kMaxImageDimension across), through one
// multiply-add of (u, v) as 16-bit pairs with (1, stride): a's offset in the low 32 bits.
class PairOffsets {
 public:
  explicit PairOffsets(const SourceView& src)
      : weights_(
            _mm_set1_epi32(static_cast<int>((static_cast<std::uint32_t>(src.stride) << 16) | 1u))) {
  }

  std::uint64_t operator()(__m128i positions) const {
    return static_cast<std::uint64_t>(
        _mm_cvtsi128_si64(_mm_madd_epi16(_mm_packs_epi32(positions, positions), weights_)));
  }

 private:
  __m128i weights_;
};

// Bilinear step shared by both kernels: two pixels' positions [u_a v_a u_b v_b] in 16.16
// fixed point (int32 lanes) -> offsets of the top-left taps, weights from the low 16
// bits, one blend for both pixels.
struct BilinearPairs {
  const SourceView& src;
  PairOffsets offsets;

  explicit BilinearPairs(const SourceView& s) : src(s), offsets(s) {}

  void blend(__m128i positions, Pixel* out) const {
    const std::uint64_t pair = offsets(_mm_srai_epi32(positions, kBlendWeightBits));
    // 16-bit lanes 0, 4 hold u_a, u_b's weights; lanes 2, 6 those of v_a, v_b.
    const __m128i fx = _mm_shufflehi_epi16(_mm_shufflelo_epi16(positions, 0), 0);
    const __m128i fy = _mm_shufflehi_epi16(_mm_shufflelo_epi16(positions, 0xaa), 0xaa);
    blend_block_pair(src.pixels + static_cast<std::uint32_t>(pair), src.pixels + (pair >> 32),
                     src.stride, fx, fy, out);
  }

  // One pixel from a 16.16 position (u, v).
  Pixel single(std::uint32_t u, std::uint32_t v) const {
    return blend_block(src.at(u >> kBlendWeightBits, v >> kBlendWeightBits), src.stride,
                       u & kBlendWeightMask, v & kBlendWeightMask);
  }
};
#endif

#if defined(OFLAB_WARP_AVX2)
// The AVX2 loops, four pixels per step, on the pieces in warp_row_loop.h: the blend
// arithmetic of the SSE2 loops (bilinear_blend.h) in both 128-bit halves of a 256-bit
// register. Perspective positions are the same products as in the SSE2 loop, so the results
// are identical; affine positions step four pixels at a time (within 2^-13 pixel of the exact
// position instead of 2^-12).

// The same stored to out[0..3].
OFLAB_AVX2 inline void blend_quad(const Pixel* pixels, std::int64_t stride,
                                  const __m256i& offset_weights, const __m256i& positions,
                                  Pixel* out) {
  store_quad(blend_quad_lanes(pixels, stride, offset_weights, positions), out);
}

// Affine bilinear, four pixels per step, in runs of up to kMaxApproximateRun pixels that
// restart from the exact position. Handles the largest multiple of 4 pixels of the span
// and returns how many it wrote.
OFLAB_AVX2 int affine_bilinear_quads(const SourceView& src, Pixel* out, int count, std::int64_t nu,
                                     std::int64_t nv, std::int64_t du, std::int64_t dv, int to_16) {
  const __m256i offset_weights = quad_offset_weights(src);
  // Locals, so that the stores to `out` cannot make the compiler reload them.
  const Pixel* const pixels = src.pixels;
  const std::int64_t stride = src.stride;
  const std::int64_t half = std::int64_t{1} << (to_16 - 1);
  const auto su = static_cast<std::int32_t>((4 * du + half) >> to_16);  // rounded
  const auto sv = static_cast<std::int32_t>((4 * dv + half) >> to_16);
  const __m256i step = _mm256_setr_epi32(su, sv, su, sv, su, sv, su, sv);
  const int total = count & ~3;
  for (int k = 0; k < total;) {
    const int run = std::min(total - k, kMaxApproximateRun);
    // Exact positions of the run's first four pixels, truncated to 16.16.
    std::int32_t first[8];
    for (int j = 0; j < 4; ++j) {
      first[2 * j] = static_cast<std::int32_t>((nu + j * du) >> to_16);
      first[2 * j + 1] = static_cast<std::int32_t>((nv + j * dv) >> to_16);
    }
    __m256i positions = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(first));
    for (int j = 0; j < run; j += 4) {
      blend_quad(pixels, stride, offset_weights, positions, out + k + j);
      positions = _mm256_add_epi32(positions, step);
    }
    k += run;
    nu += run * du;
    nv += run * dv;
  }
  return total;
}

// Perspective nearest, four pixels per step: one packed division gives the four
// reciprocals of D, and the floors are the truncated products (N + 1/2) * (1/D), exact
// under the same condition as in the SSE2 loop (numerators below
// kMaxReciprocalNumerator, checked by the caller). Handles the largest multiple of 4
// pixels of the span and returns how many it wrote.
OFLAB_AVX2 int perspective_nearest_quads(const SourceView& src, Pixel* out, int count, double nu,
                                         double nv, double d, double du, double dv, double dd) {
  const Pixel* const pixels = src.pixels;
  const __m128i stride = _mm_set1_epi32(static_cast<int>(src.stride));
  QuadStep step(nu, nv, d, du, dv, dd, 0.5, 1.0);
  const int total = count & ~3;
  for (int k = 0; k < total; k += 4) {
    __m128i u, v;
    step.next(u, v);
    // Offsets v * stride + u, below 2^28.
    const __m128i offsets = _mm_add_epi32(_mm_mullo_epi32(v, stride), u);
    const auto low = static_cast<std::uint64_t>(_mm_cvtsi128_si64(offsets));
    const auto high = static_cast<std::uint64_t>(_mm_extract_epi64(offsets, 1));
    out[k] = pixels[static_cast<std::uint32_t>(low)];
    out[k + 1] = pixels[low >> 32];
    out[k + 2] = pixels[static_cast<std::uint32_t>(high)];
    out[k + 3] = pixels[high >> 32];
  }
  return total;
}

// Perspective bilinear, four pixels per step: one packed division gives the four
// reciprocals of D, the 16.16 positions are products with them (as in the SSE2 loop).
// Handles the largest multiple of 4 pixels of the span and returns how many it wrote.
OFLAB_AVX2 int perspective_bilinear_quads(const SourceView& src, Pixel* out, int count, double nu,
                                          double nv, double d, double du, double dv, double dd) {
  const __m256i offset_weights = quad_offset_weights(src);
  // Locals, so that the stores to `out` cannot make the compiler reload them.
  const Pixel* const pixels = src.pixels;
  const std::int64_t stride = src.stride;
  QuadStep step(nu, nv, d, du, dv, dd, 0.0, 1 << kBlendWeightBits);
  const int total = count & ~3;
  for_each_quad(step, total, [=](int k, const __m256i& positions) OFLAB_AVX2 {
    blend_quad(pixels, stride, offset_weights, positions, out + k);
  });
  return total;
}

#endif

// Affine inner loop: fixed point with `shift` fractional bits, only additions.
template <bool kBilinear>
void affine_span(const SourceView& src, Pixel* out, int count, std::int64_t nu, std::int64_t nv,
                 std::int64_t du, std::int64_t dv, int shift) {
  if constexpr (!kBilinear) {
    for (int k = 0; k < count; ++k) {
      out[k] = *src.at(nu >> shift, nv >> shift);
      nu += du;
      nv += dv;
    }
  } else {
    const int to_16 = shift - kBlendWeightBits;
#if defined(OFLAB_WARP_SSE2)
    // Runs of up to kMaxApproximateRun pixels in 16.16 fixed point, two pixels per step,
    // each run starting from the exact position (truncated). Positions are below 2^30.
#if defined(OFLAB_WARP_AVX2)
    if (use_avx2()) {
      const int done = affine_bilinear_quads(src, out, count, nu, nv, du, dv, to_16);
      out += done;
      count -= done;
      nu += done * du;
      nv += done * dv;
    }
#endif
    const BilinearPairs pairs(src);
    const std::int64_t half = std::int64_t{1} << (to_16 - 1);
    const auto su = static_cast<std::int32_t>((2 * du + half) >> to_16);  // rounded
    const auto sv = static_cast<std::int32_t>((2 * dv + half) >> to_16);
    const __m128i step = _mm_set_epi32(sv, su, sv, su);
    for (int k = 0; k < count;) {
      const int run = std::min(count - k, kMaxApproximateRun);
      __m128i positions = _mm_set_epi32(static_cast<std::int32_t>((nv + dv) >> to_16),
                                        static_cast<std::int32_t>((nu + du) >> to_16),
                                        static_cast<std::int32_t>(nv >> to_16),
                                        static_cast<std::int32_t>(nu >> to_16));
      int j = 0;
      for (; j + 1 < run; j += 2) {
        pairs.blend(positions, out + k + j);
        positions = _mm_add_epi32(positions, step);
      }
      if (j < run) {
        out[k + j] = pairs.single(static_cast<std::uint32_t>((nu + j * du) >> to_16),
                                  static_cast<std::uint32_t>((nv + j * dv) >> to_16));
      }
      k += run;
      nu += run * du;
      nv += run * dv;
    }
#else
    for (int k = 0; k < count; ++k) {
      out[k] = blend_block(src.at(nu >> shift, nv >> shift), src.stride,
                           static_cast<std::uint32_t>(nu >> to_16) & kBlendWeightMask,
                           static_cast<std::uint32_t>(nv >> to_16) & kBlendWeightMask);
      nu += du;
      nv += dv;
    }
#endif
  }
}

// Perspective inner loops. Numerators and denominator are integers held exactly in
// double (inverse_map.h), so stepping them equals evaluating them; they are
// non-negative in a fast run, so truncation is the floor.
//
// The divider is the bottleneck of a per-pixel quotient, so the loops divide once per
// two pixels: one packed division gives the reciprocals (1/D_k, 1/D_k+1) of a pixel
// pair, and the four coordinates are products with them. For nearest sampling the
// floors must stay exact. The product y = (N + 1/2) * fl(1/D) differs from
// x = (N + 1/2) / D by at most x * 2^-52 (two roundings), while x lies at least 1/(2D)
// from every integer (N is an integer). So trunc(y) = floor(N / D) whenever
// (N + 1/2) * 2^-52 < 1/2, i.e. N + 1/2 < 2^51; runs whose numerators reach
// kMaxReciprocalNumerator (far from the origin of a large source with D near 2^37) use
// one correctly rounded division per pixel instead (inverse_map.h).
#if defined(OFLAB_WARP_SSE2)
constexpr double kMaxReciprocalNumerator = 1125899906842624.0;  // 2^50

// A pixel pair's numerators and denominators: lanes (pixel k, pixel k + 1).
struct PairStep {
  __m128d nu, nv, d;
  __m128d step_u, step_v, step_d;

  // Numerators `scale * (N + bias)` (exact: bias is 0 or 1/2, scale a power of two).
  PairStep(double n_u, double n_v, double den, double du, double dv, double dd, double bias,
           double scale)
      : nu(_mm_set_pd((n_u + du + bias) * scale, (n_u + bias) * scale)),
        nv(_mm_set_pd((n_v + dv + bias) * scale, (n_v + bias) * scale)),
        d(_mm_set_pd(den + dd, den)),
        step_u(_mm_set1_pd(2.0 * du * scale)),
        step_v(_mm_set1_pd(2.0 * dv * scale)),
        step_d(_mm_set1_pd(2.0 * dd)) {}

  // Truncated quotients of the pair as int32 lanes [u_k v_k u_k+1 v_k+1], then two
  // pixels to the right.
  __m128i next() {
    const __m128d r = _mm_div_pd(_mm_set1_pd(1.0), d);
    const __m128i u = _mm_cvttpd_epi32(_mm_mul_pd(nu, r));
    const __m128i v = _mm_cvttpd_epi32(_mm_mul_pd(nv, r));
    nu = _mm_add_pd(nu, step_u);
    nv = _mm_add_pd(nv, step_v);
    d = _mm_add_pd(d, step_d);
    return _mm_unpacklo_epi32(u, v);
  }
};

// Nearest sampling with one correctly rounded division per pixel (both coordinates in
// one packed division): exact for numerators up to 2^53 (inverse_map.h).
void perspective_nearest_divided(const SourceView& src, Pixel* out, int count, double nu, double nv,
                                 double d, double du, double dv, double dd) {
  __m128d numerators = _mm_set_pd(nv, nu);
  __m128d denominator = _mm_set1_pd(d);
  const __m128d numerator_step = _mm_set_pd(dv, du);
  const __m128d denominator_step = _mm_set1_pd(dd);
  for (int k = 0; k < count; ++k) {
    const __m128i floors = _mm_cvttpd_epi32(_mm_div_pd(numerators, denominator));
    numerators = _mm_add_pd(numerators, numerator_step);
    denominator = _mm_add_pd(denominator, denominator_step);
    out[k] = *src.at(_mm_cvtsi128_si32(floors), _mm_cvtsi128_si32(_mm_shuffle_epi32(floors, 1)));
  }
}

#if defined(OFLAB_WARP_AVX2)
// Moves the start of a perspective run `done` pixels to the right, past the pixels a
// wider loop has written.
void skip_pixels(int done, Pixel*& out, int& count, double& nu, double& nv, double& d, double du,
                 double dv, double dd) {
  out += done;
  count -= done;
  nu += done * du;
  nv += done * dv;
  d += done * dd;
}
#endif

template <bool kBilinear>
void perspective_span(const SourceView& src, Pixel* out, int count, double nu, double nv, double d,
                      double du, double dv, double dd) {
  if constexpr (!kBilinear) {
    // The numerators are linear along the row (and non-negative in a fast run): their
    // largest value is at an end.
    const double last = count - 1;
    const double numerator_max = std::max({nu, nu + last * du, nv, nv + last * dv});
    if (!(numerator_max + 0.5 < kMaxReciprocalNumerator)) {
      perspective_nearest_divided(src, out, count, nu, nv, d, du, dv, dd);
      return;
    }
#if defined(OFLAB_WARP_AVX2)
    if (use_avx2()) {
      const int done = perspective_nearest_quads(src, out, count, nu, nv, d, du, dv, dd);
      skip_pixels(done, out, count, nu, nv, d, du, dv, dd);
    }
#endif
    PairStep step(nu, nv, d, du, dv, dd, 0.5, 1.0);
    const PairOffsets pair_offsets(src);
    int k = 0;
    for (; k + 1 < count; k += 2) {
      const std::uint64_t offsets = pair_offsets(step.next());
      out[k] = src.pixels[static_cast<std::uint32_t>(offsets)];
      out[k + 1] = src.pixels[offsets >> 32];
    }
    if (k < count) {
      perspective_nearest_divided(src, out + k, 1, nu + k * du, nv + k * dv, d + k * dd, du, dv,
                                  dd);
    }
  } else {
    // Positions in 16.16 fixed point straight from the products: scaling the numerators
    // by 2^16 is exact, but the product, now up to 2^30, may land one unit of 2^-16 on
    // either side of the floor of the exact quotient: the same interpolated value to
    // 2^-16 (kBilinearLowMargin and kBilinearHighMargin cover the taps).
#if defined(OFLAB_WARP_AVX2)
    if (use_avx2()) {
      const int done = perspective_bilinear_quads(src, out, count, nu, nv, d, du, dv, dd);
      skip_pixels(done, out, count, nu, nv, d, du, dv, dd);
    }
#endif
    PairStep step(nu, nv, d, du, dv, dd, 0.0, 1 << kBlendWeightBits);
    const BilinearPairs pairs(src);
    // Software pipelining: the next pair's positions are computed before the current
    // pair's blend, so the blend never waits for the divider.
    __m128i next = step.next();
    int k = 0;
    for (; k + 1 < count; k += 2) {
      const __m128i positions = next;
      next = step.next();
      pairs.blend(positions, out + k);
    }
    if (k < count) {
      out[k] =
          pairs.single(static_cast<std::uint32_t>(_mm_cvtsi128_si32(next)),
                       static_cast<std::uint32_t>(_mm_cvtsi128_si32(_mm_shuffle_epi32(next, 1))));
    }
  }
}
#else
// Portable version: one correctly rounded division per coordinate (exact floors).
template <bool kBilinear>
void perspective_span(const SourceView& src, Pixel* out, int count, double nu, double nv, double d,
                      double du, double dv, double dd) {
  const double scale = 1 << kBlendWeightBits;
  for (int k = 0; k < count; ++k) {
    const double u = nu / d;
    const double v = nv / d;
    const auto iu = static_cast<std::int64_t>(u);
    const auto iv = static_cast<std::int64_t>(v);
    const Pixel* p = src.at(iu, iv);
    if constexpr (!kBilinear) {
      out[k] = *p;
    } else {
      const auto fx = static_cast<std::uint32_t>((u - static_cast<double>(iu)) * scale);
      const auto fy = static_cast<std::uint32_t>((v - static_cast<double>(iv)) * scale);
      out[k] = blend_block(p, src.stride, fx, fy);
    }
    nu += du;
    nv += dv;
    d += dd;
  }
}
#endif

// Output columns per strip. Fast runs are processed in vertical strips so that
// consecutive rows reuse the source cache lines, pages and TLB entries of the rows above:
// a rotation walks the source diagonally, and row by row across a whole 1920-pixel frame
// every output row touches about a thousand source rows. Narrow strips cost a run set-up
// per strip and row. Measured on the rotation cases of oflab-bench for 64, 128, 256, 512
// and unlimited columns (manual/warping.md): 512 is best or within noise of it on every
// case, and 2 to 3 times faster than unlimited for nearest 1920 x 1080.
constexpr int kStripWidth = 512;

// Rows per band of pass 2, so that a band's pixels (about kBandPixels) outweigh handing it
// to another thread.
constexpr int kBandPixels = 16384;
int min_band_rows(int width) { return std::max(8, kBandPixels / std::max(width, 1)); }

// Pixels [begin, end) of row y whose samples take the fast path.
struct FastRun {
  int y;
  int begin;
  int end;
};

// One fast run's pixels [begin, end) of row y into row[begin .. end - 1] (row[x] is output
// pixel x), stepping incrementally. One output pixel to the right adds 2 to X.
template <bool kAffine, bool kBilinear>
void fast_span(const SourceView& src, const InverseMap& map, Pixel* row, int y, int begin,
               int end) {
  const MapSample s = evaluate(map, begin, y);
  Pixel* out = row + begin;
  if constexpr (kAffine) {
    affine_span<kBilinear>(src, out, end - begin, s.nu, s.nv, 2 * map.a, 2 * map.d,
                           map.affine_shift);
  } else {
    perspective_span<kBilinear>(src, out, end - begin, static_cast<double>(s.nu),
                                static_cast<double>(s.nv), static_cast<double>(s.d),
                                static_cast<double>(2 * map.a), static_cast<double>(2 * map.d),
                                static_cast<double>(2 * map.g));
  }
}

// A fast run's pixels [begin, end) of row y under a partial warp (WarpOptions::only): the
// blocks counted from `begin` that hold a wanted pixel, each stretch of them in one call.
// Affine bilinear blocks are kPartialWarpBlock columns: a call that starts on a block
// boundary steps exactly as the whole run does there, as its loops restart from the exact
// position every kMaxApproximateRun (= kPartialWarpBlock) pixels of a call and go in quads
// from its start. Every other loop's pixel depends on its own exact numerators only (the
// nearest floors are exact, the perspective bilinear positions are one product per pixel of
// exact integers): blocks of one pixel. Returns the pixels computed (recorded, record_computed).
template <bool kAffine, bool kBilinear>
std::int64_t partial_run(const SourceView& src, const WarpPlan& plan, Pixel* row, int y, int begin,
                         int end) {
  static_assert(kPartialWarpBlock == kMaxApproximateRun, "blocks start where runs restart");
  const PixelRows* only = plan.only;
  if (!only) {
    fast_span<kAffine, kBilinear>(src, plan.map, row, y, begin, end);
    return end - begin;
  }
  std::int64_t done = 0;
  const int block = kAffine && kBilinear ? kPartialWarpBlock : 1;
  int from = begin, to = begin;  // the stretch to compute, pending
  for (const ColumnRun& r : only->row(y + plan.origin_y)) {
    int lo = std::max(begin, r.begin - plan.origin_x);
    int hi = std::min(end, r.end - plan.origin_x);
    if (lo >= hi) continue;
    lo = begin + (lo - begin) / block * block;  // out to the blocks' bounds
    hi = std::min(end, begin + (hi - begin + block - 1) / block * block);
    if (lo > to) {
      if (to > from) fast_span<kAffine, kBilinear>(src, plan.map, row, y, from, to);
      record_computed(plan, y, from, to);
      done += to - from;
      from = lo;
    }
    to = std::max(to, hi);
  }
  if (to > from) fast_span<kAffine, kBilinear>(src, plan.map, row, y, from, to);
  record_computed(plan, y, from, to);
  done += to - from;
  return done;
}

// Pass 1 of a span: its fast run, the pixels between the ends whose samples need clamping
// (rounding of the polygon at the source border, bilinear taps beyond it). The floor of a
// linear or linear-fractional function is monotone along a row, so the rest is one
// contiguous run that needs no checks. An empty run (no pixel fast) is [x_end, x_end).
template <bool kBilinear>
FastRun fast_run_of(const SourceView& src, const InverseMap& map, bool fast_allowed,
                    const PixelSpan& span) {
  int begin = span.x_begin;
  int end = span.x_end;
  while (begin < end &&
         !(fast_allowed && in_fast_range<kBilinear>(src, evaluate(map, begin, span.y))))
    ++begin;
  while (end > begin && !in_fast_range<kBilinear>(src, evaluate(map, end - 1, span.y))) --end;
  return FastRun{span.y, begin, end};
}

// The clamped ends of a span (pixels outside its fast run `r`) into row[x], those a partial
// warp wants (recorded, record_computed). Returns the pixels sampled.
template <bool kBilinear>
std::int64_t sample_ends(const SourceView& src, const WarpPlan& plan, const PixelSpan& span,
                         const FastRun& r, Pixel* row) {
  std::int64_t ends = 0;
  const auto clamped = [&](int x) {
    const int fx = x + plan.origin_x;
    if (plan.only && !plan.only->any(span.y + plan.origin_y, fx, fx + 1)) return;
    row[x] = sample_clamped<kBilinear>(src, evaluate(plan.map, x, span.y), plan.map.affine_shift);
    if (plan.only) record_computed(plan, span.y, x, x + 1);
    ++ends;
  };
  for (int x = span.x_begin; x < r.begin; ++x) clamped(x);
  for (int x = std::max(r.begin, r.end); x < span.x_end; ++x) clamped(x);
  return ends;
}

// The piece of fast run `r` in the strip of kStripWidth columns from x0, into row[x] (row[x]
// is output pixel x of row r.y). Returns the pixels computed.
template <bool kAffine, bool kBilinear>
std::int64_t strip_piece(const SourceView& src, const WarpPlan& plan, const FastRun& r, int x0,
                         Pixel* row) {
  const int begin = std::max(r.begin, x0);
  const int end = std::min(r.end, x0 + kStripWidth);
  return begin < end ? partial_run<kAffine, kBilinear>(src, plan, row, r.y, begin, end) : 0;
}

// The pieces of fast run `r` in the strips of kStripWidth columns from strip_begin, into
// row[x]. Returns the pixels computed.
template <bool kAffine, bool kBilinear>
std::int64_t strip_pieces(const SourceView& src, const WarpPlan& plan, const FastRun& r,
                          int strip_begin, Pixel* row) {
  std::int64_t done = 0;
  for (int x0 = strip_begin; x0 < r.end; x0 += kStripWidth)
    done += strip_piece<kAffine, kBilinear>(src, plan, r, x0, row);
  return done;
}

template <bool kAffine, bool kBilinear>
std::int64_t run(const WarpPlan& plan, const Image& source, Image& output, std::int64_t* computed) {
  const SourceView src = source_view(source);
  const bool fast_allowed = kAffine || steps_exact_in_double(plan.map);

  // Pass 1: scan conversion (two active edges per row); the clamped ends of each span are
  // sampled here, its fast run kept for pass 2.
  ScanConverter scan(plan.polygon, output.width(), output.height());
  std::vector<FastRun> runs;
  runs.reserve(static_cast<std::size_t>(std::max(scan.end_row() - scan.first_row(), 0)));
  std::int64_t written = 0, ends = 0;
  int strip_begin = output.width();
  int strip_end = 0;
  PixelSpan span;
  while (scan.next(span)) {
    if (span.x_begin >= span.x_end) continue;
    written += span.x_end - span.x_begin;
    const FastRun r = fast_run_of<kBilinear>(src, plan.map, fast_allowed, span);
    ends += sample_ends<kBilinear>(src, plan, span, r, output.row(span.y));
    if (r.begin >= r.end) continue;
    runs.push_back(r);
    strip_begin = std::min(strip_begin, r.begin);
    strip_end = std::max(strip_end, r.end);
  }
  if (computed) *computed += ends;
  if (runs.empty()) return written;

  // Pass 2: the runs, strip by strip, in bands of rows on the worker threads (each band
  // writes its own rows only).
  std::atomic<std::int64_t> run_pixels{0};
  const auto band = [&](int, int first, int last) {
    std::int64_t done = 0;
    for (int x0 = strip_begin; x0 < strip_end; x0 += kStripWidth) {
      for (int k = first; k < last; ++k) {
        const FastRun& r = runs[static_cast<std::size_t>(k)];
        done += strip_piece<kAffine, kBilinear>(src, plan, r, x0, output.row(r.y));
      }
    }
    run_pixels += done;
  };
  const int rows = static_cast<int>(runs.size());
  for_each_band(rows, min_band_rows(strip_end - strip_begin), band);
  if (computed) *computed += run_pixels;
  return written;
}

}  // namespace

void run_bilinear_row(const InverseMap& map, const Image& source, int y, int x_begin, int x_end,
                      Pixel* out) {
  const SourceView src = source_view(source);
  const bool fast_allowed = steps_exact_in_double(map);
  Pixel* row = out - x_begin;  // row[x] is output pixel x
  int begin = x_begin, end = x_end;
  for (; begin < end; ++begin) {  // pass 1's clamped ends, as in run()
    const MapSample s = evaluate(map, begin, y);
    if (fast_allowed && in_fast_range<true>(src, s)) break;
    row[begin] = sample_clamped<true>(src, s, map.affine_shift);
  }
  for (; end > begin; --end) {
    const MapSample last = evaluate(map, end - 1, y);
    if (in_fast_range<true>(src, last)) break;
    row[end - 1] = sample_clamped<true>(src, last, map.affine_shift);
  }
  if (begin >= end) return;
  const MapSample s = evaluate(map, begin, y);
  perspective_span<true>(src, row + begin, end - begin, static_cast<double>(s.nu),
                         static_cast<double>(s.nv), static_cast<double>(s.d),
                         static_cast<double>(2 * map.a), static_cast<double>(2 * map.d),
                         static_cast<double>(2 * map.g));
}

AffineBilinearLevel::AffineBilinearLevel(const WarpPlan& plan, const Image& source)
    : plan_(plan), source_(source), strip_begin_(plan.output_width) {}

void AffineBilinearLevel::add(const PixelSpan& span) {
  const FastRun r = fast_run_of<true>(source_view(source_), plan_.map, true, span);
  runs_.push_back(Run{span, r.begin, r.end});
  if (r.begin < r.end) strip_begin_ = std::min(strip_begin_, r.begin);
}

std::int64_t AffineBilinearLevel::sample(int k, Pixel* row) const {
  const Run& run = runs_[static_cast<std::size_t>(k)];
  const SourceView src = source_view(source_);
  const FastRun r{run.span.y, run.fast_begin, run.fast_end};
  std::int64_t done = sample_ends<true>(src, plan_, run.span, r, row);
  if (r.begin < r.end) done += strip_pieces<true, true>(src, plan_, r, strip_begin_, row);
  return done;
}

bool warp_avx2_enabled() {
#if defined(OFLAB_WARP_AVX2)
  return use_avx2();
#else
  return false;
#endif
}

std::int64_t run_warp_kernel(const WarpPlan& plan, const Image& source, Image& output,
                             std::int64_t* computed) {
  if (plan.empty || source.empty() || output.empty()) return 0;
  const bool bilinear = plan.sampling == Sampling::kBilinear;
  if (plan.affine_kernel) {
    return bilinear ? run<true, true>(plan, source, output, computed)
                    : run<true, false>(plan, source, output, computed);
  }
  return bilinear ? run<false, true>(plan, source, output, computed)
                  : run<false, false>(plan, source, output, computed);
}

}  // namespace oflab
