// "Over" compositing of premultiplied layers, restricted to the layer's polygon (and
// optionally a region of the frame).
#include "image/composite.h"

#include <algorithm>
#include <array>
#include <vector>

#include "image/pixel_math.h"
#include "image/scan_conversion.h"
#include "image/thread_pool.h"

namespace oflab {

Pixel over(Pixel src, Pixel dst) {
  const unsigned keep = 255u - src.a;
  // src + dst * keep / 255 <= 255 holds for well-formed premultiplied pixels; saturate
  // so that malformed input cannot wrap around.
  auto channel = [keep](std::uint8_t s, std::uint8_t d) {
    return static_cast<std::uint8_t>(std::min(255u, s + unsigned{div255_round(d * keep)}));
  };
  return Pixel{channel(src.r, dst.r), channel(src.g, dst.g), channel(src.b, dst.b),
               channel(src.a, dst.a)};
}

namespace {

// Composites one row's span of layer pixels under the frame; returns the pixels covered.
std::int64_t composite_span(Image& frame, const Layer& layer, int offset_x, int offset_y,
                            const PixelSpan& span) {
  // 64-bit so that extreme offsets cannot overflow; the clamps guard against rounding
  // of the polygon at the layer border.
  const std::int64_t ly = std::int64_t{span.y} - offset_y;
  const int begin = static_cast<int>(std::max<std::int64_t>(span.x_begin, offset_x));
  const int end = static_cast<int>(
      std::min<std::int64_t>(span.x_end, std::int64_t{offset_x} + layer.image.width()));
  if (begin >= end || ly < 0 || ly >= layer.image.height()) return 0;
  const Pixel* src = layer.image.row(static_cast<int>(ly)) + (begin - offset_x);
  Pixel* dst = frame.row(span.y) + begin;
  for (int k = 0; k < end - begin; ++k) {
    const Pixel s = src[k];
    if (s.a == 255) {
      dst[k] = s;
    } else if (s.a != 0 || s.r != 0 || s.g != 0 || s.b != 0) {
      dst[k] = over(s, dst[k]);
    }
  }
  return end - begin;
}

// Composites the layer pixels under the frame pixels whose centre lies in `polygon`
// (frame pixel coordinates, inside the layer's polygon placed at the offset), in bands of
// rows on the worker threads (core/image/thread_pool.h).
std::int64_t composite_inside(Image& frame, const Layer& layer, int offset_x, int offset_y,
                              const ConvexPolygon& polygon) {
  // The layer pixel under frame pixel (x, y) is (x - offset_x, y - offset_y), whose centre
  // is inside the layer polygon iff the frame pixel's centre is inside the translated
  // polygon. The layer invariant keeps that pixel inside the layer image.
  thread_local std::vector<PixelSpan> spans;  // memory kept from layer to layer
  spans.clear();
  ScanConverter scan(polygon, frame.width(), frame.height());
  PixelSpan span;
  int widest = 0;
  while (scan.next(span)) {
    if (span.x_begin >= span.x_end) continue;
    spans.push_back(span);
    widest = std::max(widest, span.x_end - span.x_begin);
  }
  std::array<std::int64_t, kMaxBands> counts{};
  const std::vector<PixelSpan>& rows = spans;
  for_each_band(static_cast<int>(rows.size()), std::max(8, 32768 / std::max(widest, 1)),
                [&](int band, int first, int last) {
                  for (int k = first; k < last; ++k) {
                    counts[static_cast<std::size_t>(band)] += composite_span(
                        frame, layer, offset_x, offset_y, rows[static_cast<std::size_t>(k)]);
                  }
                });
  std::int64_t count = 0;
  for (std::int64_t c : counts) count += c;
  return count;
}

}  // namespace

std::int64_t composite_over(Image& frame, const Layer& layer, int offset_x, int offset_y) {
  if (layer.empty() || frame.empty()) return 0;
  return composite_inside(frame, layer, offset_x, offset_y,
                          translated(layer.polygon, offset_x, offset_y));
}

std::int64_t composite_over_region(Image& frame, const Layer& layer, int offset_x, int offset_y,
                                   const ConvexPolygon& region) {
  if (layer.empty() || frame.empty() || region.empty()) return 0;
  // The intersection of two convex polygons: the layer's polygon (in frame coordinates)
  // clipped by each edge of the region.
  ConvexPolygon polygon = translated(layer.polygon, offset_x, offset_y);
  const std::vector<Vec2>& v = region.vertices();
  for (std::size_t k = 0; k < v.size() && !polygon.empty(); ++k) {
    const Vec2 e = v[(k + 1) % v.size()] - v[k];
    polygon = clip_to_half_plane(polygon, Vec3(-e.y, e.x, e.y * v[k].x - e.x * v[k].y));
  }
  if (polygon.empty()) return 0;
  return composite_inside(frame, layer, offset_x, offset_y, polygon);
}

}  // namespace oflab
