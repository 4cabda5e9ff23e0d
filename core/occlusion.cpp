// Covering test by convex subtraction (see core/occlusion.h).
#include "core/occlusion.h"

#include <algorithm>
#include <cmath>

namespace oflab {
namespace {

constexpr double kNegligibleArea = 1e-6;  // square pixels
constexpr std::size_t kMaxPieces = 256;

// The line of edge a -> b of a polygon with positive signed area (core/polygon.h), as
// (l.x, l.y, l.z) with l.x x + l.y y + l.z >= 0 inside and |(l.x, l.y)| = 1.
Vec3 inside_line(const Vec2& a, const Vec2& b) {
  const Vec2 e = b - a;
  const double length = glm::length(e);
  return Vec3(-e.y, e.x, e.y * a.x - e.x * a.y) / length;
}

bool boxes_overlap(const BoundingBox& a, const BoundingBox& b) {
  return a.x_min < b.x_max && b.x_min < a.x_max && a.y_min < b.y_max && b.y_min < a.y_max;
}

double cross(const Vec2& o, const Vec2& a, const Vec2& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

}  // namespace

ConvexPolygon eroded(const ConvexPolygon& polygon, double margin) {
  if (polygon.empty()) return ConvexPolygon();
  ConvexPolygon result = polygon;
  const std::vector<Vec2>& v = polygon.vertices();
  for (std::size_t k = 0; k < v.size(); ++k) {
    const Vec2& a = v[k];
    const Vec2& b = v[(k + 1) % v.size()];
    if (glm::length(b - a) <= 0.0) continue;
    const Vec3 line = inside_line(a, b);
    result = clip_to_half_plane(result, Vec3(line.x, line.y, line.z - margin));
    if (result.empty()) return ConvexPolygon();
  }
  return result;
}

ConvexPolygon dilated(const ConvexPolygon& polygon, double margin) {
  if (polygon.empty()) return ConvexPolygon();
  std::vector<Vec2> points;
  for (const Vec2& p : polygon.vertices()) {
    for (double dx : {-margin, margin}) {
      for (double dy : {-margin, margin}) points.emplace_back(p.x + dx, p.y + dy);
    }
  }
  // Andrew's monotone chain.
  std::sort(points.begin(), points.end(),
            [](const Vec2& a, const Vec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  std::vector<Vec2> hull(2 * points.size());
  std::size_t k = 0;
  for (const Vec2& p : points) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p) <= 0.0) --k;
    hull[k++] = p;
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return make_polygon_unchecked(std::move(hull));
}

void OcclusionTest::add_occluder(const ConvexPolygon& region) {
  if (region.empty()) return;
  occluders_.push_back({region, region.bounds()});
}

bool OcclusionTest::covers(const ConvexPolygon& region) const {
  if (region.empty()) return true;
  std::vector<ConvexPolygon> pieces{region}, next;
  for (const Occluder& o : occluders_) {
    next.clear();
    const std::vector<Vec2>& v = o.polygon.vertices();
    for (ConvexPolygon& piece : pieces) {
      if (!boxes_overlap(piece.bounds(), o.box)) {
        next.push_back(std::move(piece));
        continue;
      }
      ConvexPolygon inside = std::move(piece);
      for (std::size_t k = 0; k < v.size() && !inside.empty(); ++k) {
        const Vec2& a = v[k];
        const Vec2& b = v[(k + 1) % v.size()];
        if (glm::length(b - a) <= 0.0) continue;
        const Vec3 line = inside_line(a, b);
        ConvexPolygon outside = clip_to_half_plane(inside, -line);
        if (outside.area() > kNegligibleArea) next.push_back(std::move(outside));
        inside = clip_to_half_plane(inside, line);
      }
      if (next.size() > kMaxPieces) return false;
    }
    pieces.swap(next);
    if (pieces.empty()) return true;
  }
  return false;
}

}  // namespace oflab
