// Convex polygon clipping (Sutherland-Hodgman, one half-plane at a time) and projective
// transformation, with the horizon clip that keeps erratum 30's precondition true.
#include "image/polygon.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace oflab {
namespace {

constexpr double kPi = 3.14159265358979323846;

double signed_area(const std::vector<Vec2>& v) {
  double twice = 0.0;
  for (std::size_t k = 0; k < v.size(); ++k) {
    twice += cross(v[k], v[next_vertex(k, v.size())]);
  }
  return 0.5 * twice;
}

// Removes neighbours (cyclically) that coincide exactly, in place (every clip and transform
// of a polygon passes here: no second vector).
void drop_duplicate_neighbours(std::vector<Vec2>& v) {
  std::size_t kept = 0;
  for (std::size_t k = 0; k < v.size(); ++k) {
    if (kept == 0 || v[kept - 1] != v[k]) v[kept++] = v[k];
  }
  v.resize(kept);
  while (v.size() > 1 && v.front() == v.back()) v.pop_back();
}

bool finite(const Vec2& p) { return std::isfinite(p.x) && std::isfinite(p.y); }

}  // namespace

ConvexPolygon make_polygon_unchecked(std::vector<Vec2> vertices) {
  drop_duplicate_neighbours(vertices);
  if (signed_area(vertices) < 0.0) std::reverse(vertices.begin(), vertices.end());
  return ConvexPolygon(std::move(vertices));
}

ConvexPolygon ConvexPolygon::from_vertices(std::vector<Vec2> vertices) {
  for (const Vec2& p : vertices) {
    if (!finite(p)) throw std::invalid_argument("ConvexPolygon: vertex is not finite");
  }
  drop_duplicate_neighbours(vertices);
  const std::size_t n = vertices.size();
  if (n >= 3) {
    // Every turn must have the same sign (up to rounding) and the edge directions must
    // wind around exactly once; the second test rejects pentagrams.
    int positive = 0;
    int negative = 0;
    double turning = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
      const Vec2 e0 = vertices[(k + 1) % n] - vertices[k];
      const Vec2 e1 = vertices[(k + 2) % n] - vertices[(k + 1) % n];
      const double c = cross(e0, e1);
      const double tolerance = 1e-9 * glm::length(e0) * glm::length(e1);
      if (c > tolerance) ++positive;
      if (c < -tolerance) ++negative;
      turning += std::atan2(c, glm::dot(e0, e1));
    }
    const bool winds_once =
        positive + negative == 0 || std::abs(std::abs(turning) - 2.0 * kPi) < 1e-6;
    if ((positive > 0 && negative > 0) || !winds_once) {
      throw std::invalid_argument("ConvexPolygon: vertices do not form a convex polygon");
    }
  }
  return make_polygon_unchecked(std::move(vertices));
}

ConvexPolygon ConvexPolygon::rectangle(double x0, double y0, double x1, double y1) {
  if (!std::isfinite(x0) || !std::isfinite(y0) || !std::isfinite(x1) || !std::isfinite(y1)) {
    throw std::invalid_argument("ConvexPolygon::rectangle: bound is not finite");
  }
  if (x1 <= x0 || y1 <= y0) return ConvexPolygon();
  return ConvexPolygon({{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}});
}

bool ConvexPolygon::empty() const { return vertices_.size() < 3 || area() <= 0.0; }

double ConvexPolygon::area() const { return vertices_.size() < 3 ? 0.0 : signed_area(vertices_); }

BoundingBox ConvexPolygon::bounds() const {
  BoundingBox box{vertices_.at(0).x, vertices_.at(0).y, vertices_.at(0).x, vertices_.at(0).y};
  for (const Vec2& p : vertices_) {
    box.x_min = std::min(box.x_min, p.x);
    box.y_min = std::min(box.y_min, p.y);
    box.x_max = std::max(box.x_max, p.x);
    box.y_max = std::max(box.y_max, p.y);
  }
  return box;
}

ConvexPolygon clip_to_half_plane(const ConvexPolygon& polygon, const Vec3& line) {
  const std::vector<Vec2>& v = polygon.vertices();
  std::vector<Vec2> out;
  out.reserve(v.size() + 1);
  for (std::size_t k = 0; k < v.size(); ++k) {
    const Vec2& p = v[k];
    const Vec2& q = v[next_vertex(k, v.size())];
    const double fp = line.x * p.x + line.y * p.y + line.z;
    const double fq = line.x * q.x + line.y * q.y + line.z;
    if (fp >= 0.0) out.push_back(p);
    // A vertex exactly on the line is kept once and never duplicated by a crossing.
    if ((fp > 0.0 && fq < 0.0) || (fp < 0.0 && fq > 0.0)) {
      const double t = fp / (fp - fq);
      out.push_back(p + t * (q - p));
    }
  }
  if (out.size() < 3) return ConvexPolygon();
  return make_polygon_unchecked(std::move(out));
}

ConvexPolygon clip_to_box(const ConvexPolygon& polygon, const BoundingBox& box) {
  ConvexPolygon result = clip_to_half_plane(polygon, {1.0, 0.0, -box.x_min});
  result = clip_to_half_plane(result, {-1.0, 0.0, box.x_max});
  result = clip_to_half_plane(result, {0.0, 1.0, -box.y_min});
  return clip_to_half_plane(result, {0.0, -1.0, box.y_max});
}

ConvexPolygon clip_to_denominator_at_least(const ConvexPolygon& polygon, const Mat3& h,
                                           double min_denominator) {
  return clip_to_half_plane(polygon,
                            {entry(h, 2, 0), entry(h, 2, 1), entry(h, 2, 2) - min_denominator});
}

ConvexPolygon clip_near_horizon(const ConvexPolygon& polygon, const Mat3& h,
                                double relative_epsilon) {
  if (!(relative_epsilon > 0.0 && relative_epsilon < 1.0)) {
    throw std::invalid_argument("clip_near_horizon: relative_epsilon must be in (0, 1)");
  }
  double largest = 0.0;
  for (const Vec2& p : polygon.vertices()) {
    largest = std::max(largest, homography_denominator(h, p));
  }
  if (!(largest > 0.0)) return ConvexPolygon();
  return clip_to_denominator_at_least(polygon, h, relative_epsilon * largest);
}

ConvexPolygon transform(const ConvexPolygon& polygon, const Mat3& h) {
  std::vector<Vec2> out;
  out.reserve(polygon.size());
  for (const Vec2& p : polygon.vertices()) {
    const double w = homography_denominator(h, p);
    if (!(w > 0.0)) {
      throw std::invalid_argument(
          "transform: a vertex maps onto or beyond the horizon line (denominator <= 0); "
          "clip the polygon with clip_near_horizon first");
    }
    const Vec2 q = apply_homography(h, p);
    if (!finite(q)) throw std::invalid_argument("transform: a mapped vertex is not finite");
    out.push_back(q);
  }
  return make_polygon_unchecked(std::move(out));
}

ConvexPolygon translated(const ConvexPolygon& polygon, double dx, double dy) {
  std::vector<Vec2> out = polygon.vertices();
  for (Vec2& p : out) p += Vec2(dx, dy);
  return make_polygon_unchecked(std::move(out));
}

bool contains(const ConvexPolygon& polygon, const Vec2& p) {
  return !polygon.empty() && within_vertices(polygon.vertices(), p);
}

}  // namespace oflab
