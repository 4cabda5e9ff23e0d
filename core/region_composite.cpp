// Compositing restricted to a convex region of the frame (see core/region_composite.h).
#include "core/region_composite.h"

#include <algorithm>

#include "core/composite.h"
#include "core/scan_conversion.h"

namespace oflab {

std::int64_t composite_over_region(Image& frame, const Layer& layer, int offset_x, int offset_y,
                                   const ConvexPolygon& region) {
  if (layer.empty() || frame.empty() || region.empty()) return 0;
  // The intersection of two convex polygons: the layer's polygon (in frame coordinates)
  // clipped by each edge of the region.
  ConvexPolygon polygon = translated(layer.polygon, offset_x, offset_y);
  const std::vector<Vec2>& v = region.vertices();
  for (std::size_t k = 0; k < v.size() && !polygon.empty(); ++k) {
    const Vec2 e = v[(k + 1) % v.size()] - v[k];
    polygon = clip_to_half_plane(polygon, Vec3(-e.y, e.x, e.y * v[k].x - e.x * v[k].y));
  }
  if (polygon.empty()) return 0;
  ScanConverter scan(polygon, frame.width(), frame.height());
  std::int64_t count = 0;
  PixelSpan span;
  while (scan.next(span)) {
    const std::int64_t ly = std::int64_t{span.y} - offset_y;
    const int begin = static_cast<int>(std::max<std::int64_t>(span.x_begin, offset_x));
    const int end = static_cast<int>(
        std::min<std::int64_t>(span.x_end, std::int64_t{offset_x} + layer.image.width()));
    if (begin >= end || ly < 0 || ly >= layer.image.height()) continue;
    const Pixel* src = layer.image.row(static_cast<int>(ly)) + (begin - offset_x);
    Pixel* dst = frame.row(span.y) + begin;
    for (int k = 0; k < end - begin; ++k) {
      if (src[k].a == 255) {
        dst[k] = src[k];
      } else if (src[k].a != 0) {
        dst[k] = over(src[k], dst[k]);
      }
    }
    count += end - begin;
  }
  return count;
}

}  // namespace oflab
