// Core frames as the pixels of a 2D canvas (ImageData: straight-alpha RGBA8, row after row):
// a premultiplied frame flattened over an opaque background, and the difference of two
// frames as a heat map. Colour mapping for display only; what the frames show is core's.
#pragma once

#include <cstdint>
#include <vector>

#include "image/image.h"

namespace oflab {

// `frame` (premultiplied RGBA) composited over the opaque colour (r, g, b) into `out`,
// 4 bytes per pixel, resized to frame.width() * frame.height() * 4.
void flatten_into(const Image& frame, std::uint8_t r, std::uint8_t g, std::uint8_t b,
                  std::vector<std::uint8_t>& out);

// The difference of two frames of the same size as a heat map into `out` (opaque RGBA8):
// per pixel the largest absolute difference of the four premultiplied channels, in grey
// levels, coloured by the viridis ramp from 0 (dark blue) to `full_scale` and above (yellow).
// Returns the largest difference found (grey levels, 0..255). Preconditions: same size,
// full_scale >= 1.
int difference_heat_map_into(const Image& a, const Image& b, int full_scale,
                             std::vector<std::uint8_t>& out);

// The viridis colour of t in [0, 1] (clamped) as r, g, b bytes: the heat map's ramp, also
// for the page's colour bar.
void viridis(double t, std::uint8_t rgb[3]);

}  // namespace oflab
