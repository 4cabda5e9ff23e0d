// The mipmap warp kernel (Williams 83; dissertation section 7.5.5). See mipmap_kernel.h.
#include "image/mipmap_kernel.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "image/bilinear_blend.h"  // blend_taps, and OFLAB_WARP_SSE2 with <emmintrin.h>
#include "image/scan_conversion.h"
#include "image/thread_pool.h"
#include "image/warp_kernels.h"

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

// out[k] = lerp_pixel(out[k], upper[k], w) for k < count.
void lerp_run(Pixel* out, const Pixel* upper, int count, int w) {
  int k = 0;
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
// span without one. Returns the pixels it covered.
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

// A partial affine warp whose level pair blends two levels: both levels are sampled into
// scratch images (their partial warps may compute more than the wanted pixels, the lower
// level's pixels alone differing from the blend), and only the wanted pixels of the output
// receive the blend.
std::int64_t run_affine_partial(const WarpPlan& plan, const Image& source,
                                const MipPyramid& pyramid, const LevelPair& pair, Image& output,
                                std::int64_t* computed) {
  thread_local Image lower_scratch, upper_scratch;  // memory kept from warp to warp
  Image& lower = lower_scratch;  // the bands run on other threads: name this thread's scratch
  Image& upper = upper_scratch;
  lower.reshape(output.width(), output.height());
  upper.reshape(output.width(), output.height());
  const std::int64_t written = run_warp_kernel(level_plan(plan, pair.lower),
                                               level_image(source, pyramid, pair.lower), lower);
  run_warp_kernel(level_plan(plan, pair.lower + 1), pyramid.level(pair.lower + 1), upper);
  const std::vector<PixelSpan> spans = output_spans(plan);
  std::atomic<std::int64_t> blended{0};
  for_each_band(static_cast<int>(spans.size()), min_band_rows(plan.output_width),
                [&](int, int first, int last) {
                  std::int64_t count = 0;
                  for (int s = first; s < last; ++s) {
                    const PixelSpan& span = spans[static_cast<std::size_t>(s)];
                    count += for_each_wanted(plan, span, [&](int begin, int end) {
                      Pixel* out = output.row(span.y) + begin;
                      std::copy(lower.row(span.y) + begin, lower.row(span.y) + end, out);
                      lerp_run(out, upper.row(span.y) + begin, end - begin, pair.weight);
                    });
                  }
                  blended += count;
                });
  if (computed) *computed += blended;
  return written;
}

// Affine: one level pair for the whole warp.
std::int64_t run_affine(const WarpPlan& plan, const Image& source, const MipPyramid& pyramid,
                        Image& output, std::int64_t* computed) {
  const Mat3& h = plan.dest_to_source;
  const LevelPair pair = level_pair(
      mip_level(entry(h, 0, 0), entry(h, 0, 1), entry(h, 1, 0), entry(h, 1, 1), pyramid.top()));
  if (pair.weight != 0 && plan.only != nullptr) {
    return run_affine_partial(plan, source, pyramid, pair, output, computed);
  }
  // One level, or a whole warp: the lower level straight into the output.
  const std::int64_t written = run_warp_kernel(
      level_plan(plan, pair.lower), level_image(source, pyramid, pair.lower), output, computed);
  if (pair.weight == 0) return written;
  thread_local Image scratch;  // the upper level's samples, memory kept from warp to warp
  Image& upper = scratch;      // the bands run on other threads: name this thread's scratch
  upper.reshape(output.width(), output.height());
  run_warp_kernel(level_plan(plan, pair.lower + 1), pyramid.level(pair.lower + 1), upper);
  const std::vector<PixelSpan> spans = output_spans(plan);
  for_each_band(static_cast<int>(spans.size()), min_band_rows(plan.output_width),
                [&](int, int first, int last) {
                  for (int s = first; s < last; ++s) {
                    const PixelSpan& span = spans[static_cast<std::size_t>(s)];
                    lerp_run(output.row(span.y) + span.x_begin, upper.row(span.y) + span.x_begin,
                             span.x_end - span.x_begin, pair.weight);
                  }
                });
  return written;
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

constexpr double kLn2 = 0.6931471805599453;

// log2(t) for a finite t > 0 within 1e-8: t = m 2^e with m in [sqrt(1/2), sqrt(2)), and
// log2(m) = (2 / ln 2) atanh(z), z = (m - 1) / (m + 1), |z| <= 0.1716, by its odd series to
// z^9: the tail is below (2 / ln 2) |z|^11 / 11 / (1 - z^2) < 1.1e-9. (Level pairs are found
// hundreds of thousands of times a frame: libm's log is several times slower.)
double fast_log2(double t) {
  std::uint64_t bits;
  std::memcpy(&bits, &t, sizeof(bits));
  int exponent = static_cast<int>((bits >> 52) & 0x7ff) - 1023;
  bits = (bits & 0x000fffffffffffffull) | 0x3ff0000000000000ull;
  double m;
  std::memcpy(&m, &bits, sizeof(m));
  if (m > 1.4142135623730951) {
    m *= 0.5;
    ++exponent;
  }
  const double z = (m - 1.0) / (m + 1.0);
  const double z2 = z * z;
  constexpr double c = 2.8853900817779268;  // 2 / ln 2
  return exponent +
         c * z * (1.0 + z2 * (1.0 / 3.0 + z2 * (1.0 / 5.0 + z2 * (1.0 / 7.0 + z2 * (1.0 / 9.0)))));
}

// The footprint along a row of a perspective plan. At pixel centre (x, y) the inverse map's
// Jacobian is J = M / D^2 with M = A D - N g^T (h = [A c; g^T i], N = A p + c, D = g.p + i):
// M's first column is constant along a row and its second is alpha + beta x, so M(x) =
// M(x0) + (x - x0) M1 with M1 = [0 beta]. The level is log2 |M|_2 - 2 log2 D, clamped.
struct RowFootprint {
  const Mat3& h;
  double py;
  double beta0, beta1;

  RowFootprint(const Mat3& map, int y)
      : h(map),
        py(y + 0.5),
        beta0(entry(map, 0, 1) * entry(map, 2, 0) - entry(map, 0, 0) * entry(map, 2, 1)),
        beta1(entry(map, 1, 1) * entry(map, 2, 0) - entry(map, 1, 0) * entry(map, 2, 1)) {}

  // At pixel x: N = |M|_2 and D (values and log2), and for a top right singular vector w of
  // M, u = M w and v = M1 w: |u| (N but for rounding) and u.v / |u|, the slope of the line
  // |u| + t u.v / |u| that bounds |M(x + t) w| <= N(x + t) from below (Cauchy-Schwarz).
  struct End {
    double n = 0.0, d = 0.0, u = 0.0, u_slope = 0.0;
    double log2_n = 0.0, log2_d = 0.0;
    double level() const { return log2_n - 2.0 * log2_d; }  // unclamped log2 sigma
  };

  End at(int x) const {
    auto e = [&](int r, int c) { return entry(h, r, c); };
    const double px = x + 0.5;
    const double d = e(2, 0) * px + e(2, 1) * py + e(2, 2);
    const double nu = e(0, 0) * px + e(0, 1) * py + e(0, 2);
    const double nv = e(1, 0) * px + e(1, 1) * py + e(1, 2);
    const double m00 = e(0, 0) * d - nu * e(2, 0), m01 = e(0, 1) * d - nu * e(2, 1);
    const double m10 = e(1, 0) * d - nv * e(2, 0), m11 = e(1, 1) * d - nv * e(2, 1);
    const double p = m00 * m00 + m10 * m10, q = m00 * m01 + m10 * m11, r = m01 * m01 + m11 * m11;
    const double half_gap = 0.5 * (p - r);
    const double lambda = 0.5 * (p + r) + std::sqrt(half_gap * half_gap + q * q);
    // The eigenvector of M^T M for lambda: (q, lambda - p) or (lambda - r, q), the longer.
    double w0 = q, w1 = lambda - p;
    if (w0 * w0 + w1 * w1 < (lambda - r) * (lambda - r) + q * q) w0 = lambda - r, w1 = q;
    const double length = std::sqrt(w0 * w0 + w1 * w1);
    if (length > 0.0) {
      w0 /= length, w1 /= length;
    } else {
      w0 = 1.0, w1 = 0.0;  // isotropic: every direction
    }
    const double u0 = m00 * w0 + m01 * w1, u1 = m10 * w0 + m11 * w1;
    const double v0 = beta0 * w1, v1 = beta1 * w1;
    const double u2 = u0 * u0 + u1 * u1;
    End end;
    end.n = std::sqrt(lambda);
    end.d = d;
    end.u = std::sqrt(u2);
    end.u_slope = (u0 * v0 + u1 * v1) / end.u;
    end.log2_n = 0.5 * fast_log2(lambda);
    end.log2_d = fast_log2(d);
    return end;
  }
};

// A chord of a row: pixels a + t, 0 <= t <= n, with the footprints at its ends. Its level
// is the curve Q(t) = level(a) + t (level(b) - level(a)) / n + c t (t - n), the quadratic
// through the end levels whose second derivative is that of
//     f(t) = log2 l_N(t) - 2 log2 D(a + t)
// at n / 2, l_N the linear interpolation of N between the ends (D is linear itself):
// f'' = (2 rho_D^2 - rho_N^2) / ln 2 with rho = l' / l.
struct Chord {
  double start = 0.0, slope = 0.0, c = 0.0;

  Chord(const RowFootprint::End& a, const RowFootprint::End& b, int n) {
    const double rho_n = (b.n - a.n) / (n * 0.5 * (a.n + b.n));
    const double rho_d = (b.d - a.d) / (n * 0.5 * (a.d + b.d));
    start = a.level();
    slope = (b.level() - start) / n;
    c = 0.5 * (2.0 * rho_d * rho_d - rho_n * rho_n) / kLn2;
  }
  double level(int t, int n) const { return start + t * (slope + c * (t - n)); }
};

// A bound, in levels, of |level(a + t) - Q(t)| for 0 <= t <= n:
//  - f - Q: both agree at the ends and their second derivatives differ by
//    f''(t) - f''(n / 2), at most n / 2 times the largest third derivative
//    (2 |rho_N|^3 + 4 |rho_D|^3) / ln 2 (rho at most |l'| over the smaller end), so
//    |f - Q| <= n^3 / 16 (2 |rho_N|^3 + 4 |rho_D|^3) / ln 2;
//  - N(x) = |M(x)|_2 is convex (a norm of an affine map), so N <= l_N and level <= f;
//  - N >= max(line_a, line_b), the lines below |M w_a| from a and |M w_b| from b, so
//    l_N - N <= E, the largest over t of min(l_N - line_a, l_N - line_b) (at an end or where
//    the lines cross: all are linear), and f - level <= E / N_min / ln 2 with N_min the
//    smallest of max(line_a, line_b) (also at an end or the crossing).
// Infinity where a bound does not apply (a footprint near 0, a non-finite value).
double chord_error(const RowFootprint::End& a, const RowFootprint::End& b, int n) {
  const double infinity = std::numeric_limits<double>::infinity();
  if (!(a.n > 0.0 && b.n > 0.0 && a.d > 0.0 && b.d > 0.0 && a.u > 0.0 && b.u > 0.0)) {
    return infinity;
  }
  const double rho_n = std::abs(b.n - a.n) / (n * std::min(a.n, b.n));
  const double rho_d = std::abs(b.d - a.d) / (n * std::min(a.d, b.d));
  const double cube = static_cast<double>(n) * n * n;
  const double curve = cube / 16.0 * (2.0 * rho_n * rho_n * rho_n + 4.0 * rho_d * rho_d * rho_d);
  // Lines in t as value at t = 0 and slope: l_N, line_a, line_b.
  const double l0 = a.n, l1 = (b.n - a.n) / n;
  const double a0 = a.u, a1 = a.u_slope;
  const double b0 = b.u - n * b.u_slope, b1 = b.u_slope;
  const auto gap_at = [&](double t) {
    return std::min(l0 + t * l1 - (a0 + t * a1), l0 + t * l1 - (b0 + t * b1));
  };
  const auto low_at = [&](double t) { return std::max(a0 + t * a1, b0 + t * b1); };
  double gap = std::max(gap_at(0.0), gap_at(n));
  double low = std::min(low_at(0.0), low_at(n));
  if (a1 != b1) {
    const double t = (b0 - a0) / (a1 - b1);  // where line_a and line_b cross
    if (t > 0.0 && t < n) {
      gap = std::max(gap, gap_at(t));
      low = std::min(low, low_at(t));
    }
  }
  if (!(low > 0.0)) return infinity;
  const double bound = (curve + std::max(gap, 0.0) / low) / kLn2;
  return std::isfinite(bound) ? bound : infinity;
}

// Chord error allowed, in levels: under one step 1/256 of the weight (with room for the 1e-8
// of fast_log2 and the rounding of the curve), so that a pixel's rounded index is within 1.5
// steps of level_pair(mip_level)'s index before rounding, i.e. that index or one step next
// to it.
constexpr double kLevelTolerance = 0.9 / 256.0;
constexpr int kLongestChord = 64;  // pixels

// The level pairs of output pixels x_begin .. x_end - 1 of row y of the perspective inverse
// map h, as indices i = 256 lower + weight of level_pair (index 0 is x_begin): the exact
// level at the ends of chords of up to kLongestChord pixels, shortened until chord_error
// allows kLevelTolerance, and the chord's curve in between, rounded per pixel.
void row_levels(const Mat3& h, int top, int y, int x_begin, int x_end, std::uint16_t* pairs) {
  const RowFootprint row(h, y);
  const double top_level = top;
  const auto store = [&](int x, double level) {
    pairs[x - x_begin] =
        static_cast<std::uint16_t>(256.0 * std::clamp(level, 0.0, top_level) + 0.5);
  };
  RowFootprint::End a = row.at(x_begin);
  store(x_begin, a.level());
  int next = kLongestChord;  // the length to try
  for (int x = x_begin; x + 1 < x_end;) {
    int n = std::min(next, x_end - 1 - x);
    RowFootprint::End b = row.at(x + n);
    double error = chord_error(a, b, n);
    while (n > 1 && !(error <= kLevelTolerance)) {
      n = n * 3 / 4;
      b = row.at(x + n);
      error = chord_error(a, b, n);
    }
    // The bound grows about as n^2 (n^3 at most): the next chord is as long as that allows,
    // with a tenth to spare, so that few chords are tried twice.
    const double room = 0.9 * std::sqrt(kLevelTolerance / std::max(error, 1e-12));
    next = static_cast<int>(std::clamp(n * room, 2.0, static_cast<double>(kLongestChord)));
    const Chord chord(a, b, n);
    for (int t = 1; t < n; ++t) store(x + t, chord.level(t, n));
    store(x + n, b.level());
    x += n;
    a = b;
  }
}

// Per level: its bilinear map (division form) and image.
struct LevelMaps {
  std::vector<InverseMap> maps;
  std::vector<const Image*> images;
};

LevelMaps level_maps(const WarpPlan& plan, const Image& source, const MipPyramid& pyramid) {
  LevelMaps levels;
  for (int k = 0; k <= pyramid.top(); ++k) {
    levels.maps.push_back(level_plan(plan, k).map);
    levels.images.push_back(&level_image(source, pyramid, k));
  }
  return levels;
}

// Pixels first .. last - 1 of `span` (offsets into it) sampled on their level pairs
// (`pairs`: lower level << 8 | weight, per pixel of the span): per stretch of one lower level
// the fast bilinear row on it and, where a weight is not 0, on the next level, blended pixel
// by pixel. `weight` is scratch of the span's length; out[0] is the span's first pixel.
void sample_levels(const LevelMaps& levels, const std::uint16_t* pairs, std::uint16_t* weight,
                   const PixelSpan& span, int first, int last, Pixel* out) {
  const int top = static_cast<int>(levels.maps.size()) - 1;
  for (int s = first; s < last;) {
    const int k = pairs[s] >> 8;
    int e = s;
    bool blend = false;
    for (; e < last && pairs[e] >> 8 == k; ++e) {
      weight[e] = pairs[e] & 255;
      blend = blend || weight[e] != 0;
    }
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
// pixels (all of the span without plan.only), per stretch of one lower level the fast
// bilinear row on it and, where a weight is not 0, on the next level, blended pixel by pixel.
// Returns the pixels written.
std::int64_t perspective_span_mip(const WarpPlan& plan, const LevelMaps& levels,
                                  const PixelSpan& span, Image& output) {
  thread_local std::vector<std::uint16_t> pairs;
  thread_local std::vector<std::uint16_t> weight;
  const int count = span.x_end - span.x_begin;
  const int top = static_cast<int>(levels.maps.size()) - 1;
  pairs.resize(static_cast<std::size_t>(count));
  weight.resize(static_cast<std::size_t>(count));
  row_levels(plan.dest_to_source, top, span.y, span.x_begin, span.x_end, pairs.data());
  Pixel* out = output.row(span.y) + span.x_begin;
  return for_each_wanted(plan, span, [&](int begin, int end) {
    sample_levels(levels, pairs.data(), weight.data(), span, begin - span.x_begin,
                  end - span.x_begin, out);
  });
}
std::int64_t run_perspective(const WarpPlan& plan, const Image& source, const MipPyramid& pyramid,
                             Image& output, std::int64_t* computed) {
  if (footprint_bound(plan.dest_to_source, sampled_region(plan)) <= 1.0) {
    return run_warp_kernel(level_plan(plan, 0), source, output, computed);
  }
  const std::vector<PixelSpan> spans = output_spans(plan);
  const LevelMaps levels = level_maps(plan, source, pyramid);
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
