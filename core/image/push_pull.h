// Push-pull inpainting: the holes of an image filled from an image pyramid of its valid
// pixels (Gortler, Grzeszczuk, Szeliski and Cohen, "The Lumigraph", SIGGRAPH 96, section
// 3.4.2), the inpainting pyramid of frame generation (core/scene/frame_generation.h).
//
// Pull: level 0 is the image, each valid pixel with weight 1 and each hole with weight 0;
// a pixel of level l + 1 is the weighted mean of its (up to) 2 x 2 children of level l, with
// weight min(1, the sum of their weights). Push: from the coarsest level down, each pixel of
// level l takes w c + (1 - w) c_parent, c_parent its parent's pushed colour (pixel (x/2, y/2)
// of level l + 1). So a valid pixel keeps its colour, and a hole takes the mean of the valid
// pixels of the smallest block of the pyramid around it that has any. Colours are the
// premultiplied channels, averaged as single-precision reals and rounded once at the end.
#pragma once

#include <cstdint>
#include <vector>

#include "image/image.h"

namespace oflab {

// Fills the pixels of `image` where `hole` (one entry per pixel, row-major) is nonzero and
// returns how many it filled (0 when there is no valid pixel at all: the image is unchanged).
// Valid pixels are never changed. Precondition: hole.size() == image.pixel_count().
std::int64_t push_pull_inpaint(Image& image, const std::vector<char>& hole);

}  // namespace oflab
