// Convex polygons in continuous pixel coordinates (x right, y down; pixel (i, j) covers
// [i, i+1) x [j, j+1), see core/image/image.h): the bounding polygon of a layer image
// (dissertation appendix A.1, figs. 27-28), its clipping and its transformation by a
// homography.
//
// Projective maps send convex polygons to convex polygons only when the homography's
// denominator g*x + h*y + i keeps one sign over the polygon (erratum 30 of
// manual/theory.md#errata). clip_near_horizon() enforces that before transform() is applied.
#pragma once

#include <vector>

#include "flow/geometry.h"

namespace oflab {

// Axis-aligned box [x_min, x_max] x [y_min, y_max], in pixel coordinates.
struct BoundingBox {
  double x_min = 0.0;
  double y_min = 0.0;
  double x_max = 0.0;
  double y_max = 0.0;
};

// The index after vertex k of a cyclic list of n vertices (0 after n - 1), k < n: the wrap as
// a comparison, not a division (the per-vertex loops of clipping and scan set-up run for
// every face of every render).
inline std::size_t next_vertex(std::size_t k, std::size_t n) { return k + 1 == n ? 0 : k + 1; }

// A convex polygon given by its vertices in order. Invariants: every coordinate is
// finite, the vertex cycle is convex and it is ordered so that its shoelace area
// sum(x_k * y_{k+1} - x_{k+1} * y_k) / 2 is >= 0 (clockwise on screen, where y points
// down). A polygon with fewer than 3 vertices or zero area is "empty": it covers no
// pixel. The default-constructed polygon is empty.
class ConvexPolygon {
 public:
  ConvexPolygon() = default;

  // Validates and orders the vertices. Consecutive duplicate vertices are merged and
  // either orientation is accepted. Throws std::invalid_argument if a coordinate is not
  // finite or if the cycle is not convex (a turn against the others by more than a
  // relative 1e-9, or a star-shaped cycle that winds more than once).
  static ConvexPolygon from_vertices(std::vector<Vec2> vertices);

  // The rectangle [x0, x1] x [y0, y1]; empty if x1 <= x0 or y1 <= y0.
  // Throws std::invalid_argument on a non-finite bound.
  static ConvexPolygon rectangle(double x0, double y0, double x1, double y1);

  const std::vector<Vec2>& vertices() const { return vertices_; }
  std::size_t size() const { return vertices_.size(); }

  // True when the polygon covers no area (fewer than 3 vertices or zero area).
  bool empty() const;

  // Area in square pixels (>= 0).
  double area() const;

  // Smallest box containing every vertex. Precondition: size() > 0.
  BoundingBox bounds() const;

 private:
  friend ConvexPolygon make_polygon_unchecked(std::vector<Vec2> vertices);
  explicit ConvexPolygon(std::vector<Vec2> vertices) : vertices_(std::move(vertices)) {}

  std::vector<Vec2> vertices_;
};

// Wraps vertices that are convex by construction (results of clipping and transforming
// a valid polygon), fixing only the orientation and dropping duplicate neighbours.
// Not for user input: use ConvexPolygon::from_vertices there.
ConvexPolygon make_polygon_unchecked(std::vector<Vec2> vertices);

// Keeps the part of `polygon` where line.x * x + line.y * y + line.z >= 0
// (Sutherland-Hodgman against one half-plane). The result is convex, possibly empty.
ConvexPolygon clip_to_half_plane(const ConvexPolygon& polygon, const Vec3& line);

// Keeps the part of `polygon` inside the box [box.x_min, box.x_max] x [box.y_min, box.y_max].
ConvexPolygon clip_to_box(const ConvexPolygon& polygon, const BoundingBox& box);

// Keeps the part of `polygon` where the denominator of `h` (homography_denominator in
// core/flow/geometry.h, i.e. g*x + h*y + i with h's bottom row) is at least
// `min_denominator`. With min_denominator > 0 the result maps to a bounded convex
// polygon under h. The sign convention of h matters: h and -h are the same map, but
// only the side where the caller's h has a positive denominator is kept.
ConvexPolygon clip_to_denominator_at_least(const ConvexPolygon& polygon, const Mat3& h,
                                           double min_denominator);

// Horizon clip used by the warps: keeps the part where the denominator of h is at least
// relative_epsilon times its largest value over the polygon's vertices. The warped
// result is then at most about 1/relative_epsilon times larger than the image of the
// polygon's least magnified point. Returns an empty polygon if the denominator is <= 0
// at every vertex (the whole polygon is behind the viewer or on the horizon line).
// Precondition: 0 < relative_epsilon < 1 (throws std::invalid_argument otherwise).
ConvexPolygon clip_near_horizon(const ConvexPolygon& polygon, const Mat3& h,
                                double relative_epsilon);

// Maps every vertex through h (apply_homography) and re-orders the result. Exact
// image of the polygon when the denominator of h is positive at every vertex, which
// clip_near_horizon guarantees. Throws std::invalid_argument if a denominator is <= 0 or
// a mapped coordinate is not finite. An empty polygon maps to an empty polygon.
ConvexPolygon transform(const ConvexPolygon& polygon, const Mat3& h);

// Translates by (dx, dy) pixels.
ConvexPolygon translated(const ConvexPolygon& polygon, double dx, double dy);

// True if p lies inside or on the boundary of the polygon (false for an empty polygon).
bool contains(const ConvexPolygon& polygon, const Vec2& p);

// contains' test of a non-empty polygon's vertex cycle v (ConvexPolygon::vertices), without
// its emptiness check, for a loop that checked it once (inline: a shaded render runs it per
// sample): no edge has p strictly on its outer side.
inline bool within_vertices(const std::vector<Vec2>& v, const Vec2& p) {
  for (std::size_t k = 0; k < v.size(); ++k) {
    const Vec2& a = v[k];
    const Vec2& b = v[next_vertex(k, v.size())];
    if (cross(b - a, p - a) < 0.0) return false;
  }
  return true;
}

}  // namespace oflab
