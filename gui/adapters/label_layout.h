// Where the texts painted over a 3D picture go: labels placed next to the points they name
// without covering each other or the caption (the teaching layer's rule,
// session/display/label_layout.h, in Qt's types), and captions wrapped to the picture's width
// so that no line is cut. No VTK; the world view (gui/views/world_view.h)
// paints what this places, and gui/adapters/painted_text.h checks the result.
//
// Units: pixels of the picture, top-left origin, y down.
#pragma once

#include <QFontMetricsF>
#include <QPointF>
#include <QPolygonF>
#include <QRectF>
#include <QSizeF>
#include <QString>
#include <vector>

namespace oflab {

// Boxes for labels of `sizes` naming the points `anchors` (same length), in order: each label
// takes the first of its candidate places that stays inside `area` and overlaps neither a
// box in `taken`, a label placed before it (nor its `gap` about it) nor the drawn content `avoid`
// (outlines in the same pixels, e.g. a picture's projected corners); when none is clear of
// everything, the candidate clear of `taken` and the labels that covers the least of `avoid`. The
// candidates are the four corners next to the anchor, `gap` pixels away (right and above first),
// then the same places pushed up or down by whole label heights, nearest first, then pushed further
// (up to 16 label heights and their gaps) up, down, sideways or along a diagonal, nearest first; a
// label that fits nowhere takes the candidate that overlaps least. Boxes are clamped into `area` (a
// label larger than the area is aligned with its top-left corner).
std::vector<QRectF> place_labels(const std::vector<QSizeF>& sizes,
                                 const std::vector<QPointF>& anchors, const QRectF& area,
                                 std::vector<QRectF> taken, double gap = 6.0,
                                 const std::vector<QPolygonF>& avoid = {});

// The area (square pixels) of `box` inside the simple polygon `outline` (clockwise or not;
// convex outlines give the exact area, which is what the world view's pictures are).
double covered_area(const QRectF& box, const QPolygonF& outline);

// The words of `text` in lines no wider than `width` pixels as `metrics` measures them
// (a single word wider than `width` stands alone on its line); "\n" starts a new line.
std::vector<QString> wrap_text(const QString& text, const QFontMetricsF& metrics, double width);

}  // namespace oflab
