// Active-edge scan conversion of convex polygons (dissertation appendix A.1, corrected).
#include "image/scan_conversion.h"

#include <algorithm>
#include <cmath>

namespace oflab {
namespace {

// A coordinate within rounding of a pixel centre (kTieTolerance, relative to its size) is
// taken as on the centre. Two polygons sharing an edge compute it from their own vertices
// (clipped, transformed), which may differ in the last bits: on an edge through a pixel
// centre one could round the crossing up and the other down, and then neither would
// cover the centre. On the centre exactly, the half-open rule gives it to exactly one.
constexpr double kTieTolerance = 1e-9;

double snapped_to_centre(double t) {
  const double centre = std::floor(t) + 0.5;
  return std::abs(t - centre) <= kTieTolerance * std::max(1.0, std::abs(t)) ? centre : t;
}

// First integer n with n + 0.5 >= t (t snapped to a centre within rounding), clamped to
// [lo, hi] before conversion to int, so that huge or infinite coordinates cannot overflow.
int first_centre_at_or_after(double t, int lo, int hi) {
  const double n = std::ceil(snapped_to_centre(t) - 0.5);
  if (!(n > lo)) return lo;  // also catches NaN
  if (n >= hi) return hi;
  return static_cast<int>(n);
}

}  // namespace

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
  row_ = first_centre_at_or_after(vertices_[top].y, 0, clip_height);
  end_row_ = first_centre_at_or_after(vertices_[bottom_].y, 0, clip_height);
  left_ = Chain{top, 1};
  right_ = Chain{top, -1};
}

double ScanConverter::crossing(Chain& chain, double y) const {
  // Advance past every vertex at or above the row centre: the current edge then runs
  // from a vertex with p.y <= y to one with q.y > y (half-open edges, horizontal edges
  // skipped), so the interpolation parameter is in [0, 1).
  // The vertex after v along the chain (a wrap, not a division: this runs for every row).
  const auto after = [&](int v) {
    const int n = v + chain.step;
    return n < 0 ? n + count_ : (n >= count_ ? n - count_ : n);
  };
  for (;;) {
    const int next = after(chain.vertex);
    if (chain.vertex == bottom_ || vertices_[next].y > y) break;
    chain.vertex = next;
  }
  const Vec2& p = vertices_[chain.vertex];
  const Vec2& q = vertices_[after(chain.vertex)];
  if (!(q.y > p.y)) return p.x;
  const double t = (y - p.y) / (q.y - p.y);
  return p.x + t * (q.x - p.x);
}

bool ScanConverter::next(PixelSpan& span) {
  if (row_ >= end_row_) return false;
  const double yc = row_ + 0.5;
  const double a = crossing(left_, yc);
  const double b = crossing(right_, yc);
  span.y = row_;
  span.x_begin = first_centre_at_or_after(std::min(a, b), 0, clip_width_);
  span.x_end = first_centre_at_or_after(std::max(a, b), 0, clip_width_);
  ++row_;
  return true;
}

}  // namespace oflab
