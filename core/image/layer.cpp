// Layer images: construction keeps the polygon inside the image rectangle.
#include "image/layer.h"

#include <utility>

namespace oflab {

Layer make_layer(Image image) {
  ConvexPolygon polygon = ConvexPolygon::rectangle(0.0, 0.0, image.width(), image.height());
  return Layer{std::move(image), std::move(polygon)};
}

Layer make_layer(Image image, const ConvexPolygon& polygon) {
  const BoundingBox frame{0.0, 0.0, static_cast<double>(image.width()),
                          static_cast<double>(image.height())};
  ConvexPolygon clipped = clip_to_box(polygon, frame);
  return Layer{std::move(image), std::move(clipped)};
}

}  // namespace oflab
