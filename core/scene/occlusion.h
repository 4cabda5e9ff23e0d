// Whole-polygon occlusion in the image: is a polygon's image wholly covered by the images
// of opaque polygons drawn after it? Beyond the dissertation, whose section 7.5.3 names the
// weakness: its BSP compositing warped every polygon in the frustum, "even if that polygon
// turns out to be partially or totally occluded". Here a wholly covered polygon is not
// updated at all.
//
// The test is geometric (no pixel buffer): the candidate's region is cut by every
// occluder in turn (the part outside each occluder edge is kept as a convex piece, the part
// inside is dropped) and it is covered when no piece of positive area is left. So a polygon
// hidden behind several neighbouring occluders, none of which covers it alone, is found too.
// All coordinates are top-left pixels (core/image/image.h).
#pragma once

#include <cstdint>
#include <vector>

#include "image/polygon.h"

namespace oflab {

// The polygon shrunk by `margin` pixels: the points at least `margin` inside every edge.
// May be empty. Precondition: margin >= 0.
ConvexPolygon eroded(const ConvexPolygon& polygon, double margin);

// A convex polygon containing every point within `margin` pixels (in both x and y) of the
// polygon: the convex hull of its vertices moved by (+-margin, +-margin).
ConvexPolygon dilated(const ConvexPolygon& polygon, double margin);

class OcclusionTest {
 public:
  // Forgets every occluder; call once per frame. The occluders are binned on a grid over
  // the frame (width x height pixels) grown by its size on every side.
  void clear(int width = 1024, int height = 1024);

  // Adds the region of a polygon drawn (opaque) after every candidate tested from now on,
  // placed at `offset` and shrunk by `inset` pixels (eroded): only pixels the caller is
  // sure are painted opaque may hide anything. Precondition: inset >= 0.
  void add_occluder(const ConvexPolygon& region, double inset = 0.0, Vec2 offset = Vec2(0.0));

  // True when `region`, grown by `margin` pixels (see dilated), lies within the union of
  // the occluders, up to pieces of area below 1e-6 square pixels. Gives up (returns false)
  // when the pieces multiply beyond a few hundred, which only very fragmented occluder sets
  // cause.
  bool covers(const ConvexPolygon& region, double margin = 0.0) const;
  // As covers, with the `extra` regions (top-left pixels, not shrunk, not kept) counted as
  // occluders too, after the kept ones; *gave_up, when given, is set when it gave up (then
  // it returns false though the region may be covered).
  bool covers(const ConvexPolygon& region, double margin, const std::vector<ConvexPolygon>& extra,
              bool* gave_up) const;

  std::size_t occluder_count() const { return occluders_.size(); }

 private:
  // An occluder is kept as the lines of its edges, moved inwards by the inset: their
  // half-planes intersect in the eroded polygon, which is never built.
  struct Occluder {
    std::vector<Vec3> lines;  // l.x x + l.y y + l.z >= 0 inside, (l.x, l.y) unit
    BoundingBox box;
  };
  bool inside(const Occluder& o, const Vec2& p) const;
  // The occluder of `region` at `offset` shrunk by `inset`; false when nothing is left.
  static bool make_occluder(const ConvexPolygon& region, double inset, Vec2 offset, Occluder& o);
  // Occluders are binned on a grid of kGridCells x kGridCells cells over the grown frame,
  // so a candidate is cut only by the occluders near it: a frame of a thousand polygons
  // stays cheap to test. Occluders reaching beyond the grid, or spanning many cells, are
  // kept in wide_ and checked for every candidate.
  static constexpr int kGridCells = 96;
  static constexpr int kMaxCellsPerOccluder = 256;
  struct Grid {
    Vec2 origin{-1024.0, -1024.0};
    Vec2 cell{32.0, 32.0};
  };
  void nearby(const BoundingBox& box, std::vector<int>& out) const;

  Grid grid_;

  std::vector<Occluder> occluders_;
  std::vector<std::vector<int>> cells_;  // kGridCells^2, allocated on first use
  std::vector<int> touched_;             // cells holding occluders, to clear
  std::vector<int> wide_;
  mutable std::vector<int> stamp_;  // per occluder: last query that collected it
  mutable int query_ = 0;
};

}  // namespace oflab
