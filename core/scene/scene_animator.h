// Animation of a static scene of textured polygons seen by a moving viewer: Algorithm 1
// extended to many planes (dissertation sections 5.5 and 5.6.2).
//
// Every polygon is one layer driven by its own PlaneEngine (core/engine/engine.h, any mode); the
// camera's motion is the same rigid motion for all of them (core/scene/viewer_script.h). Each
// frame:
//  1. cull: polygons seen from behind or edge-on (backface culling) and polygons with no
//     part inside the view frustum are skipped;
//  2. order: the BSP tree built once for the scene gives the fragments back to front;
//  3. visibility (beyond the dissertation, its section 7.5.3): walking front to back, a
//     polygon whose every fragment's image is covered by opaque polygons already drawn in
//     front of it is "hidden" and not updated at all (core/scene/occlusion.h);
//  4. update: every other polygon gets its engine update for this frame (or a fresh start
//     when it was culled or hidden the frame before, since its layer is then stale), in
//     three phases (core/engine/budget.h): every polygon that passed culling is measured
//     (its candidate levels and their costs), the levels are allocated over all of them
//     (each its own choice, or the `budget` policy's share of a per-frame budget), and the
//     walk of step 3 applies them; a polygon found hidden then leaves its share unspent,
//     and one the budget could not afford a render is "starved": not drawn this frame.
//     The walk queues the updates in waves that run at once on the worker threads
//     (core/image/thread_pool.h): a polygon joins the wave unless its hidden test's region
//     would be covered were every layer already in the wave as wide as it may reach (its
//     exact image grown by the errors its level leaves), or both render clipped textures
//     from one scratch copy; then the wave runs first. The updates are recorded (report, ledger,
//     occluders) in the walk's order, so frames and reports are the same bytes as one polygon at a
//     time, on any number of threads;
//  5. composite the layers back to front into the frame (premultiplied, transparent where
//     nothing is drawn).
//
// Today's reprojection (core/engine/reuse_policy.h). A policy with a FramePlane of
// kStabilization gets the frame's plane before each measure: the given plane
// (EngineSettings::stabilization, world coordinates), or the automatic one, fitted to the
// frame's depth (fit_inverse_depth_plane) at every cadence frame (frame index a multiple of
// EngineSettings::cadence) and kept in world coordinates until the next. The
// depth-reprojection policy (FrameWarp::kPerPixelDepth) renders every polygon at each cadence
// frame, keeps the frame and its depth (render_depth), and shows every other frame as that
// frame forward-warped by its depth (reproject_by_depth): each polygon not culled counts as
// one layer at level perspective, the pixels written are the splats', the work one
// perspective-warp unit per source pixel, the measured error the largest per-pixel
// displacement, and AnimationFrame::hole_pixels the holes.
//
// The motion-vector extrapolation policies (PixelMotion::kMotionVectors) keep the render as
// depth reprojection does, with the viewer of the frame before it (its motion vectors), and
// generate every other frame by extrapolate_by_motion (core/scene/frame_generation.h), which
// does not read the viewer now; the true step is used only for the measured error and holes.
// The view-interpolation policy (PixelMotion::kBetweenRenders) also renders, at the first frame
// after a render, the next render's frame ahead of its time (the views to come: set_future_views;
// that render's time is counted at its own frame, where it is rendered again and shown), and
// makes every frame between from both (interpolate_views, core/scene/view_interpolation.h).
//
// The depth-mesh policy (PixelMotion::kFarMesh; mesh_frames.cpp) splits the polygons at the
// mesh's build into near and far (far_polygons, core/scene/depth_mesh.h); at each cadence frame,
// or once the viewer has moved SceneSettings::mesh.rebuild_distance, it renders the far part
// alone, keeps it with its depth and builds the mesh; every frame it renders the near part and
// merges it by depth with the far render (at a build) or with the mesh drawn from the viewer now.
// Near polygons count as re-rendered, far ones as re-rendered at a build and perspective between.
//
// The hierarchical-cache policy (FrameWarp::kNodeImages) classifies the polygons as above, then
// hands the frame to core/scene/hierarchical_cache.h: nodes of the BSP tree instead of
// polygons, no hidden test.
//
// Near plane. A polygon whose texture rectangle reaches in front of the near plane
// (Z < near) or projects beyond the guard band (see SceneSettings) is not animated: its
// part inside the frustum is clipped in 3D and rendered exactly that frame, so a polygon
// crossing the near plane is never smeared, never warped through the eye and never
// crashes a warp. Such polygons are counted as re-rendered and as "clipped".
//
// Files. A polygon's layer and status are core/scene/polygon_layer.h, and what a scene costs
// (memory, content detail) before anything is allocated core/scene/scene_resources.h; both
// are included here. SceneEngine is implemented in three files: its frame loop in
// scene_animator.cpp, its walk front to back (hidden tests and the waves of updates) in
// update_waves.cpp, its per-polygon steps (measure, allocate, update) in polygon_layer.cpp.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "engine/animator.h"
#include "engine/engine.h"
#include "image/composite.h"
#include "scene/bsp_tree.h"
#include "scene/cache_nodes.h"
#include "scene/depth_mesh.h"
#include "scene/depth_reprojection.h"
#include "scene/frame_generation.h"
#include "scene/hierarchical_cache.h"
#include "scene/occlusion.h"
#include "scene/polygon_layer.h"
#include "scene/scene.h"
#include "scene/scene_resources.h"
#include "scene/view_culling.h"
#include "scene/view_interpolation.h"
#include "scene/viewer_script.h"
#include "scene/viewer_script_animator.h"

namespace oflab {

struct SceneSettings {
  EngineSettings engine;
  double near = 0.05;  // near clipping plane Z = near, world units (> 0)
  // A polygon is animated only while its texture rectangle projects within the image grown
  // by this fraction of the image size on every side (>= 0); beyond it the polygon is
  // clipped and rendered exactly, which bounds every layer's size.
  double guard_band = 0.5;
  bool skip_hidden = true;  // step 3 above
  // Step 4's updates in waves on the worker threads (true), or one polygon at a time (the
  // walk as written, which the waves must reproduce to the byte; tests compare the two).
  bool waves = true;
  // Conservative margins of the hidden test, in pixels: occluders are shrunk by
  // occluder_inset_px (the border pixels of a warped layer may be partly transparent) and
  // the candidate's exact image is grown by candidate_margin_px (pixel rounding).
  double occluder_inset_px = 1.5;
  double candidate_margin_px = 1.0;
  // What fills the holes of the depth-reprojection policy's warped frames (they are
  // counted whatever fills them; core/scene/depth_reprojection.h).
  HoleFill hole_fill = HoleFill::kNone;
  // The hierarchical-cache policy's threshold, grouping and safety sphere
  // (core/scene/cache_nodes.h); other policies ignore it.
  CacheSettings cache;
  // The depth-mesh policy's grid, split, rebuild distance and rubber sheets.
  DepthMeshSettings mesh;
};

// The engine of a scene, driven view by view by its caller. Not an Animator
// (core/engine/animator.h), which owns its script: make_scene_animator plays a viewer script
// through one SceneEngine (core/scene/viewer_script_animator.h).
class SceneEngine {
 public:
  // `scene` must outlive the animator. Builds the BSP tree. Throws std::invalid_argument
  // when a polygon has a problem (scene_polygon_problem), the camera is invalid, a
  // setting is out of range, the scene's impostors are over their detail
  // (scene_content_problem), the scene is over its memory (scene_memory_problem, checked
  // before anything is allocated) or the BSP tree would exceed BspTree::kMaxBspFragments.
  SceneEngine(const Scene& scene, const Camera& camera, const SceneSettings& settings);
  ~SceneEngine();
  SceneEngine(const SceneEngine&) = delete;
  SceneEngine& operator=(const SceneEngine&) = delete;

  // Frame 0 seen from `view`: every visible polygon is rendered. The report's layers are
  // the scene's polygons; time_ms covers cull, order, visibility, updates and composite;
  // hidden_area_px is the image area (within the frame) of the hidden polygons, the warping
  // work the visibility test saved; max_measured_error_px the largest measured corner error
  // of an animated polygon (core/engine/engine.h); layer_reports hold the engine report of
  // each polygon animated this frame (clipped polygons have none), in polygon order.
  AnimationFrame start(const ViewerPose& view);

  // The next frame: `previous` is the viewer of the frame shown so far, `motion` the scene
  // motion towards this frame (core/scene/viewer_script.h), `current` the viewer now.
  AnimationFrame advance(const ViewerPose& previous, const RigidMotion& motion,
                         const ViewerPose& current);

  // The viewers of the frames to come, for a policy that interpolates between renders
  // (view-interpolation): views(k, pose) sets the viewer of frame index k (>= 0, counted from
  // start) and returns false past the last frame. Without it, or past the last frame, such a
  // policy renders the frame instead. The viewer script animator sets its script's.
  using FutureViews = std::function<bool(int frame, ViewerPose& pose)>;
  void set_future_views(FutureViews views) { future_views_ = std::move(views); }

  // The composited frame (camera-sized, premultiplied).
  const Image& frame() const { return frame_; }
  const BspTree& bsp() const { return bsp_; }
  const Camera& camera() const { return camera_; }
  // Per polygon, what happened in the last frame.
  const std::vector<PolygonStatus>& statuses() const { return statuses_; }
  // Per polygon, the update level of the last frame (meaningful for drawn polygons).
  const std::vector<Level>& levels() const { return levels_; }
  // The exact outlines (top-left pixels, seen from `view`, the view of the last frame) of
  // the polygons drawn in the last frame with their levels, back to front in the BSP order;
  // a polygon with a vertex within 1e-3 of the eye plane or behind it has none.
  std::vector<LayerOutline> outlines(const ViewerPose& view) const;
  // The depth-reprojection policy: the frame and depth of the last render, the viewer it was
  // seen from, and for the last frame shown the source pixel of every pixel (-1: a hole;
  // empty after a rendered frame; view interpolation: the source pixel in whichever render
  // it came from). Meaningless for other policies.
  const Image& rendered_frame() const { return rendered_frame_; }
  const DepthFrame& rendered_depth() const { return rendered_depth_; }
  const ViewerPose& rendered_view() const { return rendered_view_; }
  const std::vector<int>& reprojection_sources() const { return source_of_; }
  // The hierarchical-cache policy's cache; null under other policies.
  const HierarchicalCache* cache() const { return cache_.get(); }
  // The depth-mesh policy: the last mesh, the far polygons of its build and the split depth.
  const DepthMesh& depth_mesh() const { return mesh_; }
  const std::vector<char>& far_part() const { return far_; }
  double mesh_split() const { return split_; }

 private:
  // The frame loop (scene_animator.cpp): classify (cull and find the polygons to clip),
  // order, measure and allocate, then visibility and updates front to back, the hidden
  // polygons' tally, compositing back to front.
  AnimationFrame run_frame(const ViewerPose* previous, const RigidMotion* motion,
                           const ViewerPose& current);
  // Every polygon updated and composited for `current` (the frame loop's render path).
  void render_frame(const ViewerPose* previous, const RigidMotion* motion,
                    const ViewerPose& current, AnimationFrame& report);
  void classify(const ViewerPose& view, AnimationFrame& report);
  void update_front_to_back(const ViewerPose& current, AnimationFrame& report);
  // The image region the hidden test of a fragment must find covered (exact, top-left
  // pixels; the test grows it by candidate_margin_px).
  ConvexPolygon hidden_candidate(int fragment, const ViewerPose& view);
  void add_occluder(int fragment, const PlacedLayer& shown);
  // The waves of step 4 (scene_animator.cpp): fragments in the walk's order whose polygons'
  // updates run at once on the worker threads, then are recorded in that order.
  struct WaveEntry {
    int fragment = 0;
    bool update = false;    // this entry's polygon is updated in the wave
    bool occludes = false;  // its layer may become an occluder, within `reach`
    ConvexPolygon reach;    // top-left pixels
  };
  WaveEntry wave_entry(int fragment, bool update);
  bool wave_blocks(int polygon, const ConvexPolygon& candidate) const;
  void run_wave(const ViewerPose& current, AnimationFrame& report);
  // A rough cost of a queued update, to start the dearest first: the pixels its level may
  // write (LayerCandidates::pixels), eight times over for a lit content's render.
  double update_cost(int polygon);
  void draw_fragment(int fragment, const ViewerPose& current, AnimationFrame& report);
  void tally_hidden_and_stale(AnimationFrame& report);
  void compose(AnimationFrame& report);
  const ConvexPolygon& polygon_region(int polygon);
  ConvexPolygon fragment_region(int fragment, const ViewerPose& view) const;
  ConvexPolygon exact_region(const ViewPolygon& clipped) const;
  // Today's reprojection and the hierarchical cache (see above).
  bool cadence_frame() const;
  void update_frame_plane(const ViewerPose& current);
  void keep_render(const ViewerPose& current, const ViewerPose* previous);
  // Return the milliseconds of their diagnostics (errors, holes), left out of the frame's time.
  double reproject_frame(const ViewerPose& current, AnimationFrame& report);
  double generate_frame(const ViewerPose& current, AnimationFrame& report);
  // View interpolation (interpolated_frames.cpp): the next render made ahead when this frame
  // lies before it (false: this frame is to be rendered), its time added to `excluded_ms`;
  // then the frame made from both renders.
  bool look_ahead(double& excluded_ms);
  double interpolate_frame(const ViewerPose& current, AnimationFrame& report);
  // Shows a frame of splats (reprojected or interpolated): its image and each pixel's source
  // pixel become the engine's, and `report` takes its pixel writes, work, largest measured
  // error and holes (the pixels of `unreached` where the view `current` shows a surface: a
  // diagnostic, the depth of the view now rendered). Returns that diagnostic's milliseconds.
  double show_splats(Image image, std::vector<int> source, const std::vector<char>& unreached,
                     std::int64_t pixels_written, std::int64_t source_pixels, double max_error_px,
                     const ViewerPose& current, AnimationFrame& report);
  void mark_reprojected(const ViewerPose& current, AnimationFrame& report);
  // The depth mesh (mesh_frames.cpp): the frame (returns its diagnostics' milliseconds), the
  // polygons a render pass leaves out (set_aside_) set aside after classify, one pass.
  double mesh_frame(const ViewerPose* previous, const RigidMotion* motion,
                    const ViewerPose& current, AnimationFrame& report);
  void build_mesh(const ViewerPose* previous, const RigidMotion* motion, const ViewerPose& current,
                  AnimationFrame& report);
  void set_aside_polygons();
  void mark_meshed(bool built, AnimationFrame& report);
  void cache_frame(const ViewerPose& current, AnimationFrame& report);

  // The per-polygon steps (polygon_layer.cpp): the measure and allocate phases (step 4) of
  // the polygons that passed culling, and one polygon's update.
  void measure_polygons(const ViewerPose* previous, const RigidMotion* motion,
                        const ViewerPose& current, AnimationFrame& report);
  void allocate_polygons(AnimationFrame& report);
  LayerCandidates clipped_candidates(int polygon);
  PlaneEngine& polygon_engine(int polygon);
  // One polygon's update into `u` (safe to run at once for different polygons: it writes
  // only the polygon's own layer, status and level), and its record into the frame's
  // report and the ledger (in the walk's order).
  void update_polygon(int polygon, const ViewerPose& current, PolygonUpdate& u);
  void record_update(const PolygonUpdate& u, AnimationFrame& report);
  void render_clipped(int polygon, const ViewerPose& view, AnimationFrame& tally);
  void starve(int polygon, PolygonUpdate& u);
  // Adds a re-render of a polygon to tally.rerender_causes: `fresh` when it had no image
  // to warp, else by its engine report's note (sampling limit, refusal) or its schedule.
  void count_rerender_cause(bool fresh, const std::string& note, AnimationFrame& tally) const;
  // The engine's content settings with the polygon's own kind of content.
  LayerContent polygon_content(int polygon) const;

  const Scene& scene_;
  Camera camera_;
  SceneSettings settings_;
  ViewFrustum frustum_;
  BspTree bsp_;
  std::vector<std::unique_ptr<PolygonLayer>> states_;  // one per polygon
  std::vector<Layer> scratch_textures_;  // one per scene texture, for the clipped renders
  std::vector<PolygonStatus> statuses_;
  std::vector<Level> levels_;
  std::vector<int> order_;
  std::vector<char> fragment_drawn_;
  std::vector<ConvexPolygon> fragment_regions_;
  std::vector<WaveEntry> wave_;
  OcclusionTest occlusion_;
  // The frame pixels not under an opaque layer drawn so far in the walk (surely painted
  // opaque: its occluder's region), what a visible-only warp computes (WarpArea::kVisible).
  PixelRows shown_pixels_;
  BudgetLedger ledger_;
  Image frame_;
  LazyClear lazy_clear_;  // the frame's rows cleared so far by compose
  int frame_index_ = 0;
  // Today's reprojection: the stabilization plane in world coordinates (at_infinity: m = 0),
  // and the last render of the depth-reprojection policy with its depth and viewer.
  bool uses_frame_plane_ = false;
  Vec3 frame_plane_{0.0};  // the plane vector this frame, viewer frame
  bool plane_known_ = false;
  bool plane_at_infinity_ = false;
  Vec3 plane_point_{0.0};
  Vec3 plane_normal_{0.0, 0.0, 1.0};
  bool has_render_ = false;
  Image rendered_frame_;
  DepthFrame rendered_depth_;
  ViewerPose rendered_view_;
  ViewerPose rendered_previous_;  // the viewer of the frame before the render (motion vectors)
  int rendered_index_ = 0;        // the frame index of the render
  std::vector<int> source_of_;    // the last reprojection's source pixel per pixel
  // View interpolation: the views to come, and the next render made ahead (next_index_ -1:
  // none).
  FutureViews future_views_;
  Image next_frame_;
  DepthFrame next_depth_;
  ViewerPose next_view_;
  int next_index_ = -1;
  // The depth mesh: the polygons a render pass leaves out (empty: none), the far part of the
  // build, the split depth (0 until frame 0 sets it) and the mesh.
  std::vector<char> set_aside_;
  std::vector<char> far_;
  double split_ = 0.0;
  DepthMesh mesh_;
  std::unique_ptr<HierarchicalCache> cache_;  // the hierarchical-cache policy only
};

// The scene animator playing a viewer script: frame k is seen from script.frames[k].pose.
using SceneScriptAnimator = ViewerScriptAnimator<SceneEngine, SceneSettings>;

// Throws std::invalid_argument as SceneEngine, or when the script has no frames or the
// scene is null.
std::unique_ptr<SceneScriptAnimator> make_scene_animator(std::shared_ptr<const Scene> scene,
                                                         ViewerScript script,
                                                         const SceneSettings& settings);

}  // namespace oflab
