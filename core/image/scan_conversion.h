// Scan conversion of a convex polygon into pixel spans, one per row, with two active
// edges (dissertation appendix A.1, fig. 27; errata 28-30 of manual/theory.md#errata: the
// right gap runs from s2 to the right end, and a polygon has exactly two crossings per
// scanline only because it is convex, which the horizon clip guarantees).
//
// Pixel-centre rule. Pixel (x, y) covers [x, x+1) x [y, y+1) and has its centre at
// (x + 0.5, y + 0.5). It is covered by the polygon iff its centre c satisfies
//     y_top <= c.y < y_bottom            (lowest and highest vertex y), and
//     x_left(c.y) <= c.x < x_right(c.y)  (the polygon's crossings of the line y = c.y),
// a half-open "top-left" rule: two polygons sharing an edge never both cover a pixel.
// Crossings are evaluated directly from the edge's end points for every row (no
// accumulated increments), and a crossing or vertex y within 1e-9 (relative) of a pixel
// centre is taken as on it: two polygons whose shared edge passes through pixel centres
// (a BSP split, a clipped edge) may compute it from vertices differing in the last bits,
// and would otherwise both round away from the centre and leave it uncovered.
#pragma once

#include <algorithm>
#include <cmath>

#include "image/polygon.h"

namespace oflab {

// Defined here, with crossing and next below, so that the per-row loops of the callers
// inline them (they run for every row of every polygon drawn).
namespace scan_detail {

// A coordinate within rounding of a pixel centre (kTieTolerance, relative to its size) is
// taken as on the centre. Two polygons sharing an edge compute it from their own vertices
// (clipped, transformed), which may differ in the last bits: on an edge through a pixel
// centre one could round the crossing up and the other down, and then neither would
// cover the centre. On the centre exactly, the half-open rule gives it to exactly one.
inline constexpr double kTieTolerance = 1e-9;

inline double snapped_to_centre(double t) {
  const double centre = std::floor(t) + 0.5;
  return std::abs(t - centre) <= kTieTolerance * std::max(1.0, std::abs(t)) ? centre : t;
}

// First integer n with n + 0.5 >= t (t snapped to a centre within rounding), clamped to
// [lo, hi] before conversion to int, so that huge or infinite coordinates cannot overflow.
inline int first_centre_at_or_after(double t, int lo, int hi) {
  const double n = std::ceil(snapped_to_centre(t) - 0.5);
  if (!(n > lo)) return lo;  // also catches NaN
  if (n >= hi) return hi;
  return static_cast<int>(n);
}

}  // namespace scan_detail

// One row's covered pixels: x in [x_begin, x_end) of row y (empty when x_begin >= x_end).
struct PixelSpan {
  int y = 0;
  int x_begin = 0;
  int x_end = 0;
};

// Iterates, top to bottom, over the rows of a convex polygon clipped to the pixel
// rectangle [0, clip_width) x [0, clip_height). Vertex coordinates may be huge (the
// image of a layer close to the horizon): spans are clamped in floating point before
// conversion to int. Holds a reference to the polygon, which must outlive the converter.
class ScanConverter {
 public:
  // Preconditions: clip_width, clip_height >= 0; the polygon satisfies ConvexPolygon's
  // invariants.
  ScanConverter(const ConvexPolygon& polygon, int clip_width, int clip_height);

  // Rows [first_row(), end_row()) may be non-empty; others are certainly empty.
  int first_row() const { return row_; }
  int end_row() const { return end_row_; }

  // Restricts the rows still to come to [begin, end) (a band of a loop on the worker
  // threads); the spans of those rows are the same as without the restriction.
  void clip_rows(int begin, int end) {
    row_ = std::max(row_, begin);
    end_row_ = std::min(end_row_, end);
  }

  // Produces the next row's span (possibly empty) and returns true, or returns false
  // when every row has been produced.
  bool next(PixelSpan& span);

 private:
  // One boundary chain from the top vertex to the bottom vertex.
  struct Chain {
    int vertex = 0;  // start vertex of the current edge
    int step = 1;    // +1 or -1 through the vertex list
  };
  double crossing(Chain& chain, double y) const;

  const std::vector<Vec2>& vertices_;
  int count_ = 0;
  int bottom_ = 0;
  int row_ = 0;
  int end_row_ = 0;
  int clip_width_ = 0;
  Chain left_;
  Chain right_;
};

// Inline definitions (see the top of the file).
inline ScanConverter::ScanConverter(const ConvexPolygon& polygon, int clip_width, int clip_height)
    : vertices_(polygon.vertices()), clip_width_(clip_width) {
  count_ = static_cast<int>(vertices_.size());
  if (polygon.empty() || clip_width <= 0 || clip_height <= 0) {
    row_ = end_row_ = 0;
    return;
  }
  int top = 0;
  for (int k = 1; k < count_; ++k) {
    if (vertices_[k].y < vertices_[top].y) top = k;
    if (vertices_[k].y > vertices_[bottom_].y) bottom_ = k;
  }
  row_ = scan_detail::first_centre_at_or_after(vertices_[top].y, 0, clip_height);
  end_row_ = scan_detail::first_centre_at_or_after(vertices_[bottom_].y, 0, clip_height);
  left_ = Chain{top, 1};
  right_ = Chain{top, -1};
}

inline double ScanConverter::crossing(Chain& chain, double y) const {
  // Advance past every vertex at or above the row centre: the current edge then runs
  // from a vertex with p.y <= y to one with q.y > y (half-open edges, horizontal edges
  // skipped), so the interpolation parameter is in [0, 1).
  // The vertex after v along the chain (a wrap, not a division: this runs for every row).
  const auto after = [&](int v) {
    const int n = v + chain.step;
    return n < 0 ? n + count_ : (n >= count_ ? n - count_ : n);
  };
  for (;;) {
    const int next = after(chain.vertex);
    if (chain.vertex == bottom_ || vertices_[next].y > y) break;
    chain.vertex = next;
  }
  const Vec2& p = vertices_[chain.vertex];
  const Vec2& q = vertices_[after(chain.vertex)];
  if (!(q.y > p.y)) return p.x;
  const double t = (y - p.y) / (q.y - p.y);
  return p.x + t * (q.x - p.x);
}

inline bool ScanConverter::next(PixelSpan& span) {
  if (row_ >= end_row_) return false;
  const double yc = row_ + 0.5;
  const double a = crossing(left_, yc);
  const double b = crossing(right_, yc);
  span.y = row_;
  span.x_begin = scan_detail::first_centre_at_or_after(std::min(a, b), 0, clip_width_);
  span.x_end = scan_detail::first_centre_at_or_after(std::max(a, b), 0, clip_width_);
  ++row_;
  return true;
}

}  // namespace oflab
