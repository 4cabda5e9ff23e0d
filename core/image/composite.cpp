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

// Blends n layer pixels over the frame's (which hold their value).
void blend_row(const Pixel* src, Pixel* dst, int n) {
  for (int k = 0; k < n; ++k) {
    const Pixel s = src[k];
    if (s.a == 255) {
      dst[k] = s;
    } else if (s.a != 0 || s.r != 0 || s.g != 0 || s.b != 0) {
      dst[k] = over(s, dst[k]);
    }
  }
}

// Composites frame pixels [begin, end) of one row whose pixels outside the row's interval
// of `lazy` are not yet cleared: over transparent black the layer pixel itself is the
// result, the gap to the interval is cleared, and the interval grows to cover the span.
// `src` is the layer pixel under frame pixel `begin`.
void composite_lazy(const Pixel* src, Pixel* row, int begin, int end, int& held_begin,
                    int& held_end) {
  const auto copy = [&](int from, int to) {
    if (from < to) std::copy(src + (from - begin), src + (to - begin), row + from);
  };
  if (held_begin >= held_end) {
    copy(begin, end);
    held_begin = begin;
    held_end = end;
    return;
  }
  if (end < held_begin) std::fill(row + end, row + held_begin, Pixel{});
  if (held_end < begin) std::fill(row + held_end, row + begin, Pixel{});
  copy(begin, std::min(end, held_begin));
  const int inside_begin = std::max(begin, held_begin);
  const int inside_end = std::min(end, held_end);
  if (inside_begin < inside_end) {
    blend_row(src + (inside_begin - begin), row + inside_begin, inside_end - inside_begin);
  }
  copy(std::max(begin, held_end), end);
  held_begin = std::min(held_begin, begin);
  held_end = std::max(held_end, end);
}

// Composites one row's span of layer pixels under the frame; returns the pixels covered.
std::int64_t composite_span(Image& frame, const Layer& layer, int offset_x, int offset_y,
                            const PixelSpan& span, LazyClear* lazy) {
  // 64-bit so that extreme offsets cannot overflow; the clamps guard against rounding
  // of the polygon at the layer border.
  const std::int64_t ly = std::int64_t{span.y} - offset_y;
  const int begin = static_cast<int>(std::max<std::int64_t>(span.x_begin, offset_x));
  const int end = static_cast<int>(
      std::min<std::int64_t>(span.x_end, std::int64_t{offset_x} + layer.image.width()));
  if (begin >= end || ly < 0 || ly >= layer.image.height()) return 0;
  const Pixel* src = layer.image.row(static_cast<int>(ly)) + (begin - offset_x);
  if (lazy) {
    composite_lazy(src, frame.row(span.y), begin, end, lazy->begin(span.y), lazy->end(span.y));
  } else {
    blend_row(src, frame.row(span.y) + begin, end - begin);
  }
  return end - begin;
}

// Composites the layer pixels under the frame pixels whose centre lies in `polygon`
// (frame pixel coordinates, inside the layer's polygon placed at the offset), in bands of
// rows on the worker threads (core/image/thread_pool.h).
std::int64_t composite_inside(Image& frame, const Layer& layer, int offset_x, int offset_y,
                              const ConvexPolygon& polygon, LazyClear* lazy) {
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
                        frame, layer, offset_x, offset_y, rows[static_cast<std::size_t>(k)], lazy);
                  }
                });
  std::int64_t count = 0;
  for (std::int64_t c : counts) count += c;
  return count;
}

}  // namespace

void LazyClear::start(int height) {
  begin_.assign(static_cast<std::size_t>(std::max(height, 0)), 0);
  end_.assign(static_cast<std::size_t>(std::max(height, 0)), 0);
}

void LazyClear::finish(Image& frame) {
  const int width = frame.width();
  for_each_band(frame.height(), std::max(8, 65536 / std::max(width, 1)),
                [&](int, int first, int last) {
                  for (int y = first; y < last; ++y) {
                    Pixel* row = frame.row(y);
                    int& b = begin(y);
                    int& e = end(y);
                    if (b >= e) b = e = width;  // nothing held: the whole row is cleared
                    std::fill(row, row + b, Pixel{});
                    std::fill(row + e, row + width, Pixel{});
                    b = 0;
                    e = width;
                  }
                });
}

std::int64_t composite_over(Image& frame, const Layer& layer, int offset_x, int offset_y,
                            LazyClear* lazy) {
  if (layer.empty() || frame.empty()) return 0;
  return composite_inside(frame, layer, offset_x, offset_y,
                          translated(layer.polygon, offset_x, offset_y), lazy);
}

std::int64_t composite_over_region(Image& frame, const Layer& layer, int offset_x, int offset_y,
                                   const ConvexPolygon& region, LazyClear* lazy) {
  if (layer.empty() || frame.empty() || region.empty()) return 0;
  // The intersection of two convex polygons: the layer's polygon (in frame coordinates)
  // clipped by each edge of the region.
  ConvexPolygon polygon = translated(layer.polygon, offset_x, offset_y);
  const std::vector<Vec2>& v = region.vertices();
  for (std::size_t k = 0; k < v.size() && !polygon.empty(); ++k) {
    const Vec2 e = v[next_vertex(k, v.size())] - v[k];
    polygon = clip_to_half_plane(polygon, Vec3(-e.y, e.x, e.y * v[k].x - e.x * v[k].y));
  }
  if (polygon.empty()) return 0;
  return composite_inside(frame, layer, offset_x, offset_y, polygon, lazy);
}

}  // namespace oflab
