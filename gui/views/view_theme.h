// Colours and sizes of the VTK views for the two looks of the application: the normal
// dark look and presentation mode (light backgrounds, large text, thick lines, for a
// projector). Qt widgets get the matching palette and font from MainWindow.
#pragma once

#include <array>

namespace oflab {

using RgbF = std::array<double, 3>;  // linear 0..1 components, VTK style

struct ViewTheme {
  bool presentation = false;
  RgbF background;        // view background
  RgbF text;              // captions and legends
  RgbF outline;           // the plane's outline and the image frame
  RgbF streamline;        // streamline colour
  RgbF tile_background;   // gallery tile with a non-zero coefficient
  RgbF muted_background;  // gallery tile whose coefficient is zero
  RgbF muted;             // grid and text of a zero tile
  int font_size = 14;     // caption text, pixels
  double line_width = 1.5;
};

// The normal look (presentation == false) or presentation mode (true).
ViewTheme view_theme(bool presentation);

}  // namespace oflab
