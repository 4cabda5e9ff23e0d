// What a painter writes: every line of text a paint function draws, with its box, recorded on
// a paint device that draws nothing else. Lets a test or a lesson claim ask of a view's own
// painting whether any text is elided, leaves the canvas or overlaps another text.
//
// Units: device pixels of the recorded canvas (top-left origin).
#pragma once

#include <QRectF>
#include <QSize>
#include <QString>
#include <functional>
#include <vector>

class QPainter;

namespace oflab {

// One text item as drawn: its characters and its box (from the baseline's ascent to its
// descent, its advance wide), after the painter's transform.
struct PaintedText {
  QString text;
  QRectF box;
};

// Runs `paint` on a painter over a recording device of `size` and returns the texts it drew,
// in drawing order. Only text is recorded; images, fills and lines are ignored (cheaply).
// Precondition: size is not empty.
std::vector<PaintedText> record_painted_text(const QSize& size,
                                             const std::function<void(QPainter&)>& paint);

// What is wrong with `texts` on a canvas of `size`, one sentence each (empty when nothing is):
// a text elided (it holds an ellipsis, U+2026), a text whose box leaves the canvas by more
// than a pixel, and two texts whose boxes overlap by more than `overlap_px2` square pixels
// and by more than 1.5 px across (lines that touch, or a wrapped text's lines a line spacing
// apart in a font with a negative leading, are not an overlap).
std::vector<QString> text_problems(const std::vector<PaintedText>& texts, const QSize& size,
                                   double overlap_px2 = 4.0);

}  // namespace oflab
