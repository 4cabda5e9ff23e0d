// Affine and perspective warp kernels, nearest and bilinear (dissertation appendix A.1,
// errata 28-30 fixed). See warp_kernels.h for the scheme and inverse_map.h for the exact
// definition of the sampling position that every nearest loop here reproduces bit for
// bit; the bilinear loops stay within a few thousandths of a pixel of it.
#include "core/warp_kernels.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/bilinear_blend.h"  // also provides OFLAB_WARP_SSE2 and <emmintrin.h>
#include "core/scan_conversion.h"

namespace oflab {
namespace {

struct SourceView {
  const Pixel* pixels;
  std::int64_t stride;
  std::int64_t max_x;  // width - 1
  std::int64_t max_y;  // height - 1
  const Pixel* at(std::int64_t x, std::int64_t y) const { return pixels + y * stride + x; }
};

// Bilinear fast loops do not use the exact floor: the perspective one may round it up by
// one, the affine one steps in 16.16 fixed point and may be off by one either way. The
// fast range keeps this margin on both sides, plus one column (row) for the second tap.
constexpr std::int64_t kBilinearLowMargin = 1;
constexpr std::int64_t kBilinearHighMargin = 2;

// Longest run an affine bilinear loop steps in 16.16 fixed point before it restarts from
// the exact 64-bit position: the rounding of the step then moves the position by at most
// 32 * 2^-17 = 2^-12 pixel, at most a quarter level of difference in the result.
constexpr int kMaxApproximateRun = 64;

// Exact sample with clamping, for the pixels at the ends of a span.
template <bool kBilinear>
Pixel sample_clamped(const SourceView& src, MapSample s) {
  if (s.d <= 0) s.d = 1;  // unreachable: make_inverse_map guarantees D > 0
  const std::int64_t ku = floor_div(s.nu, s.d);
  const std::int64_t kv = floor_div(s.nv, s.d);
  if constexpr (!kBilinear) {
    return *src.at(std::clamp<std::int64_t>(ku, 0, src.max_x),
                   std::clamp<std::int64_t>(kv, 0, src.max_y));
  } else {
    const auto fx = static_cast<std::uint32_t>(((s.nu - ku * s.d) << kBlendWeightBits) / s.d);
    const auto fy = static_cast<std::uint32_t>(((s.nv - kv * s.d) << kBlendWeightBits) / s.d);
    const std::int64_t x0 = std::clamp<std::int64_t>(ku, 0, src.max_x);
    const std::int64_t x1 = std::clamp<std::int64_t>(ku + 1, 0, src.max_x);
    const std::int64_t y0 = std::clamp<std::int64_t>(kv, 0, src.max_y);
    const std::int64_t y1 = std::clamp<std::int64_t>(kv + 1, 0, src.max_y);
    return blend_taps(src.at(x0, y0), src.at(x1, y0), src.at(x0, y1), src.at(x1, y1), fx, fy);
  }
}

// True if the sample may take the fast path (no tap needs clamping).
template <bool kBilinear>
bool in_fast_range(const SourceView& src, const MapSample& s) {
  if (s.d <= 0) return false;
  const std::int64_t ku = floor_div(s.nu, s.d);
  const std::int64_t kv = floor_div(s.nv, s.d);
  const std::int64_t low = kBilinear ? kBilinearLowMargin : 0;
  const std::int64_t high = kBilinear ? kBilinearHighMargin : 0;
  return ku >= low && kv >= low && ku + high <= src.max_x && kv + high <= src.max_y;
}

#if defined(OFLAB_WARP_SSE2)
// Bilinear step shared by both kernels: two pixels' positions [u_a v_a u_b v_b] in 16.16
// fixed point (int32 lanes) -> offsets through one multiply-add of (u, v) as 16-bit pairs
// with (1, stride), weights from the low 16 bits, one blend for both pixels.
struct BilinearPairs {
  const SourceView& src;
  __m128i offset_weights;

  explicit BilinearPairs(const SourceView& s)
      : src(s),
        offset_weights(
            _mm_set1_epi32(static_cast<int>((static_cast<std::uint32_t>(s.stride) << 16) | 1u))) {}

  void blend(__m128i positions, Pixel* out) const {
    const __m128i whole = _mm_srai_epi32(positions, kBlendWeightBits);
    const __m128i offsets = _mm_madd_epi16(_mm_packs_epi32(whole, whole), offset_weights);
    const auto pair = static_cast<std::uint64_t>(_mm_cvtsi128_si64(offsets));
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

// Perspective inner loop: numerators and denominator are integers held exactly in
// double, so stepping them equals evaluating them, and the correctly rounded quotients
// have the exact floors (inverse_map.h). They are non-negative here, so truncation is the
// floor. Both quotients of a pixel come from one packed division where SSE2 is available.
#if defined(OFLAB_WARP_SSE2)
struct PerspectiveStep {
  __m128d numerators;   // (Nu, Nv), possibly times a power of two (exact)
  __m128d denominator;  // (D, D)
  __m128d numerator_step;
  __m128d denominator_step;

  // Truncated quotients in int32 lanes 0 and 1, then one step to the right.
  __m128i next() {
    const __m128d q = _mm_div_pd(numerators, denominator);
    numerators = _mm_add_pd(numerators, numerator_step);
    denominator = _mm_add_pd(denominator, denominator_step);
    return _mm_cvttpd_epi32(q);
  }
};

template <bool kBilinear>
void perspective_span(const SourceView& src, Pixel* out, int count, double nu, double nv, double d,
                      double du, double dv, double dd) {
  if constexpr (!kBilinear) {
    PerspectiveStep step{_mm_set_pd(nv, nu), _mm_set1_pd(d), _mm_set_pd(dv, du), _mm_set1_pd(dd)};
    for (int k = 0; k < count; ++k) {
      const __m128i floors = step.next();
      out[k] = *src.at(_mm_cvtsi128_si32(floors), _mm_cvtsi128_si32(_mm_shuffle_epi32(floors, 1)));
    }
  } else {
    // Positions in 16.16 fixed point straight from the division: scaling the numerators
    // by 2^16 is exact, but the quotient, now up to 2^30, may round up onto the next
    // multiple of 2^16, i.e. take the floor one too high with a weight near 0 instead of
    // near 1 for the pixel below: the same value to 2^-16 (kBilinearHighMargin covers it).
    const double scale = 1 << kBlendWeightBits;
    PerspectiveStep step{_mm_set_pd(nv * scale, nu * scale), _mm_set1_pd(d),
                         _mm_set_pd(dv * scale, du * scale), _mm_set1_pd(dd)};
    const BilinearPairs pairs(src);
    // Software pipelining: the divisions for the next two pixels are issued before the
    // blend of the current two, so the blend never waits for the divider (measured: the
    // bilinear perspective kernel went from 2.6x to 2.0x the nearest one).
    __m128i next_a = step.next();
    __m128i next_b = step.next();
    int k = 0;
    for (; k + 1 < count; k += 2) {
      const __m128i positions = _mm_unpacklo_epi64(next_a, next_b);
      next_a = step.next();
      next_b = step.next();
      pairs.blend(positions, out + k);
    }
    if (k < count) {
      out[k] =
          pairs.single(static_cast<std::uint32_t>(_mm_cvtsi128_si32(next_a)),
                       static_cast<std::uint32_t>(_mm_cvtsi128_si32(_mm_shuffle_epi32(next_a, 1))));
    }
  }
}
#else
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

// Largest step that double can hold exactly together with the running sums.
constexpr std::int64_t kMaxExactStep = std::int64_t{1} << 51;

bool steps_exact_in_double(const InverseMap& m) {
  for (std::int64_t c : {m.a, m.d, m.g}) {
    if (c >= kMaxExactStep || c <= -kMaxExactStep) return false;
  }
  return true;
}

// Output columns per strip. Fast runs are processed in vertical strips so that
// consecutive rows reuse the source cache lines and pages of the rows above: a rotation
// walks the source diagonally, and row by row over a whole frame every output pixel
// would touch a new source row. A strip is sized to touch about 24 source rows per output
// row (from the map's rows-per-pixel slope), between 32 and 512 columns; measured in
// manual/warping.md.
int strip_width(const InverseMap& map, const MapSample& sample) {
  const double rows_per_pixel =
      std::abs(2.0 * static_cast<double>(map.d) * static_cast<double>(sample.d) -
               2.0 * static_cast<double>(map.g) * static_cast<double>(sample.nv)) /
      (static_cast<double>(sample.d) * static_cast<double>(sample.d));
  const double width = 24.0 / std::max(rows_per_pixel, 1e-9);
  return static_cast<int>(std::clamp(width, 32.0, 512.0));
}

// Pixels [begin, end) of row y whose samples take the fast path.
struct FastRun {
  int y;
  int begin;
  int end;
};

template <bool kAffine, bool kBilinear>
std::int64_t run(const WarpPlan& plan, const Image& source, Image& output) {
  const SourceView src{source.pixels().data(), source.width(), source.width() - 1,
                       source.height() - 1};
  const InverseMap& map = plan.map;
  const bool fast_allowed = kAffine || steps_exact_in_double(map);

  // Pass 1: scan conversion (two active edges per row). The ends of each span whose
  // samples need clamping (rounding of the polygon at the source border, bilinear taps
  // beyond it) are done here; the floor of a linear or linear-fractional function is
  // monotone along a row, so the rest is one contiguous run that needs no checks.
  ScanConverter scan(plan.polygon, output.width(), output.height());
  std::vector<FastRun> runs;
  runs.reserve(static_cast<std::size_t>(std::max(scan.end_row() - scan.first_row(), 0)));
  std::int64_t written = 0;
  int strip_begin = output.width();
  int strip_end = 0;
  PixelSpan span;
  while (scan.next(span)) {
    int begin = span.x_begin;
    int end = span.x_end;
    if (begin >= end) continue;
    written += end - begin;
    Pixel* out = output.row(span.y);
    MapSample s = evaluate(map, begin, span.y);
    while (begin < end && !(fast_allowed && in_fast_range<kBilinear>(src, s))) {
      out[begin] = sample_clamped<kBilinear>(src, s);
      if (++begin < end) s = evaluate(map, begin, span.y);
    }
    while (end > begin) {
      const MapSample last = evaluate(map, end - 1, span.y);
      if (in_fast_range<kBilinear>(src, last)) break;
      out[end - 1] = sample_clamped<kBilinear>(src, last);
      --end;
    }
    if (begin >= end) continue;
    runs.push_back(FastRun{span.y, begin, end});
    strip_begin = std::min(strip_begin, begin);
    strip_end = std::max(strip_end, end);
  }
  if (runs.empty()) return written;

  // Pass 2: the runs, strip by strip. One output pixel to the right adds 2 to X.
  const FastRun& middle = runs[runs.size() / 2];
  const int strip = strip_width(map, evaluate(map, (middle.begin + middle.end) / 2, middle.y));
  const std::int64_t step_u = 2 * map.a;
  const std::int64_t step_v = 2 * map.d;
  const std::int64_t step_d = 2 * map.g;
  for (int x0 = strip_begin; x0 < strip_end; x0 += strip) {
    const int x1 = std::min(x0 + strip, strip_end);
    for (const FastRun& r : runs) {
      const int begin = std::max(r.begin, x0);
      const int end = std::min(r.end, x1);
      if (begin >= end) continue;
      const MapSample s = evaluate(map, begin, r.y);
      Pixel* out = output.row(r.y) + begin;
      if constexpr (kAffine) {
        affine_span<kBilinear>(src, out, end - begin, s.nu, s.nv, step_u, step_v, map.affine_shift);
      } else {
        perspective_span<kBilinear>(src, out, end - begin, static_cast<double>(s.nu),
                                    static_cast<double>(s.nv), static_cast<double>(s.d),
                                    static_cast<double>(step_u), static_cast<double>(step_v),
                                    static_cast<double>(step_d));
      }
    }
  }
  return written;
}

}  // namespace

std::int64_t run_warp_kernel(const WarpPlan& plan, const Image& source, Image& output) {
  if (plan.empty || source.empty() || output.empty()) return 0;
  const bool bilinear = plan.sampling == Sampling::kBilinear;
  if (plan.affine_kernel) {
    return bilinear ? run<true, true>(plan, source, output)
                    : run<true, false>(plan, source, output);
  }
  return bilinear ? run<false, true>(plan, source, output)
                  : run<false, false>(plan, source, output);
}

}  // namespace oflab
