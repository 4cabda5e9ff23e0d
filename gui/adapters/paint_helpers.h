// Small Qt helpers of the views that paint with QPainter: the views' colour types as Qt
// colours, and the area of a painted polygon.
#pragma once

#include <QColor>
#include <QPolygonF>
#include <cmath>

#include "adapters/view_theme.h"
#include "display/palette.h"

namespace oflab {

// A theme colour (components 0..1) as a QColor.
inline QColor to_qcolor(const RgbF& c) { return QColor::fromRgbF(c[0], c[1], c[2]); }
// A palette colour (8-bit sRGB) as a QColor.
inline QColor to_qcolor(const Rgb8& c) { return QColor(c.r, c.g, c.b); }

// The area of a simple polygon (its vertices in order, either orientation; the shoelace
// formula), in the square of its coordinates' unit; 0 for fewer than three vertices.
inline double polygon_area(const QPolygonF& polygon) {
  double twice = 0.0;
  for (int i = 0; i < polygon.size(); ++i) {
    const QPointF& a = polygon[i];
    const QPointF& b = polygon[(i + 1) % polygon.size()];
    twice += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5 * std::abs(twice);
}

}  // namespace oflab
