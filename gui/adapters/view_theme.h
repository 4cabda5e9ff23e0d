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
  // Presentation mode's sizes relative to a 1920x1080 window (presentation_scale); 1 in
  // the normal look.
  double scale = 1.0;
};

// The smallest text size presentation mode allows anywhere in a window of 1920x1080 or
// larger, pixels: readable from the back of a classroom on a 1920x1080 projector. A smaller
// window (a 1366x768 projector) scales it with presentation_scale, as the projector shows
// the same picture at the same size with fewer pixels.
constexpr int kPresentationMinTextPx = 18;

// The smallest scale presentation mode shrinks to (a window of 1152x648 or smaller).
constexpr double kPresentationMinScale = 0.6;

// The scale of presentation mode's sizes for a window of `width` x `height` pixels: the
// smaller of width / 1920 and height / 1080, at most 1 and at least kPresentationMinScale
// (1366x768: 0.711).
double presentation_scale(int width, int height);

// The smallest text presentation mode allows at `scale`, pixels: kPresentationMinTextPx
// scaled and rounded down (12 px at 1366x768).
int presentation_min_text_px(double scale);

// The normal look (presentation == false) or presentation mode (true), whose text sizes
// are those of a 1920x1080 window times `scale` (presentation_scale; ignored in the normal
// look).
ViewTheme view_theme(bool presentation, double scale = 1.0);

}  // namespace oflab
