// Qt colours of the views' colour types, for the views that paint with QPainter.
#pragma once

#include <QColor>

#include "adapters/view_theme.h"
#include "display/palette.h"

namespace oflab {

// A theme colour (components 0..1) as a QColor.
inline QColor to_qcolor(const RgbF& c) { return QColor::fromRgbF(c[0], c[1], c[2]); }
// A palette colour (8-bit sRGB) as a QColor.
inline QColor to_qcolor(const Rgb8& c) { return QColor(c.r, c.g, c.b); }

}  // namespace oflab
