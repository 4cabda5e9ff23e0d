// Binary space partitioning of a static scene for back-to-front ordering (dissertation
// section 5.5.1; Fuchs, Kedem and Naylor 1980). Built once per scene; each frame a traversal
// from the eye position gives the painter's order of the polygons' fragments, so layers can
// be composited without a depth buffer.
//
// Each node holds a splitting plane (the plane of one polygon) and the fragments lying in
// it; fragments wholly in front of the plane go to the front subtree, wholly behind to the
// back subtree, and a polygon that straddles the plane is split into two fragments, one for
// each side. Fragments keep their polygon's texture mapping (normalised texture
// coordinates of every vertex), so a split polygon is still drawn from one layer.
//
// Precondition: polygons do not intersect each other (they may touch along edges and may be
// coplanar without overlapping). Intersecting polygons still give an order, but no order
// is then correct for every pixel.
#pragma once

#include <cstdint>
#include <vector>

#include "flow/geometry.h"
#include "scene/scene.h"

namespace oflab {

struct BspFragment {
  int polygon = 0;             // index of the scene polygon it belongs to
  std::vector<Vec3> vertices;  // world coordinates, convex, in outline order
  std::vector<Vec2> uv;        // normalised texture coordinates of the same vertices
  bool whole = true;           // the entire polygon (false for the pieces of a split)
};

// One node of the tree: its splitting plane, the fragments lying in it, and its subtrees
// (indices into BspTree::nodes(), -1 for none). The front subtree holds what lies on the
// side the normal points to.
struct BspNode {
  Vec3 normal{0.0};           // unit normal of the splitting plane
  double offset = 0.0;        // plane: dot(normal, x) == offset
  std::vector<int> coplanar;  // fragment indices
  int front = -1;
  int back = -1;
};

struct BspStats {
  int nodes = 0;
  int fragments = 0;          // >= the number of polygons
  int splits = 0;             // polygons or fragments cut in two while building
  int depth = 0;              // longest root-to-leaf path, in nodes
  std::int64_t vertices = 0;  // of all fragments
};

class BspTree {
 public:
  BspTree() = default;

  // Most fragments a tree may hold. Polygons that do not intersect each other stay far below
  // it (shipped scenes: at most a few splits per polygon); intersecting ones can split
  // without end (3000 random quads give about 150 000 fragments).
  static constexpr int kMaxBspFragments = 200000;
  // Most vertices all fragments together may have: the per-frame hidden-surface test clips
  // fragments against each other, so its time grows with the vertices, not with the count
  // of fragments (100 intersecting circles of 2000 vertices: minutes per frame). Shipped
  // scenes hold a few thousand; manual/robustness.md gives the worst case's time per frame.
  static constexpr std::int64_t kMaxBspVertices = 100000;

  // Builds the tree. The splitting plane of each node is chosen among up to 24 candidate
  // fragments to keep splits few and the two sides balanced. Deterministic.
  // Precondition: every polygon is valid (scene_polygon_problem is empty).
  // Throws std::invalid_argument naming the limit when more than `max_fragments` fragments,
  // or fragments of more than `max_vertices` vertices in all, would be needed (checked on
  // the polygons first and before each split, so memory and time stay bounded).
  explicit BspTree(const std::vector<ScenePolygon>& polygons, int max_fragments = kMaxBspFragments,
                   std::int64_t max_vertices = kMaxBspVertices);

  // Replaces `order` with the indices of every fragment, back to front as seen from `eye`
  // (world coordinates): a fragment never comes after one it can hide. Fragments in a
  // plane through the eye are seen edge-on and keep their node's position.
  void back_to_front(const Vec3& eye, std::vector<int>& order) const;

  const std::vector<BspFragment>& fragments() const { return fragments_; }
  const BspStats& stats() const { return stats_; }
  // The nodes, and the index of the root (-1 for an empty tree): what the hierarchical
  // image cache groups (core/scene/cache_nodes.h).
  const std::vector<BspNode>& nodes() const { return nodes_; }
  int root() const { return root_; }

 private:
  struct Plane {
    Vec3 normal{0.0};     // unit normal
    double offset = 0.0;  // plane: dot(normal, x) == offset
  };
  using Node = BspNode;

  int build(std::vector<int> fragment_ids, int depth);
  int choose_splitter(const std::vector<int>& fragment_ids) const;
  [[noreturn]] void fail_fragment_limit() const;
  [[noreturn]] void fail_vertex_limit() const;
  void traverse(int node, const Vec3& eye, std::vector<int>& order) const;

  std::vector<Node> nodes_;
  std::vector<BspFragment> fragments_;
  std::vector<Plane> planes_;  // per scene polygon
  double epsilon_ = 1e-9;      // plane-side tolerance, world units
  int max_fragments_ = kMaxBspFragments;
  std::int64_t max_vertices_ = kMaxBspVertices;
  std::int64_t vertices_ = 0;  // of all fragments
  int root_ = -1;
  BspStats stats_;
};

}  // namespace oflab
