// Where labels go over a picture: each label next to the point it names, off the other labels,
// off texts already there and, as far as it can, off the drawn content. The desktop's world
// view (gui/views/world_texts.h, through gui/adapters/label_layout.h) and the page's
// (web/world_view.js) place their labels with this one rule. No Qt.
//
// Units: pixels of the picture, top-left origin, y down.
#pragma once

#include <vector>

#include "flow/geometry.h"

namespace oflab {

// An axis-aligned box: top-left corner and size, pixels (width, height >= 0).
struct LabelBox {
  double x = 0.0, y = 0.0, width = 0.0, height = 0.0;
  double right() const { return x + width; }
  double bottom() const { return y + height; }
  // This box grown by `d` on every side (shrunk for d < 0).
  LabelBox grown(double d) const { return {x - d, y - d, width + 2 * d, height + 2 * d}; }
  bool operator==(const LabelBox& o) const {
    return x == o.x && y == o.y && width == o.width && height == o.height;
  }
};

// Boxes for labels of `sizes` (width, height) naming the points `anchors` (same length), in
// order: each label takes the first of its candidate places that stays inside `area` and
// overlaps neither a box in `taken`, a label placed before it (nor its `gap` about it) nor the
// drawn content `avoid` (polygons in the same pixels, e.g. a picture's projected corners); when
// none is clear of everything, the candidate clear of `taken` and the labels that covers the
// least of `avoid`. The candidates are the four corners next to the anchor, `gap` pixels away
// (right and above first), then the same places pushed up or down by whole label heights,
// nearest first, then pushed further (up to 16 label heights and their gaps) up, down,
// sideways or along a diagonal, nearest first; a label that fits nowhere takes the candidate
// that overlaps least. Boxes are clamped into `area` (a label larger than the area is aligned
// with its top-left corner).
std::vector<LabelBox> place_labels(const std::vector<Vec2>& sizes, const std::vector<Vec2>& anchors,
                                   const LabelBox& area, std::vector<LabelBox> taken,
                                   double gap = 6.0,
                                   const std::vector<std::vector<Vec2>>& avoid = {});

// The area (square pixels) of `box` inside the simple polygon `outline` (clockwise or not;
// convex outlines give the exact area, which is what the world view's pictures are).
double covered_area(const LabelBox& box, const std::vector<Vec2>& outline);

}  // namespace oflab
