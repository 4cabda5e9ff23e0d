// The `hierarchical-cache` policy (core/engine/reuse_policy.h): Shade et al.'s hierarchical
// image cache (SIGGRAPH 96; dissertation section 2.4.7) played on a scene, frame by frame, by
// the scene engine (core/scene/scene_animator.h), which classifies the polygons first.
//
// Each frame, for every node of the grouping (core/scene/cache_nodes.h) with a polygon not
// culled, back to front in the BSP order:
//  - with an image cached from an earlier eye E0 and no reason to render (cache_render_cause:
//    every bounding-box corner's angular error within CacheSettings::angle_deg, the eye within
//    the safety sphere), the image is warped by the homography its quad induces between the
//    view it was rendered in and now (plane_induced_homography of the quad's plane);
//  - otherwise the node is rendered again: its fragments, back to front, exactly (the
//    polygons' contents, render_clipped_piece) into one image covering the projection of its
//    bounding box, on a new quad through the node's centre facing the eye;
//  - a node that cannot be cached (a corner of its box at or behind the near plane, the box's
//    projection beyond the guard band, or a warp refused) is rendered straight into the frame,
//    clipped to the view, every frame it is drawn.
// The node images are composited back to front into the frame.
//
// Levels and work. Each polygon not culled is one layer-frame, at level re-render when a node
// of its was rendered this frame, else perspective (the warp). Work in the cost model: a
// render costs what its polygons' renders cost (overdraw inside the node included), a warp
// one perspective-warp unit per pixel it writes.
//
// Errors (FrameReport per drawn node, AnimationFrame::cache): a node's measured error is the
// largest distance, pixels, between the exact projection now of a vertex of its fragments and
// the projection now of where its image shows that vertex (the vertex's point on the quad);
// 0 for a node rendered this frame. Its estimated error is the threshold angle converted to
// pixels at each of those vertices (angle_in_pixels: f tan(angle) on the optical axis, about
// f angle / cos^2 of the vertex's angle off it), the largest over the vertices, so
// RunSummary::max_excess_px says how far the angular rule lets the error go beyond the angle
// it promises at the corners of the node's box (0 for a rendered node). The per-pixel error
// and overlaps are measured against the exact depth of the frame (render_depth); holes are
// pixels the exact frame (every fragment rendered from its content, back to front) covers at
// least half opaque and no node image does, since a content may be transparent inside its
// polygon (an impostor's facade). All outside the frame's time.
//
// Pixel work. A warp writes only the pixels inside the frame (the image's region clipped to
// the frame's preimage); a render writes the node's whole image, guard band included, as it
// is kept for later frames.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "content/layer_content.h"
#include "engine/animator.h"
#include "engine/engine.h"
#include "engine/exact_render.h"
#include "flow/reprojection.h"
#include "image/image.h"
#include "scene/bsp_tree.h"
#include "scene/cache_nodes.h"
#include "scene/scene.h"
#include "scene/view_culling.h"
#include "scene/viewer_script.h"

namespace oflab {

// The settings the cache shares with its scene engine (SceneSettings).
struct CacheContext {
  double near = 0.05;       // near plane Z, world units (> 0)
  double guard_band = 0.5;  // a node image may reach this fraction of the image beyond it
  Sampling sampling = Sampling::kNearest;
  LayerContent content;  // the run's content settings; each polygon keeps its own kind
};

// What is wrong with `settings` ("" when nothing): the limits of core/flow/limits.h
// (kCacheAngle, kCacheNodePolygons, kSafetyRadius), naming the field.
std::string cache_settings_problem(const CacheSettings& settings);

class HierarchicalCache {
 public:
  // `scene` and `bsp` (built from scene.polygons) must outlive the cache. Throws
  // std::invalid_argument when cache_settings_problem is not empty.
  HierarchicalCache(const Scene& scene, const Camera& camera, const BspTree& bsp,
                    const CacheSettings& settings, const CacheContext& context);
  ~HierarchicalCache();
  HierarchicalCache(const HierarchicalCache&) = delete;
  HierarchicalCache& operator=(const HierarchicalCache&) = delete;

  // Forgets every cached image (the next frame renders every node drawn).
  void restart();

  // One frame seen from `current`: `culled` has one entry per scene polygon, nonzero for the
  // polygons culled this frame (back-facing or outside the frustum). Writes the composited
  // frame (camera-sized, premultiplied) into `frame`, the level of each drawn polygon into
  // `levels`, and adds the levels, pixels, work, times, errors, layer reports (one per
  // drawn node, back to front), holes and AnimationFrame::cache to `report`. Returns the
  // milliseconds spent on the diagnostics (the pixel measures against the exact depth), which
  // the caller leaves out of the frame's time.
  double frame(const ViewerPose& current, const std::vector<char>& culled, Image& frame,
               std::vector<Level>& levels, AnimationFrame& report);

  const std::vector<CacheNode>& nodes() const { return nodes_; }
  // The threshold, radians, and the safety radius of node k as last rendered (world units;
  // 0 before its first render).
  double threshold() const { return threshold_; }
  double node_radius(int k) const;

 private:
  struct NodeState;
  // Where a node image lies in the frame it is rendered in: top-left pixel and size, and the
  // projected hull of the node's bounding box (empty for an image covering the whole frame).
  struct NodeRect {
    int x0, y0, width, height;
    std::vector<Vec2> hull;
  };

  // The frame's steps: the drawn nodes in back-to-front order (the others' images dropped);
  // each drawn node reused or rendered (true: rendered), with its report.
  std::vector<int> order_nodes(const Vec3& eye, const std::vector<char>& culled);
  bool update_node(int k, const ViewerPose& current, const Vec3& eye,
                   const std::vector<char>& culled, AnimationFrame& report);
  // Whether node k's image may be kept when it is rendered now: every corner of its box
  // beyond the near plane, on the far side of a new quad, projecting within the guard band.
  bool cacheable(int k, const ViewerPose& current, const Vec3& eye) const;
  // A render of node k: where its image lies (the whole frame unless cached), its fragments
  // painted back to front (the surface labels kept), the image kept with its quad.
  NodeRect node_rect(int k, const ViewerPose& view, bool cached) const;
  Image paint_fragments(int k, const ViewerPose& view, const std::vector<char>& culled,
                        const NodeRect& at, AnimationFrame& report);
  // Fragment f seen from `view`, clipped to `frustum` (of `sub`, the camera of `image`),
  // rendered from its polygon's content and composited over `image`; adds to *pixels and
  // *work. False (nothing drawn) when the clipped piece is empty or beyond the warps' range.
  bool paint_fragment(int f, const ViewerPose& view, const Camera& sub, const ViewFrustum& frustum,
                      Image& image, std::int64_t* pixels, double* work, PlacedLayer& placed);
  // The exact frame: every fragment of a polygon not culled, back to front (order_), as a
  // render of every node would paint it (a diagnostic: its work is not counted).
  Image exact_frame(const ViewerPose& view, const std::vector<char>& culled);
  // Pixels where the exact frame is at least half opaque and no node image is (front_node_).
  std::int64_t count_holes(const ViewerPose& current, const std::vector<char>& culled);
  void render_node(int k, const ViewerPose& view, const std::vector<char>& culled, bool cached,
                   AnimationFrame& report);
  bool warp_node(int k, const ViewerPose& current, AnimationFrame& report);
  // Over the vertices of node k's fragments in front of the near plane (as shown and
  // exactly): the largest distance between a vertex's exact projection now and where the
  // image shows it (measured), and the largest image size of the threshold angle at a vertex
  // (angle_in_pixels: estimated), pixels.
  struct VertexErrors {
    double measured = 0.0;
    double estimated = 0.0;
  };
  VertexErrors vertex_errors(int k, const ViewerPose& current) const;
  // The image distance (pixels) between where the cached image of node state `s` shows the
  // surface point at frame pixel centre `centre` and that point's exact projection now;
  // negative when the pixel shows no surface of the node or the point is behind the near
  // plane. `from_frame` maps frame pixels to the node image's, `step` the node's view to now.
  double pixel_error(const NodeState& s, const Mat3& from_frame, const RigidStep3& step,
                     const Vec2& centre) const;
  void measure_pixels(const ViewerPose& current, const std::vector<int>& drawn,
                      const std::vector<char>& culled, AnimationFrame& report);

  const Scene& scene_;
  Camera camera_;
  const BspTree& bsp_;
  CacheSettings settings_;
  CacheContext context_;
  double threshold_ = 0.0;
  std::vector<CacheNode> nodes_;
  std::vector<std::vector<int>> nodes_of_polygon_;
  std::vector<int> fragment_position_;  // in this frame's back-to-front order
  std::vector<int> order_;
  std::vector<Layer> textures_;  // one per scene texture, for the renders
  std::vector<std::unique_ptr<NodeState>> states_;
  std::vector<int> front_node_;  // per pixel of the frame, the front node drawn (-1: none)
};

}  // namespace oflab
