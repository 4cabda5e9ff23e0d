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
// All coordinates are top-left pixels (core/image.h).
#pragma once

#include <vector>

#include "core/polygon.h"

namespace oflab {

// The polygon shrunk by `margin` pixels: the points at least `margin` inside every edge.
// May be empty. Precondition: margin >= 0.
ConvexPolygon eroded(const ConvexPolygon& polygon, double margin);

// A convex polygon containing every point within `margin` pixels (in both x and y) of the
// polygon: the convex hull of its vertices moved by (+-margin, +-margin).
ConvexPolygon dilated(const ConvexPolygon& polygon, double margin);

class OcclusionTest {
 public:
  // Forgets every occluder (call once per frame).
  void clear() { occluders_.clear(); }

  // Adds the region (already made conservative by the caller: only pixels certainly drawn
  // opaque) of a polygon drawn after every candidate tested from now on.
  void add_occluder(const ConvexPolygon& region);

  // True when `region` lies within the union of the occluders, up to pieces of area below
  // 1e-6 square pixels. Gives up (returns false) when the pieces multiply beyond a few
  // hundred, which only very fragmented occluder sets cause.
  bool covers(const ConvexPolygon& region) const;

  std::size_t occluder_count() const { return occluders_.size(); }

 private:
  struct Occluder {
    ConvexPolygon polygon;
    BoundingBox box;
  };
  std::vector<Occluder> occluders_;
};

}  // namespace oflab
