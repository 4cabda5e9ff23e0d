// The shared texture of the bundled scenes (dissertation Fig. 25: "all share one texture"):
// an opaque 128 x 128 tile, the butterfly on a framed, lightly chequered ground. Opaque, so
// that the scene animator can skip polygons hidden behind it. The committed
// datasets/textures/tile.png is this function's output; a test keeps them equal.
#pragma once

#include "image/image.h"

namespace oflab {

// Draws the tile (premultiplied, every pixel opaque).
Image make_tile_texture();

}  // namespace oflab
