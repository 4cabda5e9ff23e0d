// "Over" compositing of premultiplied layers, restricted to the layer's polygon (and
// optionally a region of the frame).
#include "image/composite.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
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

// True if the eight pixels from p are all opaque (alpha 255): eight loads and ands, no branch.
inline bool eight_opaque(const Pixel* p) {
  unsigned alpha = 255u;
  for (int i = 0; i < 8; ++i) alpha &= p[i].a;
  return alpha == 255u;
}

// True if the eight pixels from p are all transparent black (every channel 0).
inline bool eight_clear(const Pixel* p) {
  unsigned any = 0u;
  for (int i = 0; i < 8; ++i) any |= p[i].r | p[i].g | p[i].b | p[i].a;
  return any == 0u;
}

// Blends n layer pixels over the frame's (which hold their value): an opaque layer pixel
// replaces the frame's, a transparent black one leaves it, any other is put over it. Runs of
// eight opaque pixels are copied at once and runs of eight clear ones skipped, which gives
// the bytes of the pixel-by-pixel rule.
void blend_row(const Pixel* src, Pixel* dst, int n) {
  int k = 0;
  while (k < n) {
    int e = k;
    while (e + 8 <= n && eight_opaque(src + e)) e += 8;
    if (e > k) {
      std::copy(src + k, src + e, dst + k);
      k = e;
      continue;
    }
    while (e + 8 <= n && eight_clear(src + e)) e += 8;
    if (e > k) {
      k = e;
      continue;
    }
    // Eight pixels (or the row's last few) one by one.
    for (const int stop = std::min(n, k + 8); k < stop; ++k) {
      const Pixel s = src[k];
      if (s.a == 255) {
        dst[k] = s;
      } else if (s.a != 0 || s.r != 0 || s.g != 0 || s.b != 0) {
        dst[k] = over(s, dst[k]);
      }
    }
  }
}

// Clears row pixels [from, to) (within the row) where they may be other than transparent
// black: those inside [dirty_begin, dirty_end) (LazyClear::dirty_begin, dirty_end).
void clear_dirty(Pixel* row, int from, int to, int dirty_begin, int dirty_end) {
  from = std::max(from, dirty_begin);
  to = std::min(to, dirty_end);
  if (from < to) std::fill(row + from, row + to, Pixel{});
}

// Composites frame pixels [begin, end) of one row whose pixels outside the row's interval
// of `lazy` are not yet cleared: over transparent black the layer pixel itself is the
// result, the gap to the interval is cleared (its pixels inside [dirty_begin, dirty_end):
// the others are transparent black already), and the interval grows to cover the span.
// `src` is the layer pixel under frame pixel `begin`.
void composite_lazy(const Pixel* src, Pixel* row, int begin, int end, int& held_begin,
                    int& held_end, int dirty_begin, int dirty_end) {
  const auto copy = [&](int from, int to) {
    if (from < to) std::copy(src + (from - begin), src + (to - begin), row + from);
  };
  if (held_begin >= held_end) {
    copy(begin, end);
    held_begin = begin;
    held_end = end;
    return;
  }
  if (end < held_begin) clear_dirty(row, end, held_begin, dirty_begin, dirty_end);
  if (held_end < begin) clear_dirty(row, held_end, begin, dirty_begin, dirty_end);
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
    composite_lazy(src, frame.row(span.y), begin, end, lazy->begin(span.y), lazy->end(span.y),
                   lazy->dirty_begin(span.y), lazy->dirty_end(span.y));
  } else {
    blend_row(src, frame.row(span.y) + begin, end - begin);
  }
  return end - begin;
}

// A layer of a batch as the bands scan it: its part of the frame (frame pixels), and the
// frame rows [first_row, end_row) that part may reach.
struct PlacedPart {
  const Layer* layer;
  int offset_x, offset_y;
  ConvexPolygon polygon;
  int first_row, end_row;
};

// Composites each layer's rows in order, in bands of frame rows on the worker threads: a
// band scans every layer's part inside its rows (ScanConverter::clip_rows: the same spans as
// one scan of the whole part) and composites them, layer after layer, so each frame row
// meets the layers in the order given, as one layer after the other over the whole frame
// would (the same bytes and count). The layer pixel under frame pixel (x, y) is
// (x - offset_x, y - offset_y), whose centre is inside the layer polygon iff the frame pixel's
// centre is inside the translated polygon; the layer invariant keeps that pixel inside the
// layer image.
std::int64_t composite_rows(Image& frame, const std::vector<PlacedPart>& parts, LazyClear* lazy) {
  if (parts.empty()) return 0;
  // Bands of the rows the layers reach, each of about 32768 pixels of the widest part (its
  // box within the frame) or more.
  int top = frame.height(), bottom = 0, widest = 1;
  for (const PlacedPart& p : parts) {
    top = std::min(top, p.first_row);
    bottom = std::max(bottom, p.end_row);
    const BoundingBox box = p.polygon.bounds();
    const double left = std::max(box.x_min, 0.0);
    const double right = std::min(box.x_max, static_cast<double>(frame.width()));
    widest = std::max(widest, static_cast<int>(std::ceil(right - left)));
  }
  if (top >= bottom) return 0;
  std::array<std::int64_t, kMaxBands> counts{};
  for_each_band(bottom - top, std::max(8, 32768 / widest), [&](int band, int first, int last) {
    // Counted here and stored once: the bands' slots share a cache line, and a store per
    // span from both threads had each wait for the line.
    std::int64_t count = 0;
    for (const PlacedPart& p : parts) {
      if (p.end_row <= top + first || p.first_row >= top + last) continue;
      ScanConverter scan(p.polygon, frame.width(), frame.height());
      scan.clip_rows(top + first, top + last);
      PixelSpan span;
      while (scan.next(span)) {
        if (span.x_begin < span.x_end) {
          count += composite_span(frame, *p.layer, p.offset_x, p.offset_y, span, lazy);
        }
      }
    }
    counts[static_cast<std::size_t>(band)] = count;
  });
  std::int64_t count = 0;
  for (std::int64_t c : counts) count += c;
  return count;
}

// The part of the layer's polygon (placed at the offset) inside `region` (frame pixels;
// null: the whole polygon): the intersection of two convex polygons, the layer's clipped by
// each edge of the region.
ConvexPolygon placed_part(const Layer& layer, int offset_x, int offset_y,
                          const ConvexPolygon* region) {
  ConvexPolygon polygon = translated(layer.polygon, offset_x, offset_y);
  if (region == nullptr) return polygon;
  const std::vector<Vec2>& v = region->vertices();
  for (std::size_t k = 0; k < v.size() && !polygon.empty(); ++k) {
    const Vec2 e = v[next_vertex(k, v.size())] - v[k];
    polygon = clip_to_half_plane(polygon, Vec3(-e.y, e.x, e.y * v[k].x - e.x * v[k].y));
  }
  return polygon;
}

// Composites items[0 .. count - 1] in order (composite_over, composite_over_region and
// composite_all): each item's part of the frame placed, then one composite_rows.
std::int64_t composite_items(Image& frame, const CompositeItem* items, std::size_t count,
                             LazyClear* lazy) {
  if (frame.empty()) return 0;
  thread_local std::vector<PlacedPart> parts;  // memory kept from call to call
  parts.clear();
  for (std::size_t k = 0; k < count; ++k) {
    const CompositeItem& item = items[k];
    const Layer& layer = *item.layer;
    if (layer.empty() || (item.region != nullptr && item.region->empty())) continue;
    ConvexPolygon polygon = placed_part(layer, item.offset_x, item.offset_y, item.region);
    if (polygon.empty()) continue;
    const ScanConverter scan(polygon, frame.width(), frame.height());
    if (scan.first_row() >= scan.end_row()) continue;
    const int first_row = scan.first_row(), end_row = scan.end_row();
    parts.push_back({&layer, item.offset_x, item.offset_y, std::move(polygon), first_row, end_row});
  }
  return composite_rows(frame, parts, lazy);
}

}  // namespace

void LazyClear::start(int height) {
  const auto rows = static_cast<std::size_t>(std::max(height, 0));
  begin_.assign(rows, 0);
  end_.assign(rows, 0);
  forget();
  dirty_begin_.assign(rows, 0);  // nothing known: the whole row may hold anything
  dirty_end_.assign(rows, std::numeric_limits<int>::max());
}

void LazyClear::start_on(const Image& frame) {
  const bool known = finished_ != nullptr && finished_ == frame.pixels().data() &&
                     finished_width_ == frame.width() &&
                     dirty_begin_.size() == static_cast<std::size_t>(frame.height());
  if (!known) {
    start(frame.height());
    return;
  }
  begin_.assign(dirty_begin_.size(), 0);
  end_.assign(dirty_begin_.size(), 0);
}

void LazyClear::forget() {
  // The intervals stay until start, which start_on then calls: no frame is known.
  finished_ = nullptr;
  finished_width_ = 0;
}

void LazyClear::finish(Image& frame) {
  const int width = frame.width();
  for_each_band(frame.height(), std::max(8, 65536 / std::max(width, 1)),
                [&](int, int first, int last) {
                  for (int y = first; y < last; ++y) {
                    Pixel* row = frame.row(y);
                    int& b = begin(y);
                    int& e = end(y);
                    int& db = dirty_begin_[static_cast<std::size_t>(y)];
                    int& de = dirty_end_[static_cast<std::size_t>(y)];
                    if (b >= e) b = e = width;  // nothing held: the whole row is cleared
                    clear_dirty(row, 0, b, db, de);
                    clear_dirty(row, e, width, db, de);
                    db = b;  // what the next frame may find other than transparent black
                    de = e;
                    b = 0;
                    e = width;
                  }
                });
  finished_ = frame.pixels().data();
  finished_width_ = width;
}

std::int64_t composite_over(Image& frame, const Layer& layer, int offset_x, int offset_y,
                            LazyClear* lazy) {
  const CompositeItem item{&layer, offset_x, offset_y, nullptr};
  return composite_items(frame, &item, 1, lazy);
}

std::int64_t composite_over_region(Image& frame, const Layer& layer, int offset_x, int offset_y,
                                   const ConvexPolygon& region, LazyClear* lazy) {
  const CompositeItem item{&layer, offset_x, offset_y, &region};
  return composite_items(frame, &item, 1, lazy);
}

std::int64_t composite_all(Image& frame, const std::vector<CompositeItem>& items, LazyClear* lazy) {
  return composite_items(frame, items.data(), items.size(), lazy);
}

}  // namespace oflab
