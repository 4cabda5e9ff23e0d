// The nodes and the error metric of Shade et al.'s hierarchical image cache (Shade,
// Lischinski, Salesin, DeRose and Snyder 96; dissertation section 2.4.7): the geometry of a
// node of the scene's BSP tree (or of a cluster of nodes) is rendered into one image on a
// quadrilateral through the node's centre facing the viewer, and that image is reused, warped
// by the quad's homography, until an angular error says otherwise. The policy that plays them
// is `hierarchical-cache` (core/scene/hierarchical_cache.h, manual/policies.md).
//
// Grouping (group_cache_nodes). A subtree of the BSP tree whose fragments belong to at most
// `max_polygons` distinct polygons is one node (a cluster); a larger subtree gives its
// splitting plane's own fragments a node of their own and groups its two subtrees the same
// way. So every fragment is in exactly one node and a node's fragments are contiguous in every
// back-to-front order of the tree: nodes can be painted back to front like fragments.
//
// The angular metric. A point P of the node was cached where the ray from the cache's eye E0
// through P meets the quad, at P' (point_on_quad). Seen from an eye E, the cached image shows
// P at P', so the error of P is the angle at E between the rays to P and to P'
// (angular_error); the node's error is the largest over the eight corners of its bounding box
// (node_angular_error). At E = E0 it is zero, and it does not depend on the viewer's rotation.
//
// The safety sphere (safety_radius). E0, P' and P lie on one ray, at distances a and b from
// E0. An eye E within r of E0 (r < min(a, b)) sees the segment P'P under the angle
// atan(h |b - a| / ((a - x)(b - x) + h^2)), with x the component of E - E0 along the ray and h
// the distance of E from the ray; since x, h <= r that is at most
// atan(r |b - a| / ((a - r)(b - r))). The radius is the largest r for which this bound stays
// within the threshold at every corner, the smaller root of
// tan(t) r^2 - (tan(t)(a + b) + |b - a|) r + tan(t) a b = 0: inside the sphere no corner's
// angle can exceed the threshold (a conservative sphere, as Shade et al.'s).
//
// World units and world coordinates throughout; angles in radians unless named _deg.
#pragma once

#include <array>
#include <vector>

#include "flow/camera.h"
#include "flow/geometry.h"
#include "scene/bsp_tree.h"

namespace oflab {

// The policy's options (SceneSettings::cache; limits in core/flow/limits.h).
struct CacheSettings {
  double angle_deg = 0.2;     // re-render when a corner's angular error exceeds this, degrees
  int max_node_polygons = 8;  // the grouping rule: polygons per cluster, at most
  // The safety sphere's radius, world units; 0 is automatic: safety_radius of the threshold.
  double safety_radius = 0.0;
};

struct CacheNode {
  std::vector<int> fragments;  // indices into BspTree::fragments()
  std::vector<int> polygons;   // the distinct scene polygons of those fragments, ascending
  Vec3 box_min{0.0};           // axis-aligned bounding box of the fragments, world units
  Vec3 box_max{0.0};
  bool cluster = false;  // a whole subtree (else one splitting plane's own fragments)

  Vec3 centre() const { return 0.5 * (box_min + box_max); }
  std::array<Vec3, 8> corners() const;
};

// The nodes of `tree` by the rule above, in the tree's order (a subtree's back part, its
// plane, its front part). Precondition: max_polygons >= 1.
std::vector<CacheNode> group_cache_nodes(const BspTree& tree, int max_polygons);

// The quad of a node cached from `eye`: the plane through the node's centre whose normal is
// the unit direction from the eye to the centre. Precondition: eye != centre.
struct CacheQuad {
  Vec3 eye{0.0};
  Vec3 centre{0.0};
  Vec3 normal{0.0, 0.0, 1.0};
};
CacheQuad cache_quad(const Vec3& eye, const Vec3& centre);

// Depth of `p` beyond the eye along the quad's normal; a point with depth <= 0 cannot be
// projected onto the quad.
double quad_depth(const CacheQuad& quad, const Vec3& p);

// Where the ray from the quad's eye through `p` meets the quad's plane.
// Precondition: quad_depth(quad, p) > 0.
Vec3 point_on_quad(const CacheQuad& quad, const Vec3& p);

// The angle at `eye` between the rays to `p` and to `shown`, radians in [0, pi]
// (atan2 of the cross and dot products). Precondition: neither point is the eye.
double angular_error(const Vec3& eye, const Vec3& p, const Vec3& shown);

// The largest angular_error over `corners` of their cached points (point_on_quad), seen
// from `eye`. Precondition: every corner has quad_depth > 0.
double node_angular_error(const CacheQuad& quad, const std::array<Vec3, 8>& corners,
                          const Vec3& eye);

// The image size of an angular error at a point: the largest distance, pixels, between the
// projection of `p` (viewer frame, Z > 0) and the projection of any ray within `angle`
// radians of the ray to p. With phi the angle between that ray and the optical axis, the rays
// within `angle` project to an ellipse whose long axis runs from f tan(phi - angle) to
// f tan(phi + angle) through p's projection; its farthest point from p's projection is the
// outer end, so the size is f (tan(phi + angle) - tan(phi)): f tan(angle) on the axis, about
// f angle / cos^2(phi) off it. Infinite when phi + angle reaches pi / 2 (the error may leave
// the image plane). Precondition: p.z > 0, 0 <= angle < pi / 2.
double angle_in_pixels(const Camera& camera, const Vec3& p, double angle);

// The radius of the conservative safety sphere around quad.eye for `threshold` radians
// (see above), world units; 0 when a corner has quad_depth <= 0.
// Precondition: 0 < threshold < pi / 2.
double safety_radius(const CacheQuad& quad, const std::array<Vec3, 8>& corners, double threshold);

// Why a node cached with `quad` must be re-rendered when the eye is at `eye`: kNone when it
// may be reused. The angle is checked first; the sphere (radius, world units) second.
enum class CacheRenderCause { kNone, kAngle, kSphere };
CacheRenderCause cache_render_cause(const CacheQuad& quad, const std::array<Vec3, 8>& corners,
                                    double radius, const Vec3& eye, double threshold);

}  // namespace oflab
