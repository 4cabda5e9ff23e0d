// Active-edge scan conversion of convex polygons (dissertation appendix A.1, corrected).
#include "image/scan_conversion.h"

#include <algorithm>
#include <cmath>

namespace oflab {

ScanConverter::ScanConverter(const ConvexPolygon& polygon, int clip_width, int clip_height)
    : vertices_(polygon.vertices()), clip_width_(clip_width) {
  count_ = static_cast<int>(vertices_.size());
  if (polygon.empty() || clip_width <= 0 || clip_height <= 0) {
    row_ = end_row_ = 0;
    return;
  }
  int top = 0;
  for (int k = 1; k < count_; ++k) {
    if (vertices_[k].y < vertices_[top].y) top = k;
    if (vertices_[k].y > vertices_[bottom_].y) bottom_ = k;
  }
  row_ = scan_detail::first_centre_at_or_after(vertices_[top].y, 0, clip_height);
  end_row_ = scan_detail::first_centre_at_or_after(vertices_[bottom_].y, 0, clip_height);
  left_ = Chain{top, 1};
  right_ = Chain{top, -1};
}

}  // namespace oflab
