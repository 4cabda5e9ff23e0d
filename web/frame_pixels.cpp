#include "frame_pixels.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "display/palette.h"

namespace oflab {
namespace {

void require_same_size(const Image& a, const Image& b) {
  if (a.width() != b.width() || a.height() != b.height()) {
    throw std::invalid_argument("frame_pixels: frames of different sizes");
  }
}

int channel_difference(const Pixel& p, const Pixel& q) {
  return std::max(std::max(std::abs(p.r - q.r), std::abs(p.g - q.g)),
                  std::max(std::abs(p.b - q.b), std::abs(p.a - q.a)));
}

std::vector<int> nearest_indices(int frame_size, int out_size) {
  std::vector<int> indices(static_cast<std::size_t>(std::max(1, out_size)));
  for (std::size_t i = 0; i < indices.size(); ++i) {
    const double centre = (static_cast<double>(i) + 0.5) * frame_size / indices.size();
    indices[i] = std::clamp(static_cast<int>(centre), 0, std::max(0, frame_size - 1));
  }
  return indices;
}

}  // namespace

DisplaySampling display_sampling(int frame_width, int frame_height, int out_width, int out_height) {
  return {nearest_indices(frame_width, out_width), nearest_indices(frame_height, out_height)};
}

namespace {

// Frame indices of `out_size` display pixels starting at frame coordinate `start`, `pixel`
// frame pixels each; -1 outside 0 .. frame_size - 1.
std::vector<int> region_indices(int frame_size, double start, double pixel, int out_size) {
  std::vector<int> indices(static_cast<std::size_t>(std::max(1, out_size)));
  for (std::size_t i = 0; i < indices.size(); ++i) {
    const double centre = std::floor(start + (static_cast<double>(i) + 0.5) * pixel);
    indices[i] = centre >= 0.0 && centre < frame_size ? static_cast<int>(centre) : -1;
  }
  return indices;
}

}  // namespace

DisplaySampling region_sampling(int frame_width, int frame_height, double x0, double y0,
                                double pixel, int out_width, int out_height) {
  return {region_indices(frame_width, x0, pixel, out_width),
          region_indices(frame_height, y0, pixel, out_height)};
}

PanelView fit_panel_view(const BoundingBox& frame, int cell_width, int cell_height) {
  const double fw = frame.x_max - frame.x_min, fh = frame.y_max - frame.y_min;
  const double k = std::min(cell_width / fw, cell_height / fh);
  PanelView view;
  view.width = std::clamp(static_cast<int>(std::floor(k * fw)), 1, std::max(1, cell_width));
  view.height = std::clamp(static_cast<int>(std::floor(k * fh)), 1, std::max(1, cell_height));
  view.pixel = std::max(fw / view.width, fh / view.height);
  view.x0 = 0.5 * (frame.x_min + frame.x_max - view.pixel * view.width);
  view.y0 = 0.5 * (frame.y_min + frame.y_max - view.pixel * view.height);
  return view;
}

void shift_sampling(DisplaySampling& sampling, int offset_x, int offset_y, int width, int height) {
  const auto shift = [](std::vector<int>& indices, int offset, int size) {
    for (int& i : indices) i = i < 0 || i - offset < 0 || i - offset >= size ? -1 : i - offset;
  };
  shift(sampling.columns, offset_x, width);
  shift(sampling.rows, offset_y, height);
}

namespace {

// Writes out[4 * i ...] for every display pixel i, row after row, from `colour(frame row,
// frame column)`, which returns 4 bytes. Empty frames give transparent black.
template <class Colour>
void sample_into(const Image& frame, const DisplaySampling& sampling, Colour colour,
                 std::vector<std::uint8_t>& out) {
  out.resize(sampling.columns.size() * sampling.rows.size() * 4);
  if (frame.empty()) {
    std::fill(out.begin(), out.end(), 0);
    return;
  }
  std::uint8_t* o = out.data();
  for (const int y : sampling.rows) {
    for (const int x : sampling.columns) {
      const std::array<std::uint8_t, 4> c = colour(y, x);
      std::copy(c.begin(), c.end(), o);
      o += 4;
    }
  }
}

}  // namespace

void flatten_into(const Image& frame, const DisplaySampling& sampling, const std::uint8_t rgb[3],
                  std::vector<std::uint8_t>& out, double opacity) {
  if (frame.empty()) {
    out.assign(sampling.columns.size() * sampling.rows.size() * 4, 0);
    return;
  }
  // The fade of each composited channel value, looked up: background + opacity * (c - bg).
  const double weight = std::clamp(opacity, 0.0, 1.0);
  std::array<std::array<std::uint8_t, 256>, 3> fade{};
  for (int c = 0; c < 3; ++c) {
    for (int v = 0; v < 256; ++v) {
      fade[c][v] = static_cast<std::uint8_t>(
          opacity < 1.0 ? rgb[c] + std::lround(weight * (v - rgb[c])) : v);
    }
  }
  const std::array<std::uint8_t, 4> empty{fade[0][rgb[0]], fade[1][rgb[1]], fade[2][rgb[2]], 255};
  // Premultiplied "over": colour + background * (1 - alpha), rounded; opaque and empty pixels
  // (most of a frame) take the short ways.
  const auto over = [&](const Pixel& p) -> std::array<std::uint8_t, 4> {
    if (p.a == 255) return {fade[0][p.r], fade[1][p.g], fade[2][p.b], 255};
    if ((p.a | p.r | p.g | p.b) == 0) return empty;
    const int rest = 255 - p.a;
    return {fade[0][p.r + (rgb[0] * rest + 127) / 255], fade[1][p.g + (rgb[1] * rest + 127) / 255],
            fade[2][p.b + (rgb[2] * rest + 127) / 255], 255};
  };
  out.resize(sampling.columns.size() * sampling.rows.size() * 4);
  std::uint8_t* o = out.data();
  for (const int y : sampling.rows) {
    const Pixel* row = y < 0 ? nullptr : frame.row(y);
    for (const int x : sampling.columns) {
      const std::array<std::uint8_t, 4> c = row && x >= 0 ? over(row[x]) : empty;
      std::copy(c.begin(), c.end(), o);
      o += 4;
    }
  }
}

int largest_difference(const Image& a, const Image& b) {
  require_same_size(a, b);
  if (&a == &b) return 0;  // a compared re-render shown as the exact panel: no byte differs
  // The largest over pixels of the largest over channels is the largest over all bytes: one
  // flat loop over bytes, which the compiler turns into SIMD.
  const auto* pa = reinterpret_cast<const std::uint8_t*>(a.pixels().data());
  const auto* pb = reinterpret_cast<const std::uint8_t*>(b.pixels().data());
  const std::size_t bytes = a.pixel_count() * sizeof(Pixel);
  std::uint8_t largest = 0;
  for (std::size_t i = 0; i < bytes; ++i) {
    const std::uint8_t d = pa[i] > pb[i] ? pa[i] - pb[i] : pb[i] - pa[i];
    largest = std::max(largest, d);
  }
  return largest;
}

void difference_heat_map_into(const Image& a, const Image& b, int full_scale,
                              const DisplaySampling& sampling, std::vector<std::uint8_t>& out) {
  require_same_size(a, b);
  if (full_scale < 1) throw std::invalid_argument("difference_heat_map_into: full_scale < 1");
  std::array<std::array<std::uint8_t, 4>, 256> ramp{};
  for (int d = 0; d < 256; ++d) {
    const Rgb8 c = magnitude_colour(static_cast<double>(d) / full_scale);
    ramp[d] = {c.r, c.g, c.b, 255};
  }
  // Off the frame (index -1) both show the background: no difference.
  const auto heat = [&](int y, int x) {
    return y < 0 || x < 0 ? ramp[0] : ramp[channel_difference(a.at(x, y), b.at(x, y))];
  };
  sample_into(a, sampling, heat, out);
}

}  // namespace oflab
