// Colours and sizes of the painted views for the two looks of the application: the normal
// dark look and presentation mode (light backgrounds, large text, thick lines, for a
// projector). Qt widgets get the matching palette and font from MainWindow.
#pragma once

#include <array>

namespace oflab {

using RgbF = std::array<double, 3>;  // linear 0..1 components, VTK style

struct ViewTheme {
  bool presentation = false;
  RgbF background;  // view background
  RgbF text;        // captions and legends
  RgbF outline;     // the plane's outline and the image frame
  // The camera image's area under a frame where nothing is drawn: light enough that a black
  // texel (the butterfly's body) stands apart from it (contrast ratio at least 3 to 1).
  RgbF image_background;
  RgbF streamline;        // streamline colour
  RgbF tile_background;   // gallery tile with a non-zero coefficient
  RgbF muted_background;  // gallery tile whose coefficient is zero
  RgbF muted;             // grid and text of a zero tile
  int font_size = 14;     // captions and titles, pixels
  // The smallest text a view draws (legends, colour-bar and chart labels, axis ticks,
  // tile values), pixels: at least kPresentationMinTextPx in presentation mode.
  int label_size = 12;
  // Qt controls' font, pixels; 0 keeps the platform's font (the normal look).
  int control_font_px = 0;
  double line_width = 1.5;
};

// The smallest text size presentation mode allows anywhere, pixels: readable from the
// back of a classroom on a 1920x1080 projector.
constexpr int kPresentationMinTextPx = 18;

// The normal look (presentation == false) or presentation mode (true).
ViewTheme view_theme(bool presentation);

}  // namespace oflab
