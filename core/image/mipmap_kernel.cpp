// The mipmap warp kernel (Williams 83; dissertation section 7.5.5). See mipmap_kernel.h.
#include "image/mipmap_kernel.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <vector>

#include "image/bilinear_blend.h"  // blend_taps, and OFLAB_WARP_SSE2 with <emmintrin.h>
#include "image/mip_row_levels.h"
#include "image/scan_conversion.h"
#include "image/thread_pool.h"
#include "image/trilinear_row.h"
#include "image/warp_kernels.h"
#include "image/warp_row_loop.h"  // lerp_lanes, store_quad and OFLAB_WARP_AVX2

namespace oflab {
namespace {

// Rows per band, as the other kernels' pass 2 (about 16384 pixels a band).
int min_band_rows(int width) { return std::max(8, 16384 / std::max(width, 1)); }

// The trilinear weight of the upper level in 1/256: frac(level) rounded; `lower` is then
// the lower level (the weight 256 moves to the next level with weight 0).
struct LevelPair {
  int lower = 0;
  int weight = 0;  // 0..255
};

LevelPair level_pair(double level) {
  LevelPair pair;
  pair.lower = static_cast<int>(std::floor(level));
  pair.weight = static_cast<int>(std::lround((level - pair.lower) * 256.0));
  if (pair.weight >= 256) {
    ++pair.lower;
    pair.weight = 0;
  }
  return pair;
}

// (a * (256 - w) + b * w + 128) / 256 per channel, rounded.
Pixel lerp_pixel(const Pixel& a, const Pixel& b, int w) {
  const int v = 256 - w;
  auto channel = [&](std::uint8_t Pixel::*c) {
    return static_cast<std::uint8_t>((a.*c * v + b.*c * w + 128) >> 8);
  };
  return Pixel{channel(&Pixel::r), channel(&Pixel::g), channel(&Pixel::b), channel(&Pixel::a)};
}

#if defined(OFLAB_WARP_AVX2)
// lerp_run's largest multiple of 4 pixels, four a step (lerp_lanes: lerp_pixel's bytes).
// Returns how many it blended.
OFLAB_AVX2 int lerp_quads(Pixel* out, const Pixel* upper, int count, int w) {
  const __m256i weight = _mm256_set1_epi16(static_cast<short>(128 * w));
  const int total = count & ~3;
  for (int k = 0; k < total; k += 4) {
    const __m256i a =
        _mm256_cvtepu8_epi16(_mm_loadu_si128(reinterpret_cast<const __m128i*>(out + k)));
    const __m256i b =
        _mm256_cvtepu8_epi16(_mm_loadu_si128(reinterpret_cast<const __m128i*>(upper + k)));
    warp_row::store_quad(warp_row::lerp_lanes(a, b, weight), out + k);
  }
  return total;
}
#endif

// out[k] = lerp_pixel(out[k], upper[k], w) for k < count.
void lerp_run(Pixel* out, const Pixel* upper, int count, int w) {
  int k = 0;
#if defined(OFLAB_WARP_AVX2)
  if (warp_row::use_avx2()) k = lerp_quads(out, upper, count, w);
#endif
#if defined(OFLAB_WARP_SSE2)
  const __m128i zero = _mm_setzero_si128();
  const __m128i wa = _mm_set1_epi16(static_cast<short>(256 - w));
  const __m128i wb = _mm_set1_epi16(static_cast<short>(w));
  const __m128i half = _mm_set1_epi16(128);
  const auto lerp8 = [&](__m128i a, __m128i b) {
    const __m128i sum = _mm_add_epi16(_mm_mullo_epi16(a, wa), _mm_mullo_epi16(b, wb));
    return _mm_srli_epi16(_mm_add_epi16(sum, half), 8);
  };
  for (; k + 4 <= count; k += 4) {
    const __m128i a = _mm_loadu_si128(reinterpret_cast<const __m128i*>(out + k));
    const __m128i b = _mm_loadu_si128(reinterpret_cast<const __m128i*>(upper + k));
    const __m128i low = lerp8(_mm_unpacklo_epi8(a, zero), _mm_unpacklo_epi8(b, zero));
    const __m128i high = lerp8(_mm_unpackhi_epi8(a, zero), _mm_unpackhi_epi8(b, zero));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out + k), _mm_packus_epi16(low, high));
  }
#endif
  for (; k < count; ++k) out[k] = lerp_pixel(out[k], upper[k], w);
}

// The spans of the plan's polygon in the output (the pixels every kernel writes).
std::vector<PixelSpan> output_spans(const WarpPlan& plan) {
  std::vector<PixelSpan> spans;
  ScanConverter scan(plan.polygon, plan.output_width, plan.output_height);
  PixelSpan span;
  while (scan.next(span)) {
    if (span.x_begin < span.x_end) spans.push_back(span);
  }
  return spans;
}

// Calls fn(x_begin, x_end) for each stretch of the span's columns a partial warp wants
// (plan.only, in destination pixels: output pixel plus the plan's origin), or for the whole
// span without one, noting each stretch of a partial warp as computed (record_computed).
// Returns the pixels it covered.
template <typename Fn>
std::int64_t for_each_wanted(const WarpPlan& plan, const PixelSpan& span, Fn fn) {
  if (plan.only == nullptr) {
    fn(span.x_begin, span.x_end);
    return span.x_end - span.x_begin;
  }
  std::int64_t count = 0;
  for (const ColumnRun& r : plan.only->row(span.y + plan.origin_y)) {
    const int begin = std::max(span.x_begin, r.begin - plan.origin_x);
    const int end = std::min(span.x_end, r.end - plan.origin_x);
    if (begin >= end) continue;
    fn(begin, end);
    record_computed(plan, span.y, begin, end);
    count += end - begin;
  }
  return count;
}

// The region the plan samples: its polygon clipped to the output.
ConvexPolygon sampled_region(const WarpPlan& plan) {
  return clip_to_box(plan.polygon, BoundingBox{0.0, 0.0, static_cast<double>(plan.output_width),
                                               static_cast<double>(plan.output_height)});
}

// The plan of level k's bilinear warp: the same output pixels, positions scaled by 2^-k.
WarpPlan level_plan(const WarpPlan& plan, int k) {
  WarpPlan level = plan;
  level.sampling = Sampling::kBilinear;
  if (k == 0) return level;  // plan.map is level 0's bilinear map already
  const double scale = std::ldexp(1.0, -k);
  Mat3 to_level = translation_matrix(-0.5, -0.5) *
                  mat3_from_rows({scale, 0.0, 0.0}, {0.0, scale, 0.0}, {0.0, 0.0, 1.0}) *
                  plan.dest_to_source;
  if (plan.affine_kernel) {
    entry(to_level, 2, 0) = 0.0;
    entry(to_level, 2, 1) = 0.0;
    entry(to_level, 2, 2) = 1.0;
  }
  level.map = make_inverse_map(to_level, sampled_region(plan), plan.affine_kernel);
  return level;
}

const Image& level_image(const Image& source, const MipPyramid& pyramid, int k) {
  return k == 0 ? source : pyramid.level(k);
}

// True if an affine blend samples level k's bordered copy: every level but 0 when the
// pyramid has its copies.
bool samples_bordered(const MipPyramid& pyramid, int k) { return k > 0 && pyramid.has_borders(); }

// The image an affine blend samples for level k: its bordered copy, or the level.
const Image& sampled_image(const Image& source, const MipPyramid& pyramid, int k) {
  return samples_bordered(pyramid, k) ? pyramid.bordered_level(k) : level_image(source, pyramid, k);
}

// Level k's affine bilinear plan on the image sampled_image gives: on a bordered copy each
// position moves by kMipBorder texels on both axes, exactly (the affine form's D is the
// constant i, so kMipBorder * i is added to both numerators' constants). The taps of every
// pixel of the plan's polygon then stay inside the copy (positions in [-1/2, w - 1/2] on
// the level, [kMipBorder - 1/2, w + kMipBorder - 1/2] on the copy, within the bilinear
// loops' margins of 1 and 2 texels), so no span has ends sampled one by one, and each tap
// reads the texel the level's clamping gives.
WarpPlan bordered_level_plan(const WarpPlan& plan, const MipPyramid& pyramid, int k) {
  WarpPlan level = level_plan(plan, k);
  level.computed = nullptr;  // its samples go to rows of the blend's, not to the output
  if (samples_bordered(pyramid, k)) {
    level.map.c += kMipBorder * level.map.i;
    level.map.f += kMipBorder * level.map.i;
  }
  return level;
}

// An affine warp between two levels, in one pass: per span, the lower level's samples go
// into the output row (in a partial warp into a row of this thread's, as its blocks may hold
// pixels that are not wanted), the upper level's into another row of this thread's, and the
// wanted pixels are blended in the output row while both rows are in the cache. The bytes of
// sampling each level alone with the bilinear kernel (AffineBilinearLevel) and blending them.
std::int64_t run_affine_blend(const WarpPlan& plan, const Image& source, const MipPyramid& pyramid,
                              const LevelPair& pair, Image& output, std::int64_t* computed) {
  const WarpPlan lower_plan = bordered_level_plan(plan, pyramid, pair.lower);
  const WarpPlan upper_plan = bordered_level_plan(plan, pyramid, pair.lower + 1);
  AffineBilinearLevel lower(lower_plan, sampled_image(source, pyramid, pair.lower));
  AffineBilinearLevel upper(upper_plan, sampled_image(source, pyramid, pair.lower + 1));
  const std::vector<PixelSpan> spans = output_spans(plan);
  std::int64_t written = 0;
  for (const PixelSpan& span : spans) {
    lower.add(span);
    upper.add(span);
    written += span.x_end - span.x_begin;
  }
  const auto width = static_cast<std::size_t>(plan.output_width);
  std::atomic<std::int64_t> blended{0};
  for_each_band(static_cast<int>(spans.size()), min_band_rows(plan.output_width),
                [&](int, int first, int last) {
                  thread_local std::vector<Pixel> rows;  // memory kept from warp to warp
                  rows.resize(2 * width);
                  Pixel* const lower_row = rows.data();
                  Pixel* const upper_row = rows.data() + width;
                  std::int64_t count = 0;
                  for (int s = first; s < last; ++s) {
                    const PixelSpan& span = spans[static_cast<std::size_t>(s)];
                    Pixel* const out = output.row(span.y);
                    lower.sample(s, plan.only ? lower_row : out);
                    upper.sample(s, upper_row);
                    count += for_each_wanted(plan, span, [&](int begin, int end) {
                      if (plan.only) std::copy(lower_row + begin, lower_row + end, out + begin);
                      lerp_run(out + begin, upper_row + begin, end - begin, pair.weight);
                    });
                  }
                  blended += count;
                });
  if (computed) *computed += blended;
  return written;
}

// Affine: one level pair for the whole warp; one level alone is the bilinear kernel on it.
std::int64_t run_affine(const WarpPlan& plan, const Image& source, const MipPyramid& pyramid,
                        Image& output, std::int64_t* computed) {
  const Mat3& h = plan.dest_to_source;
  const LevelPair pair = level_pair(
      mip_level(entry(h, 0, 0), entry(h, 0, 1), entry(h, 1, 0), entry(h, 1, 1), pyramid.top()));
  if (pair.weight != 0) return run_affine_blend(plan, source, pyramid, pair, output, computed);
  return run_warp_kernel(level_plan(plan, pair.lower), level_image(source, pyramid, pair.lower),
                         output, computed);
}

// An upper bound of the footprint axis over the region of a perspective plan: the inverse
// map's Jacobian is N(x) / D(x)^2 with N affine in x, so |N|_F (convex) is largest and D
// (linear, positive) smallest at a vertex.
double footprint_bound(const Mat3& h, const ConvexPolygon& region) {
  double largest_n = 0.0;
  double smallest_d = std::numeric_limits<double>::infinity();
  for (const Vec2& p : region.vertices()) {
    const double d = entry(h, 2, 0) * p.x + entry(h, 2, 1) * p.y + entry(h, 2, 2);
    const double nu = entry(h, 0, 0) * p.x + entry(h, 0, 1) * p.y + entry(h, 0, 2);
    const double nv = entry(h, 1, 0) * p.x + entry(h, 1, 1) * p.y + entry(h, 1, 2);
    double norm = 0.0;
    for (int c = 0; c < 2; ++c) {
      const double ju = entry(h, 0, c) * d - nu * entry(h, 2, c);
      const double jv = entry(h, 1, c) * d - nv * entry(h, 2, c);
      norm += ju * ju + jv * jv;
    }
    largest_n = std::max(largest_n, std::sqrt(norm));
    smallest_d = std::min(smallest_d, d);
  }
  if (!(smallest_d > 0.0)) return std::numeric_limits<double>::infinity();
  return largest_n / (smallest_d * smallest_d);
}

// Bilinear sample of `image` at (u, v) in pixel-centre index coordinates, taps clamped to
// the image; weights truncated to 2^-16 as in the kernels.
Pixel bilinear_clamped(const Image& image, double u, double v) {
  u = std::clamp(u, -1.0, static_cast<double>(image.width()));
  v = std::clamp(v, -1.0, static_cast<double>(image.height()));
  const double fu = std::floor(u);
  const double fv = std::floor(v);
  const auto fx = std::min(static_cast<std::uint32_t>((u - fu) * 65536.0), kBlendWeightMask);
  const auto fy = std::min(static_cast<std::uint32_t>((v - fv) * 65536.0), kBlendWeightMask);
  const int max_x = image.width() - 1;
  const int max_y = image.height() - 1;
  const int x0 = std::clamp(static_cast<int>(fu), 0, max_x);
  const int x1 = std::clamp(static_cast<int>(fu) + 1, 0, max_x);
  const int y0 = std::clamp(static_cast<int>(fv), 0, max_y);
  const int y1 = std::clamp(static_cast<int>(fv) + 1, 0, max_y);
  return blend_taps(&image.at(x0, y0), &image.at(x1, y0), &image.at(x0, y1), &image.at(x1, y1), fx,
                    fy);
}

// One output pixel at (x, y) of a perspective plan: its own level, trilinear.
Pixel trilinear_pixel(const Mat3& h, const Image& source, const MipPyramid& pyramid, int x, int y) {
  const double px = x + 0.5, py = y + 0.5;
  const double d = entry(h, 2, 0) * px + entry(h, 2, 1) * py + entry(h, 2, 2);
  const double su = (entry(h, 0, 0) * px + entry(h, 0, 1) * py + entry(h, 0, 2)) / d;
  const double sv = (entry(h, 1, 0) * px + entry(h, 1, 1) * py + entry(h, 1, 2)) / d;
  const double j00 = (entry(h, 0, 0) - su * entry(h, 2, 0)) / d;
  const double j01 = (entry(h, 0, 1) - su * entry(h, 2, 1)) / d;
  const double j10 = (entry(h, 1, 0) - sv * entry(h, 2, 0)) / d;
  const double j11 = (entry(h, 1, 1) - sv * entry(h, 2, 1)) / d;
  const LevelPair pair = level_pair(mip_level(j00, j01, j10, j11, pyramid.top()));
  const double scale = std::ldexp(1.0, -pair.lower);
  const Pixel lower = bilinear_clamped(level_image(source, pyramid, pair.lower), su * scale - 0.5,
                                       sv * scale - 0.5);
  if (pair.weight == 0) return lower;
  const Pixel upper = bilinear_clamped(pyramid.level(pair.lower + 1), 0.5 * su * scale - 0.5,
                                       0.5 * sv * scale - 0.5);
  return lerp_pixel(lower, upper, pair.weight);
}

// Per level: its bilinear map (division form), image and bordered copy (none for level 0).
MipLevelMaps level_maps(const WarpPlan& plan, const Image& source, const MipPyramid& pyramid) {
  MipLevelMaps levels;
  for (int k = 0; k <= pyramid.top(); ++k) {
    levels.maps.push_back(level_plan(plan, k).map);
    levels.images.push_back(&level_image(source, pyramid, k));
    levels.bordered.push_back(k > 0 && pyramid.has_borders() ? &pyramid.bordered_level(k)
                                                             : nullptr);
  }
  return levels;
}

// The end of the stretch of pairs[s ..] with pairs[s]'s lower level (pair >> 8), at most
// `last`: eight pairs a step with SSE2.
int stretch_end(const std::uint16_t* pairs, int s, int last) {
  const int k = pairs[s] >> 8;
  int e = s;
#if defined(OFLAB_WARP_SSE2)
  const __m128i level = _mm_set1_epi16(static_cast<short>(k));
  for (; e + 8 <= last; e += 8) {
    const __m128i eight = _mm_loadu_si128(reinterpret_cast<const __m128i*>(pairs + e));
    const int same = _mm_movemask_epi8(_mm_cmpeq_epi16(_mm_srli_epi16(eight, 8), level));
    if (same != 0xffff) return e + __builtin_ctz(~same & 0xffff) / 2;
  }
#endif
  while (e < last && pairs[e] >> 8 == k) ++e;
  return e;
}

// Pixels first .. last - 1 of `span` (offsets into it) sampled on their level pairs
// (`pairs`: lower level << 8 | weight, per pixel of the span): per stretch of one lower level
// the fast bilinear row on it and, where a weight is not 0, on the next level, blended pixel
// by pixel. `weight` is scratch of the span's length; out[0] is the span's first pixel.
void sample_levels(const MipLevelMaps& levels, const std::uint16_t* pairs, std::uint16_t* weight,
                   const PixelSpan& span, int first, int last, Pixel* out) {
  const int top = static_cast<int>(levels.maps.size()) - 1;
  for (int s = first; s < last;) {
    const int k = pairs[s] >> 8;
    const int e = stretch_end(pairs, s, last);
    int any = 0;  // a separate loop without exits, which the compiler vectorizes
    for (int i = s; i < e; ++i) {
      weight[i] = pairs[i] & 255;
      any |= weight[i];
    }
    const bool blend = any != 0;
    const int x0 = span.x_begin + s, x1 = span.x_begin + e;
    const auto ku = static_cast<std::size_t>(k);
    if (blend && k < top) {  // the top level's weight is 0
      run_trilinear_row(levels.maps[ku], *levels.images[ku], levels.maps[ku + 1],
                        *levels.images[ku + 1], span.y, x0, x1, weight + s, out + s);
    } else {
      run_bilinear_row(levels.maps[ku], *levels.images[ku], span.y, x0, x1, out + s);
    }
    s = e;
  }
}

// One span of a perspective plan: each pixel's level pair (found over the whole span, so a
// partial warp's pixels get the levels the whole warp gives them), then, over the wanted
// pixels (all of the span without plan.only), the levels sampled with the row cut where the
// lower level changes (run_trilinear_levels_row) or, without the AVX2 loops, per stretch of
// one lower level the fast bilinear row on it and, where a weight is not 0, on the next
// level, blended pixel by pixel. Returns the pixels written.
std::int64_t perspective_span_mip(const WarpPlan& plan, const MipLevelMaps& levels,
                                  const PixelSpan& span, Image& output) {
  thread_local std::vector<std::uint16_t> pairs;
  thread_local std::vector<std::uint16_t> weight;
  const int count = span.x_end - span.x_begin;
  const int top = static_cast<int>(levels.maps.size()) - 1;
  pairs.resize(static_cast<std::size_t>(count) + 7);  // run_trilinear_levels_row's padding
  weight.resize(static_cast<std::size_t>(count));
  mip_row_levels(plan.dest_to_source, top, span.y, span.x_begin, span.x_end, pairs.data());
  Pixel* out = output.row(span.y) + span.x_begin;
  return for_each_wanted(plan, span, [&](int begin, int end) {
    const int first = begin - span.x_begin, last = end - span.x_begin;
    if (!run_trilinear_levels_row(levels, pairs.data() + first, span.y, begin, end, out + first)) {
      sample_levels(levels, pairs.data(), weight.data(), span, first, last, out);
    }
  });
}

std::int64_t run_perspective(const WarpPlan& plan, const Image& source, const MipPyramid& pyramid,
                             Image& output, std::int64_t* computed) {
  if (footprint_bound(plan.dest_to_source, sampled_region(plan)) <= 1.0) {
    return run_warp_kernel(level_plan(plan, 0), source, output, computed);
  }
  const std::vector<PixelSpan> spans = output_spans(plan);
  const MipLevelMaps levels = level_maps(plan, source, pyramid);
  std::int64_t written = 0;
  for (const PixelSpan& span : spans) written += span.x_end - span.x_begin;
  std::atomic<std::int64_t> sampled{0};
  for_each_band(static_cast<int>(spans.size()), min_band_rows(plan.output_width),
                [&](int, int first, int last) {
                  std::int64_t count = 0;
                  for (int s = first; s < last; ++s) {
                    count += perspective_span_mip(plan, levels, spans[static_cast<std::size_t>(s)],
                                                  output);
                  }
                  sampled += count;
                });
  if (computed) *computed += sampled;
  return written;
}

}  // namespace

Pixel mipmap_pixel(const Mat3& dest_to_source, const Image& source, const MipPyramid& pyramid,
                   int x, int y) {
  return trilinear_pixel(dest_to_source, source, pyramid, x, y);
}

std::int64_t run_mipmap_kernel(const WarpPlan& plan, const Image& source, const MipPyramid& pyramid,
                               Image& output, std::int64_t* computed) {
  if (plan.empty || source.empty() || output.empty()) return 0;
  return plan.affine_kernel ? run_affine(plan, source, pyramid, output, computed)
                            : run_perspective(plan, source, pyramid, output, computed);
}

}  // namespace oflab
