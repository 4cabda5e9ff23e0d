// What the flow view shows: which part of the flow and how it is drawn. Plain C++, part of
// the window's state (session/state/window_state.h), so lessons and saved sessions carry it.
//
// The drawing options are also listed in flow_draw_options(), with their key in session
// and lesson files, their label and their tooltip: the session reader and writer, the
// state's comparison and the flow view's check boxes all go through that list, so a new
// option is a member here, a row of the list, its drawing (gui/adapters/flow_renderer.cpp)
// and its test.
#pragma once

#include <vector>

#include "display/flow_parts.h"

namespace oflab {

// What the flow view shows.
struct FlowDisplay {
  FlowPart part = FlowPart::kFull;
  bool arrows = true;         // arrow glyphs on a grid
  bool streamlines = false;   // short streamlines of the shown part
  bool colour_wheel = false;  // colour-wheel coding of the shown part, with its legend
  bool texture = true;        // the faint texture on the plane
  bool zoom_to_plane = true;  // fit the view to the plane's image (and the principal
                              // point) instead of the whole image
  bool common_scale = false;  // arrows of every part drawn at the full flow's scale (compare
                              // parts by length); otherwise each part fills the grid
  // Arrow grid spacing in image pixels (4 .. 1000); 0 picks one from the size of the plane's
  // image (about 14 arrows across it, 6 to 48 pixels apart).
  double spacing_px = 0.0;
};

// One on/off drawing option of the flow view.
struct FlowDrawOption {
  const char* key;       // in session and lesson files: "colour_wheel"
  const char* cli_name;  // in `oflab --flow-draw`: "wheel"
  const char* label;     // check box: "Colour wheel"
  const char* tooltip;   // what it draws
  bool FlowDisplay::*member;
};

// Every drawing option, in the order of the view's check boxes.
inline const std::vector<FlowDrawOption>& flow_draw_options() {
  static const std::vector<FlowDrawOption> options = {
      {"arrows", "arrows", "Arrows",
       "Arrows of the chosen part of the flow, length in pixels per second times the arrow "
       "scale; colour is the magnitude, px/s",
       &FlowDisplay::arrows},
      {"streamlines", "streamlines", "Streamlines",
       "Paths a point would follow in the instantaneous field", &FlowDisplay::streamlines},
      {"colour_wheel", "wheel", "Colour wheel",
       "Colour the plane by the flow: hue is the direction, saturation the magnitude",
       &FlowDisplay::colour_wheel},
      {"texture", "texture", "Texture", "Show the plane's texture under the flow",
       &FlowDisplay::texture},
      {"zoom_to_plane", "zoom", "Zoom to plane",
       "Fit the view to the plane's image instead of the whole image", &FlowDisplay::zoom_to_plane},
      {"common_scale", "common-scale", "Common scale",
       "Draw every part at the full flow's arrow scale, so parts compare by length",
       &FlowDisplay::common_scale},
  };
  return options;
}

}  // namespace oflab
