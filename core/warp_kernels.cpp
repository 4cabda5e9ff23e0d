// Affine and perspective warp kernels, nearest and bilinear (dissertation appendix A.1,
// errata 28-30 fixed). See warp_kernels.h for the scheme and inverse_map.h for the exact
// definition of the sampling position that every loop here reproduces bit for bit.
#include "core/warp_kernels.h"

#include <algorithm>
#include <cmath>

#include "core/scan_conversion.h"

namespace oflab {
namespace {

// Bilinear weights are fractions in units of 2^-11: with 8-bit channels the result is
// within 0.75 of the exactly interpolated value before rounding to the nearest level.
constexpr int kWeightBits = 11;
constexpr std::uint32_t kWeightOne = 1u << kWeightBits;

struct SourceView {
  const Pixel* pixels;
  std::int64_t stride;
  std::int64_t max_x;  // width - 1
  std::int64_t max_y;  // height - 1
  const Pixel* at(std::int64_t x, std::int64_t y) const { return pixels + y * stride + x; }
};

// Interpolates one channel pair at a time: r and b (or g and a) sit in separate 32-bit
// halves of a 64-bit word, where products of up to 2^30 cannot spill into the neighbour.
inline std::uint64_t spread_rb(std::uint32_t p) {
  return (p & 0xffu) | (static_cast<std::uint64_t>((p >> 16) & 0xffu) << 32);
}
inline std::uint64_t spread_ga(std::uint32_t p) {
  return ((p >> 8) & 0xffu) | (static_cast<std::uint64_t>(p >> 24) << 32);
}
inline std::uint32_t load_word(const Pixel* p) {
  std::uint32_t w;
  static_assert(sizeof(Pixel) == sizeof(w), "Pixel must be 4 bytes");
  __builtin_memcpy(&w, p, sizeof(w));
  return w;
}

// Bilinear blend of the four taps with weights fx, fy in [0, 2^11): exact
// round((p00 (1-fx)(1-fy) + p10 fx (1-fy) + p01 (1-fx) fy + p11 fx fy) / 2^22).
inline Pixel blend(const Pixel* p00, const Pixel* p10, const Pixel* p01, const Pixel* p11,
                   std::uint32_t fx, std::uint32_t fy) {
  const std::uint32_t w00 = load_word(p00), w10 = load_word(p10);
  const std::uint32_t w01 = load_word(p01), w11 = load_word(p11);
  const std::uint64_t gx = kWeightOne - fx;
  const std::uint64_t gy = kWeightOne - fy;
  // Each lane sum is below 255 * 2^22 < 2^30; add one half (2^21) to each lane.
  const std::uint64_t half = (std::uint64_t{1} << 21) | (std::uint64_t{1} << 53);
  const std::uint64_t rb = (spread_rb(w00) * gx + spread_rb(w10) * fx) * gy +
                           (spread_rb(w01) * gx + spread_rb(w11) * fx) * fy + half;
  const std::uint64_t ga = (spread_ga(w00) * gx + spread_ga(w10) * fx) * gy +
                           (spread_ga(w01) * gx + spread_ga(w11) * fx) * fy + half;
  Pixel out;
  out.r = static_cast<std::uint8_t>(rb >> 22);
  out.b = static_cast<std::uint8_t>(rb >> 54);
  out.g = static_cast<std::uint8_t>(ga >> 22);
  out.a = static_cast<std::uint8_t>(ga >> 54);
  return out;
}

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
    const auto fx = static_cast<std::uint32_t>(((s.nu - ku * s.d) << kWeightBits) / s.d);
    const auto fy = static_cast<std::uint32_t>(((s.nv - kv * s.d) << kWeightBits) / s.d);
    const std::int64_t x0 = std::clamp<std::int64_t>(ku, 0, src.max_x);
    const std::int64_t x1 = std::clamp<std::int64_t>(ku + 1, 0, src.max_x);
    const std::int64_t y0 = std::clamp<std::int64_t>(kv, 0, src.max_y);
    const std::int64_t y1 = std::clamp<std::int64_t>(kv + 1, 0, src.max_y);
    return blend(src.at(x0, y0), src.at(x1, y0), src.at(x0, y1), src.at(x1, y1), fx, fy);
  }
}

// True if every tap of the sample lies inside the source without clamping.
template <bool kBilinear>
bool in_fast_range(const SourceView& src, const MapSample& s) {
  if (s.d <= 0) return false;
  const std::int64_t ku = floor_div(s.nu, s.d);
  const std::int64_t kv = floor_div(s.nv, s.d);
  const std::int64_t margin = kBilinear ? 1 : 0;
  return ku >= 0 && kv >= 0 && ku + margin <= src.max_x && kv + margin <= src.max_y;
}

// Affine inner loop: fixed point with `shift` fractional bits, only additions.
template <bool kBilinear>
void affine_span(const SourceView& src, Pixel* out, int count, std::int64_t nu, std::int64_t nv,
                 std::int64_t du, std::int64_t dv, int shift) {
  for (int k = 0; k < count; ++k) {
    const std::int64_t u = nu >> shift;
    const std::int64_t v = nv >> shift;
    const Pixel* p = src.at(u, v);
    if constexpr (!kBilinear) {
      out[k] = *p;
    } else {
      const int fraction_shift = shift - kWeightBits;
      const auto fx = static_cast<std::uint32_t>(nu >> fraction_shift) & (kWeightOne - 1);
      const auto fy = static_cast<std::uint32_t>(nv >> fraction_shift) & (kWeightOne - 1);
      out[k] = blend(p, p + 1, p + src.stride, p + src.stride + 1, fx, fy);
    }
    nu += du;
    nv += dv;
  }
}

// Perspective inner loop: numerators and denominator are integers held exactly in
// double, so stepping them equals evaluating them; the quotients are non-negative here,
// so truncation is the floor.
template <bool kBilinear>
void perspective_span(const SourceView& src, Pixel* out, int count, double nu, double nv, double d,
                      double du, double dv, double dd) {
  for (int k = 0; k < count; ++k) {
    const double u = nu / d;
    const double v = nv / d;
    const auto iu = static_cast<std::int64_t>(u);
    const auto iv = static_cast<std::int64_t>(v);
    const Pixel* p = src.at(iu, iv);
    if constexpr (!kBilinear) {
      out[k] = *p;
    } else {
      const auto fx = static_cast<std::uint32_t>((u - static_cast<double>(iu)) * kWeightOne);
      const auto fy = static_cast<std::uint32_t>((v - static_cast<double>(iv)) * kWeightOne);
      out[k] = blend(p, p + 1, p + src.stride, p + src.stride + 1, fx, fy);
    }
    nu += du;
    nv += dv;
    d += dd;
  }
}

// Largest step that double can hold exactly together with the running sums.
constexpr std::int64_t kMaxExactStep = std::int64_t{1} << 51;

bool steps_exact_in_double(const InverseMap& m) {
  for (std::int64_t c : {m.a, m.d, m.g}) {
    if (c >= kMaxExactStep || c <= -kMaxExactStep) return false;
  }
  return true;
}

template <bool kAffine, bool kBilinear>
std::int64_t run(const WarpPlan& plan, const Image& source, Image& output) {
  const SourceView src{source.pixels().data(), source.width(), source.width() - 1,
                       source.height() - 1};
  const InverseMap& map = plan.map;
  // One output pixel to the right adds 2 to X.
  const std::int64_t step_u = 2 * map.a;
  const std::int64_t step_v = 2 * map.d;
  const std::int64_t step_d = 2 * map.g;
  const bool fast_allowed = kAffine || steps_exact_in_double(map);

  ScanConverter scan(plan.polygon, output.width(), output.height());
  std::int64_t written = 0;
  PixelSpan span;
  while (scan.next(span)) {
    int begin = span.x_begin;
    int end = span.x_end;
    if (begin >= end) continue;
    written += end - begin;
    Pixel* out = output.row(span.y);
    const int y = span.y;
    // Peel the ends whose samples need clamping (rounding of the polygon at the source
    // border, bilinear taps beyond it); the rest is one contiguous fast run.
    MapSample s = evaluate(map, begin, y);
    while (begin < end && !(fast_allowed && in_fast_range<kBilinear>(src, s))) {
      out[begin] = sample_clamped<kBilinear>(src, s);
      if (++begin < end) s = evaluate(map, begin, y);
    }
    while (end > begin) {
      const MapSample last = evaluate(map, end - 1, y);
      if (in_fast_range<kBilinear>(src, last)) break;
      out[end - 1] = sample_clamped<kBilinear>(src, last);
      --end;
    }
    if (begin >= end) continue;
    if constexpr (kAffine) {
      affine_span<kBilinear>(src, out + begin, end - begin, s.nu, s.nv, step_u, step_v,
                             map.affine_shift);
    } else {
      perspective_span<kBilinear>(src, out + begin, end - begin, static_cast<double>(s.nu),
                                  static_cast<double>(s.nv), static_cast<double>(s.d),
                                  static_cast<double>(step_u), static_cast<double>(step_v),
                                  static_cast<double>(step_d));
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
