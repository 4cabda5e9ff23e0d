// Core frames as the pixels of a 2D canvas (ImageData: straight-alpha RGBA8, row after row),
// at the size the page shows them: a premultiplied frame flattened over an opaque
// background, and the difference of two frames as a heat map. Colour mapping and display
// sampling only; what the frames show is core's.
#pragma once

#include <cstdint>
#include <vector>

#include "image/image.h"
#include "image/polygon.h"  // BoundingBox

namespace oflab {

// A display of out_width x out_height pixels showing a whole frame: display pixel (x, y)
// shows the frame pixel under its centre (nearest neighbour). Preconditions: out sizes >= 1.
struct DisplaySampling {
  std::vector<int> columns;  // frame column of each display column
  std::vector<int> rows;     // frame row of each display row
};
DisplaySampling display_sampling(int frame_width, int frame_height, int out_width, int out_height);

// A display of out_width x out_height pixels showing part of a frame (or reaching beyond it):
// display pixel (x, y) shows the frame pixel under the point (x0 + (x + 0.5) * pixel,
// y0 + (y + 0.5) * pixel) in top-left frame pixels (nearest neighbour), or index -1 where
// that point lies outside the frame (shown as the background). Preconditions: out sizes >= 1,
// pixel > 0 (frame pixels per display pixel).
DisplaySampling region_sampling(int frame_width, int frame_height, double x0, double y0,
                                double pixel, int out_width, int out_height);

// The part `frame` (camera pixels) of a camera image shown in a panel fitted into a cell of
// cell_width x cell_height display pixels (each >= 1): the largest panel of the frame's aspect
// within the cell (at least 1 x 1), whose pixel (x, y) shows the camera pixel under (x0 + (x +
// 0.5) pixel, y0 + (y + 0.5) pixel) (region_sampling), centred on the frame's centre.
struct PanelView {
  int width = 1, height = 1;  // the panel, display pixels
  double x0 = 0.0, y0 = 0.0;  // its top-left corner, camera pixels
  double pixel = 1.0;         // camera pixels per display pixel
};
PanelView fit_panel_view(const BoundingBox& frame, int cell_width, int cell_height);

// `sampling` of a frame moved onto an image placed at (offset_x, offset_y) of it, of width x
// height pixels (a layer's): every index less the offset, -1 where it falls outside the
// image (or was -1).
void shift_sampling(DisplaySampling& sampling, int offset_x, int offset_y, int width, int height);

// `frame` (premultiplied RGBA) composited over the opaque colour (r, g, b) and sampled by
// `sampling` into `out`, 4 bytes per display pixel (resized to fit); a sampling index of -1
// shows the background. With opacity < 1 the composited frame is faded towards the
// background: background + opacity * (composited - background), rounded (opacity in [0, 1];
// 1 leaves it as composited).
void flatten_into(const Image& frame, const DisplaySampling& sampling, const std::uint8_t rgb[3],
                  std::vector<std::uint8_t>& out, double opacity = 1.0);

// The largest absolute difference of the four premultiplied channels over all pixels of two
// frames, in grey levels (0..255). Precondition: same size (throws std::invalid_argument).
int largest_difference(const Image& a, const Image& b);

// The difference of two frames as a heat map sampled by `sampling` into `out` (opaque RGBA8):
// per pixel the largest absolute difference of the four premultiplied channels, in grey
// levels, coloured by the one viridis ramp (session/display/palette.h magnitude_colour) from 0
// (dark blue) to `full_scale` and above (yellow); off the frame (a sampling index of -1) the
// colour of no difference. Preconditions: same size (throws std::invalid_argument),
// full_scale >= 1.
void difference_heat_map_into(const Image& a, const Image& b, int full_scale,
                              const DisplaySampling& sampling, std::vector<std::uint8_t>& out);

}  // namespace oflab
