// One interface for everything oflab animates frame by frame: a single textured plane driven
// by a motion script (core/engine/engine.h), a scene of polygons walked through by a viewer
// script (core/scene/scene_animator.h), and Hofmann's scene shifting of such a scene
// (core/scene_shifting/scene_shifting_renderer.h). Each owns its script, so a run driver,
// the GUI and the experiments play any of them through start() and advance() alone.
//
// Layers. Every animator shows its frame as layers composited back to front: one for a
// plane, one per polygon for a scene, one per depth slice for scene shifting. Each frame a
// drawn layer is updated at one level (core/engine/decision.h); scene shifting maps its
// slice updates onto levels (still = none, shifted = translate, scaled = affine, rebuilt =
// rerender) and counts each polygon of a slice as one layer, so level histograms of all
// three are comparable polygon for polygon.
//
// Units: pixels of the output image, milliseconds of wall time, world units for poses.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "engine/decision.h"
#include "engine/engine.h"
#include "engine/script.h"
#include "flow/camera.h"
#include "image/image.h"
#include "scene/scene.h"
#include "scene/viewer_script.h"

namespace oflab {

// What the hierarchical image cache (core/scene/hierarchical_cache.h) did in one frame; only
// that policy fills it (active).
struct NodeCacheFrame {
  bool active = false;
  int nodes = 0;               // nodes of the grouping (core/scene/cache_nodes.h)
  int drawn = 0;               // nodes drawn this frame (some polygon of theirs not culled)
  int rendered = 0;            // of which rendered into their image again (every cause below)
  int fresh = 0;               // rendered: no image to reuse (frame 0, or drawn again after a cull)
  int by_angle = 0;            // rendered: a corner's angular error over the threshold
  int by_sphere = 0;           // rendered: the viewer outside the safety sphere, angle within
  int uncacheable = 0;         // rendered straight into the frame: a corner at or behind the near
                               // plane, the quad beyond the guard band, or a warp refused
  double threshold_px = 0.0;   // the angle threshold at the focal length: f tan(angle), px
  double max_angle_deg = 0.0;  // the largest corner angle of a reused node, degrees
  // Against the exact projection of the frame (untimed diagnostics): pixels where a surface
  // is seen but no node image covers (holes), pixels where the front node image is not the
  // node of the surface seen there, or covers the background (overlap), and the per-pixel
  // displacement of the reused nodes' pixels (max and mean over error_pixels pixels).
  std::int64_t overlap_pixels = 0;
  double max_pixel_error_px = 0.0;
  double mean_pixel_error_px = 0.0;
  std::int64_t error_pixels = 0;
};

// Why the layers re-rendered in a frame were re-rendered, one cause per layer-frame at level
// re-render (the scene engine counts them; their sum is AnimationFrame::levels[kRerender]):
// the policy's own schedule (its rule, or its cadence: frame 0 and every cadence-th frame of
// the layer; a per-pixel depth warp's render frames), or against it: the warp would have
// magnified the cache beyond the sampling limit, a warp was refused (beyond its range), the
// layer had no image to warp (it came into view, or back after being hidden), or it reaches
// in front of the near plane or beyond the guard band (clipped: rendered exactly every frame
// it is). A policy on a fixed cadence keeps it exactly when the last four are zero.
struct RerenderCauses {
  int schedule = 0;
  int sampling_limit = 0;
  int refused = 0;
  int no_image = 0;
  int clipped = 0;
  int off_schedule() const { return sampling_limit + refused + no_image + clipped; }
};

// What an animator did in one frame, in terms every animator shares. Fields that do not
// apply to an animator stay zero (e.g. culling counts for a single plane).
struct AnimationFrame {
  int frame = 0;
  int layers = 0;                         // layers (polygons) of the source
  std::array<int, kLevelCount> levels{};  // drawn layers per update level
  int back_facing = 0;                    // culled: seen from behind or edge-on
  int outside_frustum = 0;                // culled: nothing inside the view frustum
  int hidden = 0;                         // wholly covered by layers in front: not updated
  int clipped = 0;                        // rendered exactly after clipping (also rerender)
  double time_ms = 0.0;                   // the whole frame
  double update_ms = 0.0;                 // of which updating layers (warps, bookkeeping)
  double composite_ms = 0.0;              // of which clearing the frame and compositing
  double visibility_ms = 0.0;             // of which the hidden test
  int update_waves = 0;             // the scene engine's waves of layer updates (scene_animator.h)
  std::int64_t pixels_written = 0;  // by the warp kernels
  // Of pixels_written, those the scene engine's visible-only warp left out, less those of
  // earlier frames it warped now (FrameReport::pixels_not_warped); the pixels warped are
  // pixels_written - pixels_not_warped.
  std::int64_t pixels_not_warped = 0;
  std::int64_t pixels_composited = 0;  // into the frame
  // The layers' work in the engine's cost model (core/engine/cost_model.h kPerspectiveWarpCost
  // and the rest; pixels of a perspective warp, deterministic), the part of update_ms spent
  // rendering contents, and the largest photometric error (FrameReport) of a drawn layer.
  double model_work = 0.0;
  double render_ms = 0.0;
  double max_photometric_error = 0.0;
  double hidden_area_px = 0.0;  // image area of the hidden layers
  // Largest measured error over the drawn layers, pixels (0 when none was drawn; see
  // each animator for what is measured).
  double max_measured_error_px = 0.0;
  // Pixels of the frame no warped pixel reached (core/scene/depth_reprojection.h: a
  // disocclusion or a part of the view outside the rendered frame); only a per-pixel depth
  // warp has any, a layer warp shows every layer whole.
  std::int64_t hole_pixels = 0;
  // Of the unreached pixels, those filled by inpainting (core/scene/frame_generation.h: the
  // mv-extrapolation policy); 0 for every other policy.
  std::int64_t inpainted_pixels = 0;
  // True under a policy whose reports carry hole pixels (core/engine/reuse_policy.h
  // reports_holes): the per-frame CSV and the summaries then add them.
  bool reports_holes = false;
  // The engine report of each layer updated this frame, in layer order: exactly one for a
  // single plane (also when it is not visible), one per animated polygon for a scene (one per
  // drawn node under the hierarchical image cache), none for scene shifting (its slices
  // keep no per-term books).
  std::vector<FrameReport> layer_reports;
  // A policy that shares a per-frame budget (core/engine/budget.h): the budget, what the
  // frame spent, starved layers and the optimality gap; inactive otherwise and in frame 0.
  BudgetReport budget;
  // The hierarchical image cache's nodes (inactive for every other policy).
  NodeCacheFrame cache;
  // The causes of this frame's re-renders (the scene engine; zero for the other animators
  // and the hierarchical cache, whose nodes count their own).
  RerenderCauses rerender_causes;
  std::string note;  // why the frame is special, empty when it is not

  int culled() const { return back_facing + outside_frustum; }
  int drawn() const;  // sum of levels
};

// A layer's outline in top-left image pixels, the level it was updated at, the scene polygon
// it shows and the error its update left.
struct LayerOutline {
  std::vector<Vec2> points;
  Level level = Level::kNone;
  int polygon = 0;  // index into Animator::scene().polygons (0 for a single plane)
  // The measured error of the layer this frame (FrameReport::measured_error_px), pixels; 0
  // for a layer rendered exactly (re-render, clipped); NaN where the animator keeps no
  // per-layer books (scene shifting).
  double error_px = std::numeric_limits<double>::quiet_NaN();
};

class Animator {
 public:
  virtual ~Animator() = default;

  // Frames of the script (>= 1).
  virtual int frame_count() const = 0;
  // The frame shown now: -1 before start(), then 0 .. frame_count() - 1.
  virtual int frame() const = 0;

  // Frame 0: every visible layer is rendered exactly. May be called again to restart.
  virtual AnimationFrame start() = 0;
  // The next frame. Precondition: 0 <= frame() < frame_count() - 1.
  virtual AnimationFrame advance() = 0;

  // The displayed frame: camera-sized, premultiplied RGBA, transparent where nothing is.
  virtual const Image& image() const = 0;
  virtual const Camera& camera() const = 0;
  // Outlines of the drawn layers with their levels, back to front.
  virtual std::vector<LayerOutline> outlines() const = 0;

  // What is animated, as a scene seen by a viewer: the exact projection of the current
  // frame is `scene()` seen from `view()` with camera(). A single plane is the polygon of
  // its frame-0 pose with the viewer frame of frame 0 as the world (plane_as_scene), its
  // polygon showing the engine's content (EngineSettings::content kind and quality), so a
  // scene animator re-rendering scene() with the same settings draws what the engine's
  // re-renders draw.
  virtual const Scene& scene() const = 0;
  virtual ViewerPose view() const = 0;
};

// Plays a motion script `repeat` times back to back (F = script.frames.size(), F * repeat
// frames): frame k shows script.frames[k % F].pose, and the engine carries its state (the
// displayed image, the accumulated error) from the last frame of one play to the first of
// the next, as from any frame to the next. `texture` premultiplied RGBA. image() is the
// engine's displayed layer composed into a camera-sized frame, transparent (nothing) in
// frames where the plane is not visible; outlines() the displayed polygon. Throws
// std::invalid_argument when the script has no frames, or repeat < 1 or F * repeat does not
// fit an int, or the policy needs a scene (FrameWarp::kNodeImages: hierarchical-cache).
std::unique_ptr<Animator> make_plane_animator(const MotionScript& script, const Image& texture,
                                              const EngineSettings& settings, int repeat = 1);

}  // namespace oflab
