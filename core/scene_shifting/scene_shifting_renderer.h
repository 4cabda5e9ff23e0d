// A scene-shifting renderer (Hofmann's layers, dissertation chapter 3) for scenes of planes
// parallel to the image plane: the "view from a train window" of manual/scene-shifting.md.
//
// At start the scene is cut into slices along the viewing direction (scene_slices, eq. 9
// with the corrected asymptote) and every polygon goes to the slice holding its depth. Each
// slice's layer is rendered once: its polygons exactly (render warps of core/image/warp.h, the
// exact texture warp of core/engine/exact_render.h), composited far to near. Every later frame, per
// slice (decide_slice_updates):
//  - shift: the layer moves by the accumulated slice_transform of the viewer's steps, placed
//    on whole pixels (the rounded exact shift, like the engine's translate level: no
//    resampling, no pixels written);
//  - scale: a forward step scales the layer about the principal point (one affine warp of
//    the layer, its pixels counted as work);
//  - rebuild: the layer is rendered again from the current view, when the accumulated error
//    would exceed epsilon, when the step turns the viewing direction (then every slice), when
//    the viewer would reach the slice, or when a layer clipped to the guard band no longer
//    covers the frame.
// The frame is the layers composited far to near (premultiplied, transparent elsewhere).
//
// Levels (core/engine/animator.h). Each frame is also reported as an AnimationFrame whose
// layers are the scene's polygons: a polygon drawn when its slice's layer was last built
// counts at the level of its slice's update (still = none, shifted = translate, scaled =
// affine, rebuilt = rerender); the others (behind the viewer at start, or not drawn at the
// last build) count as outside the frustum.
//
// Slicing is fixed at start, in depths seen from the start view; each slice's depth range
// then moves with the viewer's forward steps. After a turn the planes are no longer
// parallel to the image plane: the turning frames rebuild every slice, so their layers are
// exact, but later shifts of those layers carry the turn's misfit, which the measured error
// shows.
//
// Units: world units, pixels (centred unless stated), per frame. Measured error: the
// largest distance, pixels, between a polygon's texture-rectangle corners as shown (the
// corners' exact image when its layer was built, moved by the layer's placement) and their
// exact projection from the current view, over the polygons drawn.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "engine/animator.h"
#include "engine/reuse_policy.h"
#include "flow/camera.h"
#include "image/warp.h"
#include "scene/scene.h"
#include "scene/viewer_script.h"
#include "scene/viewer_script_animator.h"
#include "scene_shifting/scene_shifting.h"

namespace oflab {

struct SceneShiftingSettings {
  double epsilon_px = 1.0;    // tolerance: per frame for the slicing, and the error budget
  double design_speed = 0.0;  // |V| the slices are cut for, world units per frame (>= 0)
  double near = 0.0;          // near edge of the first slice (> 0), or 0: the nearest polygon
  Sampling sampling = Sampling::kNearest;
  // Layers reach this fraction of the image size beyond every side of the frame (>= 0).
  double guard_band = 1.0;
  // A policy that allows no reuse (rerender, core/engine/reuse_policy.h) is the exact
  // baseline: every slice rendered every frame. Any other policy shifts and scales layers.
  const ReusePolicy* policy = &default_reuse_policy();
  int max_slices = 64;  // cap on the slice count (scene_slices throws beyond it)
};

// What a layer did in a frame.
enum class LayerUpdate { kStill, kShifted, kScaled, kRebuilt };

struct SceneShiftingFrameReport {
  int frame = 0;
  int slices = 0;
  int occupied = 0;          // slices holding at least one polygon (the others are never drawn)
  int rebuilt = 0;           // occupied slices rendered this frame (all of them at start)
  int shifted = 0;           // occupied slices moved by whole pixels
  int scaled = 0;            // occupied slices scaled (resampled)
  bool view_turned = false;  // turns_view_direction: every occupied slice rebuilt
  std::vector<LayerUpdate> updates;    // per slice; kStill for empty slices and unmoved layers
  std::int64_t pixels_written = 0;     // by the warp kernels
  std::int64_t pixels_composited = 0;  // into the frame
  double time_ms = 0.0;                // rendering, moving and compositing the layers
  double max_measured_error_px = 0.0;
};

// Slice updates over the frames since start().
struct SceneShiftingTotals {
  int turning_frames = 0;              // frames whose step turned the viewing direction
  int turning_frames_all_rebuilt = 0;  // of those, the frames that rebuilt every occupied slice
  long rebuilt_layers = 0;             // occupied slices rebuilt, frames after the first
  long shifted_layers = 0;             // occupied slices shifted or scaled, after the first
};

// The bytes a scene-shifting renderer may hold for `scene` seen through `camera` with
// `occupied_slices` slices holding polygons, estimated before anything is allocated, 4
// bytes a pixel: the scene's textures, per polygon its copy of its texture, the frame, and per
// occupied slice plus two (the compositing scratch and the image a rebuild or scale makes before it
// replaces the old layer) a layer as large as the frame grown by the guard band on every
// side ((1 + 2 guard_band)^2 camera images). occupied_slices 0: the textures and the frame.
double scene_shifting_memory_bytes(const Scene& scene, const Camera& camera, double guard_band,
                                   int occupied_slices);

class SceneShiftingRenderer {
 public:
  // `scene` must outlive the renderer. Throws std::invalid_argument for a polygon problem
  // (scene_polygon_problem), an invalid camera, a setting out of range, or when the
  // polygons' texture copies and the frame are over limits::kSceneEngineMemory
  // (scene_shifting_memory_bytes, checked before anything is allocated).
  SceneShiftingRenderer(const Scene& scene, const Camera& camera,
                        const SceneShiftingSettings& settings);
  ~SceneShiftingRenderer();
  SceneShiftingRenderer(const SceneShiftingRenderer&) = delete;
  SceneShiftingRenderer& operator=(const SceneShiftingRenderer&) = delete;

  // Frame 0 seen from `view`: cuts the slices and renders every layer. Throws
  // std::invalid_argument when a polygon in front of the viewer is not parallel to the image
  // plane (its front normal within 1e-6 of -Z in the viewer frame), the slicing needs
  // more than settings.max_slices slices, or the occupied slices' layers would be over
  // limits::kSceneEngineMemory (scene_shifting_memory_bytes, checked after the cut and
  // before any layer is rendered). The report maps the slice updates onto levels
  // (see "Levels" above); time_ms and update_ms are the slice report's time_ms.
  AnimationFrame start(const ViewerPose& view);

  // The next frame: `previous` the viewer shown so far, `motion` the scene motion towards
  // this frame (core/scene/viewer_script.h), `current` the viewer now.
  AnimationFrame advance(const ViewerPose& previous, const RigidMotion& motion,
                         const ViewerPose& current);

  const Image& frame() const { return frame_; }
  const Camera& camera() const { return camera_; }
  const SceneShiftingSettings& settings() const { return settings_; }
  // The slice updates of the last frame, and their totals since start().
  const SceneShiftingFrameReport& slice_report() const { return slice_report_; }
  const SceneShiftingTotals& totals() const { return totals_; }
  // The polygons drawn in the last frame as shown (shown_corners, in top-left pixels) with
  // their slice's level, far to near. `view` is unused: the outlines are the layers' own.
  std::vector<LayerOutline> outlines(const ViewerPose& view) const;
  // The slices as cut at start (depths from the start view).
  const std::vector<Slice>& slices() const { return slices_; }
  // Per polygon, its slice index, or -1 when it was behind the viewer at start.
  const std::vector<int>& polygon_slices() const { return polygon_slice_; }
  // The polygon's texture-rectangle corners as shown now (centred pixels); empty when it
  // was not drawn when its layer was last built.
  std::vector<Vec2> shown_corners(int polygon) const;

 private:
  struct SliceLayer;

  void cut_slices(const ViewerPose& view);
  void build(int slice, const ViewerPose& view, SceneShiftingFrameReport& report);
  bool covers_frame(const SliceLayer& layer) const;
  void compose(SceneShiftingFrameReport& report);
  double measured_error(const ViewerPose& view) const;
  AnimationFrame finish(SceneShiftingFrameReport&& report);

  const Scene& scene_;
  Camera camera_;
  SceneShiftingSettings settings_;
  std::vector<Layer> textures_;  // one per polygon (its outline as the valid region)
  std::vector<Slice> slices_;
  std::vector<int> polygon_slice_;
  std::vector<std::vector<Vec2>> built_corners_;  // per polygon, centred, at its last build
  std::vector<SliceLayer> layers_;
  Layer scratch_;
  Image frame_;
  int frame_index_ = 0;
  SceneShiftingFrameReport slice_report_;
  SceneShiftingTotals totals_;
};

// The viewer's step over one frame for a scene motion (core/scene/viewer_script.h): the viewer
// moves against the scene, translation -V and rotation -Omega.
ViewerStep viewer_step(const RigidMotion& motion);

// The largest sideways speed of the viewer over the script's frames, world units per frame:
// the |V| scene shifting cuts its slices for.
double script_design_speed(const ViewerScript& script);

// The scene-shifting renderer playing a viewer script (core/scene/viewer_script_animator.h).
using SceneShiftingAnimator = ViewerScriptAnimator<SceneShiftingRenderer, SceneShiftingSettings>;

// Cuts the slices for settings.design_speed, or for script_design_speed(script) when it is
// 0. Throws std::invalid_argument as SceneShiftingRenderer, or when the script has no frames
// or the scene is null.
std::unique_ptr<SceneShiftingAnimator> make_scene_shifting_animator(
    std::shared_ptr<const Scene> scene, ViewerScript script, SceneShiftingSettings settings);

}  // namespace oflab
