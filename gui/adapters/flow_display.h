// What the flow view shows: which part of the flow and how it is drawn. Plain C++, so
// lesson presets and saved sessions can carry it.
#pragma once

#include "views/flow_parts.h"

namespace oflab {

// What the flow view shows.
struct FlowDisplay {
  FlowPart part = FlowPart::kFull;
  bool arrows = true;         // arrow glyphs on a grid
  bool streamlines = false;   // short streamlines of the shown part
  bool colour_wheel = false;  // colour-wheel coding of the shown part, with its legend
  bool texture = true;        // the faint texture on the plane
  bool common_scale = false;  // arrows of every part drawn at the full flow's scale (compare
                              // parts by length); otherwise each part fills the grid
  bool zoom_to_plane = true;  // fit the view to the plane's image (and the principal
                              // point) instead of the whole image
  // Arrow grid spacing in image pixels (>= 4); 0 picks one from the size of the plane's
  // image (about 14 arrows across it, 6 to 48 pixels apart).
  double spacing_px = 0.0;
};

}  // namespace oflab
