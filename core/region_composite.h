// "Over" compositing of part of a layer: the pieces of a polygon split by the BSP tree
// (core/bsp_tree.h) are drawn from the polygon's one layer, each restricted to its own
// region, in back-to-front order.
#pragma once

#include <cstdint>

#include "core/image.h"
#include "core/layer.h"

namespace oflab {

// Like composite_over (core/composite.h), but only the frame pixels whose centre lies in
// both the layer's polygon (placed at the offset) and `region` (frame pixel coordinates,
// half-open rule of core/scan_conversion.h) take part. Regions that partition a layer's
// polygon therefore composite every layer pixel exactly once. Returns the pixel count.
std::int64_t composite_over_region(Image& frame, const Layer& layer, int offset_x, int offset_y,
                                   const ConvexPolygon& region);

}  // namespace oflab
