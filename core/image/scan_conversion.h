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

#include "image/polygon.h"

namespace oflab {

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

}  // namespace oflab
