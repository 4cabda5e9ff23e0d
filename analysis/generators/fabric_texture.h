// The texture of the receding plane (datasets/scripts/recede.json, the sampling experiment and
// the lesson shrinking-without-shimmering): the butterfly on a finely woven ground, a 512 x 416
// texel chequer of 2 x 2 texel cells, whose detail sits at the texel scale so that a minified
// warp that skips texels shows it as moiré. Opaque. The committed datasets/textures/fabric.png
// is this function's output; a test keeps them equal.
#pragma once

#include "image/image.h"

namespace oflab {

// Draws the fabric (premultiplied, every pixel opaque).
Image make_fabric_texture();

}  // namespace oflab
