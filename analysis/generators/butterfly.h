// The bundled demo texture: a procedurally drawn butterfly cut-out on a transparent
// background (the dissertation's Experiment 1 used a 243 x 198 butterfly). The committed
// datasets/textures/butterfly.png is this function's output; a test keeps them equal.
#pragma once

#include "image/image.h"

namespace oflab {

// Draws the butterfly into a width x height premultiplied image (default 243 x 198),
// 4 x 4 supersampled. Preconditions: width, height >= 8.
Image make_butterfly(int width = 243, int height = 198);

}  // namespace oflab
