#include "frame_pixels.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace oflab {

void flatten_into(const Image& frame, std::uint8_t r, std::uint8_t g, std::uint8_t b,
                  std::vector<std::uint8_t>& out) {
  out.resize(frame.pixel_count() * 4);
  std::uint8_t* o = out.data();
  for (const Pixel& p : frame.pixels()) {
    // Premultiplied "over": colour + background * (1 - alpha), rounded.
    const int rest = 255 - p.a;
    o[0] = static_cast<std::uint8_t>(p.r + (r * rest + 127) / 255);
    o[1] = static_cast<std::uint8_t>(p.g + (g * rest + 127) / 255);
    o[2] = static_cast<std::uint8_t>(p.b + (b * rest + 127) / 255);
    o[3] = 255;
    o += 4;
  }
}

void viridis(double t, std::uint8_t rgb[3]) {
  // Nine samples of matplotlib's viridis at t = 0, 1/8, ..., 1, interpolated linearly.
  static constexpr std::array<std::array<double, 3>, 9> kStops = {{{68, 1, 84},
                                                                   {71, 44, 122},
                                                                   {59, 81, 139},
                                                                   {44, 113, 142},
                                                                   {33, 144, 141},
                                                                   {39, 173, 129},
                                                                   {92, 200, 99},
                                                                   {170, 220, 50},
                                                                   {253, 231, 37}}};
  const double x = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0) * 8.0;
  const int i = std::min(7, static_cast<int>(x));
  const double f = x - i;
  for (int c = 0; c < 3; ++c) {
    const double v = kStops[i][c] + (kStops[i + 1][c] - kStops[i][c]) * f;
    rgb[c] = static_cast<std::uint8_t>(std::lround(v));
  }
}

int difference_heat_map_into(const Image& a, const Image& b, int full_scale,
                             std::vector<std::uint8_t>& out) {
  if (a.width() != b.width() || a.height() != b.height()) {
    throw std::invalid_argument("difference_heat_map_into: frames of different sizes");
  }
  if (full_scale < 1) throw std::invalid_argument("difference_heat_map_into: full_scale < 1");
  std::array<std::array<std::uint8_t, 4>, 256> ramp{};
  for (int d = 0; d < 256; ++d) {
    std::uint8_t rgb[3];
    viridis(static_cast<double>(d) / full_scale, rgb);
    ramp[d] = {rgb[0], rgb[1], rgb[2], 255};
  }
  out.resize(a.pixel_count() * 4);
  const Pixel* pa = a.pixels().data();
  const Pixel* pb = b.pixels().data();
  std::uint8_t* o = out.data();
  int largest = 0;
  for (std::size_t i = 0; i < a.pixel_count(); ++i) {
    const int d = std::max(std::max(std::abs(pa[i].r - pb[i].r), std::abs(pa[i].g - pb[i].g)),
                           std::max(std::abs(pa[i].b - pb[i].b), std::abs(pa[i].a - pb[i].a)));
    largest = std::max(largest, d);
    std::copy(ramp[d].begin(), ramp[d].end(), o + 4 * i);
  }
  return largest;
}

}  // namespace oflab
