// Layer images (dissertation appendix A.1, figs. 27-28): an image plus the convex
// polygon that bounds its valid region, in the layer's own pixel coordinates. Warps
// carry the polygon along, so a chain of warps never accumulates empty space (fig. 28)
// and each warp only touches the pixels inside the warped polygon.
#pragma once

#include "image/image.h"
#include "image/polygon.h"

namespace oflab {

// Invariant: `polygon` lies inside [0, image.width()] x [0, image.height()] (the
// constructors clip it). Pixels whose centre lies outside the polygon are not part of the
// layer: compositing ignores them and warps never read them except as bilinear
// neighbours of boundary pixels (they are transparent in every layer a warp creates).
struct Layer {
  Image image;
  ConvexPolygon polygon;

  // True if the layer covers no pixel area.
  bool empty() const { return image.empty() || polygon.empty(); }
};

// A layer whose valid region is the whole image: the polygon is the rectangle
// [0, width] x [0, height] (empty for an empty image).
Layer make_layer(Image image);

// A layer whose valid region is `polygon` clipped to the image rectangle.
Layer make_layer(Image image, const ConvexPolygon& polygon);

}  // namespace oflab
