// Porter-Duff "over" compositing of premultiplied layers into a frame.
#pragma once

#include <cstdint>

#include "image/image.h"
#include "image/layer.h"
#include "image/polygon.h"

namespace oflab {

// "Over" for one premultiplied pixel, per channel:
//     out = src + round(dst * (255 - src.a) / 255)
// (exact integer rounding, halves up). The result is well formed when both inputs are.
Pixel over(Pixel src, Pixel dst);

// Composites `layer` over `frame`, with layer pixel (0, 0) placed on frame pixel
// (offset_x, offset_y). Only layer pixels whose centre lies inside layer.polygon (the
// half-open rule of core/image/scan_conversion.h) take part, clipped to the frame; no other
// frame pixel changes. Offsets may be negative or put the layer wholly outside the frame.
// Returns the number of frame pixels composited.
std::int64_t composite_over(Image& frame, const Layer& layer, int offset_x, int offset_y);

// Like composite_over, but only the frame pixels whose centre lies in both the layer's
// polygon (placed at the offset) and `region` (frame pixel coordinates, half-open rule of
// core/image/scan_conversion.h) take part. Regions that partition a layer's polygon therefore
// composite every layer pixel exactly once: the pieces of a polygon split by the BSP tree
// (core/scene/bsp_tree.h) are drawn from the polygon's one layer this way, each restricted to
// its own region, in back-to-front order. Returns the pixel count.
std::int64_t composite_over_region(Image& frame, const Layer& layer, int offset_x, int offset_y,
                                   const ConvexPolygon& region);

}  // namespace oflab
