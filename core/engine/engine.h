// The animation engine for one textured plane: Algorithm 1 of the dissertation (section
// 5.6.1), corrected as documented in manual/animation.md.
//
// Frames. `displayed warp` D maps texel coordinates (core/flow/plane.h) to top-left image
// pixels (core/flow/camera.h). The engine shows D(texture) and keeps, besides it:
//  - the model warp B: where its flow model says the plane is now. The reuse policy
//    (core/engine/reuse_policy.h) says how B advances: by the first-order Taylor homography
//    of each frame's motion (perspective policy), by its affine part (affine), or to the
//    exact texture-to-image warp of the current pose (exact).
//  - a perspective cache (section 5.4.3, corrected eq. 55): D = W_aff W_persp with the
//    source origin at the texture centre; the cache is W_persp(texture) and affine updates
//    warp the cache by the new W_aff, never the previous frame, so resampling does not
//    compound.
// Each frame the pending correction C = B D^-1 is applied at the chosen level:
//   translate: C's motion of the expansion point rounded to whole pixels (the layer is
//     moved on whole pixels; the sub-pixel remainder stays pending, and is counted in the
//     exact pending error of FrameReport::pending and the estimate);
//   affine: C's first-order (affine) part about the expansion point;
//   perspective: C itself (a new cache, then the affine step);
//   re-render: D = the exact warp, rendered straight from the texture.
// D is always where the shown pixels are, so the measured error is that of the image.
//
// Framing. A pose is drawn whole (the engine animates the texture rectangle) only while
// the rectangle lies beyond the near plane and projects within the guard band; a plane
// that still meets the image otherwise is clipped in 3D and rendered exactly that frame
// (as the scene animator does, core/scene/scene_animator.h), and a plane that does not
// meet the image (core/scene/view_culling.h plane_meets_image) is not visible: nothing is
// drawn and no error is counted. No pose makes start() or advance() throw.
//
// The exact renders are core/engine/exact_render.h and the cost model's prices
// core/engine/cost_model.h, both included here. PlaneEngine is implemented in two files: its
// frame's decision in engine.cpp, its shown layer's updates in layer_updates.cpp.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "content/layer_content.h"
#include "engine/budget.h"
#include "engine/cost_model.h"
#include "engine/decision.h"
#include "engine/exact_render.h"
#include "engine/lookahead.h"
#include "engine/reuse_policy.h"
#include "flow/camera.h"
#include "flow/decomposition.h"
#include "flow/motion.h"
#include "flow/plane.h"
#include "image/layer.h"
#include "image/warp.h"
#include "scene/view_culling.h"

namespace oflab {

// The stabilization plane of the `stabilized-plane` policy (core/engine/reuse_policy.h
// FramePlane::kStabilization), one plane for the whole frame. Automatic: the plane whose
// inverse depth best fits the visible layers' (the scene engine fits it at every render,
// core/scene/depth_reprojection.h fit_inverse_depth_plane; a single plane is its own plane).
// Given: the plane through `point` with normal `normal` in world coordinates (a scene's; for
// a single plane, the viewer frame of frame 0, moving with the plane), as an application
// sets it. Precondition when given: finite, normal non-zero, the plane not through the eye.
struct StabilizationPlane {
  bool automatic = true;
  Vec3 point{0.0, 0.0, 1.0};
  Vec3 normal{0.0, 0.0, 1.0};
};

struct EngineSettings {
  // What may be reused and how levels are chosen (core/engine/reuse_policy.h); never null.
  const ReusePolicy* policy = &default_reuse_policy();
  TermArray thresholds{1.0, 1.0, 1.0, 1.0};  // pixels, budgets of none..perspective
  DeltaPolicy delta = DeltaPolicy::kDissertation;
  Sampling sampling = Sampling::kNearest;
  // Sampling limit: an affine step that would magnify the cache by more than this (largest
  // singular value of its Jacobian) re-renders instead, as magnifying loses detail.
  // It applies to every level that reuses the cache: the affine step and the affine rest
  // of a perspective update (anisotropy included: the largest singular value).
  double max_magnification = 2.0;
  // Framing (see above): the near plane Z = near (world units, > 0) and the guard band, a
  // fraction of the image size on every side (>= 0) within which the whole rectangle must
  // project to be animated.
  double near = 0.05;
  double guard_band = 0.5;
  // What a re-render draws (core/content/layer_content.h): the texture itself (default), or
  // a lit content rendered for the pose, whose image the warps then reuse. The texture
  // still gives the texel grid (its size) and the valid region (its polygon).
  LayerContent content;
  // The per-frame budget of a policy that shares one (ReusePolicy::shares_budget, the
  // `budget` policy; core/engine/budget.h): kNone takes budget_or_default's. Other
  // policies ignore it (the CLI and GUI refuse a budget without the budget policy).
  FrameBudget budget;
  // A fixed cadence's period (Schedule::kCadence policies): render every N-th frame since a
  // layer's last render, warp between; limits::kCadence (1..8). Others ignore it.
  int cadence = 2;
  // The plane of FramePlane::kStabilization policies; others ignore it.
  StabilizationPlane stabilization;
  WarpArea warp_area = WarpArea::kWhole;  // scenes only (core/image/pixel_rows.h)
};

// What the engine did in one frame. Error estimates are the engine's own bookkeeping;
// measured_error_px is the truth: the largest distance between where the shown layer's
// pixels put the texture's corners (the warp that made the layer, moved by the whole pixels
// the layer was shifted since) and the exact projection of the corners; 0 for a clipped
// exact render, NaN when the plane is not visible.
struct FrameReport {
  int frame = 0;
  Level level = Level::kNone;
  bool visible = true;   // false: nothing drawn, no error counted (see note)
  bool clipped = false;  // rendered exactly after clipping (level re-render)
  // Why a frame is special: "outside the image", "not visible: ...", "clipped: ...",
  // "sampling limit: ...", "re-rendered after a refusal: ...".
  std::string note;
  TermArray flow{};         // this frame's flow measures, pixels
  TermArray carried{};      // accumulated estimates carried into the decision, pixels
  TermArray accumulated{};  // accumulated estimates after this frame, pixels
  // Exact error each level none..perspective would have left (FrameInputs::pending).
  TermArray pending{};
  // Pending error the level left: the larger of the books (the sum of `accumulated`) and
  // the exact pending error of the chosen level, so an upper bound of the error against
  // the policy's own view of the pose (the exact projection, or its affine part).
  double estimated_error_px = 0.0;
  double measured_error_px = 0.0;
  // Policies with an affine initial view only: the error an affine view of the current pose
  // has by itself (its missing perspective), part of measured_error_px that no update level
  // can remove.
  double affine_view_error_px = 0.0;
  // What reuse adds: the largest corner distance, pixels, between where the shown layer's
  // pixels put the texture's corners and the policy's own view of the pose (the exact
  // projection, or its affine part); 0 on a re-render, NaN when the plane is not visible.
  // For a policy with an exact initial view this equals measured_error_px.
  double reuse_error_px = 0.0;
  // Wall time of the update: deciding the level, warping and placing the layer. The
  // diagnostics (measured and affine-view errors) are computed after it, untimed.
  double time_ms = 0.0;
  std::int64_t pixels_written = 0;  // pixels the warp kernels (or a content render) wrote
  // Of pixels_written, those not computed (a visible-only warp's, AnimationFrame's).
  std::int64_t pixels_not_warped = 0;
  // Of time_ms: rendering the content (a re-render, or a clipped exact render), and the rest
  // of the update (warps, placing, deciding).
  double render_ms = 0.0;
  double warp_ms = 0.0;
  // Work of the frame in the cost model above (pixels of a perspective warp): deterministic.
  double model_work = 0.0;
  // Lit contents: how stale the shown shading is, the largest change of lit intensity in
  // 8-bit grey levels since the content was rendered (shading_change in
  // core/content/layer_content.h); 0 when re-rendered this frame, for texture content and
  // when not visible. The warps follow the geometry; this is what they cannot follow.
  double photometric_error = 0.0;
  // The layer's predicted expiry (core/engine/lookahead.h), policies of the threshold rule:
  // the frame in which it is predicted to expire as of this frame (absolute; -1 when none is
  // predicted or it was rendered now), and how its life ended when this frame ended one.
  int predicted_expiry = -1;
  ExpiryOutcome expiry;
  // Which layer of its animator this is: the scene polygon's index (0 for a single plane).
  int layer = 0;
};

// The engine of one plane, driven pose by pose by its caller. Not an Animator
// (core/engine/animator.h), which owns its script: make_plane_animator plays a motion script
// through one PlaneEngine, and the scene engine (core/scene/scene_animator.h) keeps one per
// polygon.
class PlaneEngine {
 public:
  // `texture` is premultiplied RGBA (any size; an empty texture draws nothing). The
  // texture's texel size is taken from the image, overriding pose.texture_size.
  PlaneEngine(const Camera& camera, Layer texture, const EngineSettings& settings);

  // Frame 0: renders `pose` in the policy's initial view (exactly, or its affine part).
  // The same as measure_start then apply at the candidates' choice.
  FrameReport start(const PlanePose& pose);

  // The next frame: `previous` is the frame shown so far (pose and its motion towards the
  // next frame, velocities per frame), `current` the pose to show now. The same as
  // measure_advance then apply at the candidates' choice.
  FrameReport advance(const PlanePose& previous, const RigidMotion& motion,
                      const PlanePose& current);

  // The phases of a frame (core/engine/budget.h). measure_start and measure_advance say what
  // the frame start() or advance() would show could be, changing nothing the display shows:
  // a fresh render, a choice of levels, or nothing to draw. The pixel costs of the levels
  // (LayerCandidates::pixels, feasible, extent_px) are computed only for a policy that
  // shares a budget; other policies get the estimate of estimate_level_pixels.
  LayerCandidates measure_start(const PlanePose& pose);
  LayerCandidates measure_advance(const PlanePose& previous, const RigidMotion& motion,
                                  const PlanePose& current);
  // Shows the frame measured last: a kChoice frame at `level` (any level; one outside
  // `feasible` may be refused and re-render, as the policy's own choice may), a kFresh frame
  // rendered, or, with shown false, not drawn at all (FrameReport::visible false, note
  // "starved: ..."), which leaves the next frame to start afresh. time_ms includes the
  // measure. Precondition: a measure since the last apply, start or advance.
  FrameReport apply(Level level, bool shown = true);

  const PlacedLayer& displayed() const { return display_; }
  // Texel -> image pixel warp of the shown layer (the whole texture rectangle; meaningless
  // in a clipped or not visible frame, see displayed_outline).
  const Mat3& displayed_warp() const { return displayed_; }
  // The shown polygon in top-left image pixels: the texture rectangle through the displayed
  // warp, the clipped polygon's image in a clipped frame, empty when nothing is shown.
  std::vector<Vec2> displayed_outline() const;
  const EngineSettings& settings() const { return settings_; }
  const ReusePolicy& policy() const { return *settings_.policy; }

  // The frame's stabilization plane as a plane vector m in the current viewer frame
  // (core/flow/reprojection.h; m = 0 the plane at infinity), set by a scene before each
  // frame's measure; a re-render keeps the plane set then for the warps until the next one.
  // Without a call, FramePlane::kStabilization uses EngineSettings::stabilization (automatic:
  // the layer's own plane).
  void set_frame_plane(const Vec3& m);
  // The pixels (top-left) the next apply's warps must compute; null: all (PartialWarp).
  void set_shown_pixels(const PixelRows* pixels) { shown_pixels_ = pixels; }

 private:
  struct Cache {
    bool valid = false;
    Layer layer;
    MipPyramid mips;       // Sampling::kMipmap: layer's pyramid, built when the cache is made
    Mat3 from_texel{1.0};  // texel -> cache layer pixels
    Mat3 to_display{1.0};  // cache layer pixels -> image pixels (affine)
  };

  // How a pose can be drawn this frame (see "Framing" above).
  struct Framing {
    enum Kind { kWhole, kClipped, kNotShown } kind = kWhole;
    std::string note;     // kClipped, kNotShown: why
    ViewPolygon clipped;  // kClipped: the rectangle clipped to the view frustum
  };
  Framing frame_pose(const PlanePose& pose) const;

  // The frame measured last (measure_start, measure_advance) and what apply needs of it.
  struct Measured {
    bool start = false;
    PlanePose previous;
    RigidMotion motion;
    PlanePose current;
    LayerCandidates candidates;
    std::string refusal;  // what a refused measure said: the frame re-renders
    double ms = 0.0;      // time spent measuring
    FlowMeasures measures;
    TermArray flow{}, carried{}, pending{};
    Mat3 model{1.0};  // the model warp after this frame
    FitFiducials fit;
    int since_render = 1;
    double rerender_slack = 0.0, write_slack = 0.0, upgrade_slack = 0.0;  // lookahead.h
  };
  // The lives of the shown layer for lookahead's prediction (core/engine/lookahead.h): the
  // slacks since the last render, the last pixel-writing update and the last perspective
  // update, the frame of the render and the expiry predicted in each frame since (absolute,
  // -1 none).
  struct ExpiryTrack {
    bool live = false;
    int start = 0;
    SlackSeries rerender, write, upgrade;
    std::vector<int> predicted;
  };
  void measure_expiry();
  int highest_reuse_level() const;  // the highest allowed level below re-render
  void track_expiry(Level allocated, FrameReport& report);
  FrameReport apply_frame(Level level, bool shown);

  // The frame's decision (engine.cpp): the measure, the choice and the hand-over to apply.
  void measure(bool start, const PlanePose* previous, const RigidMotion* motion,
               const PlanePose& current);
  void measure_fresh(const PlanePose& pose);
  void measure_choice();
  void measure_level_costs(const Mat3& correction, const Vec2& point);
  void apply_measured(Level level, bool shown, FrameReport& report);
  void apply_choice(Level level, FrameReport& report);
  FrameReport apply_after_refusal(const std::string& refusal, double spent_ms);
  Mat3 next_model(const PlanarFlowCoefficients& flow, const PlanePose& current,
                  FitFiducials& fit) const;
  Vec3 render_plane_vector(const PlanePose& sized) const;
  Mat3 warp_after(Level level, const Mat3& correction, const Vec2& point, const Mat3& model) const;
  LevelPixels level_pixels() const;

  // The shown layer (layer_updates.cpp): the levels applied to it, its re-renders, hidden and
  // clipped frames, the perspective cache, and the error its pixels measure.
  void render_fresh(const PlanePose& pose, FrameReport& report);
  void hide(const std::string& note, FrameReport& report);
  void show_clipped(const PlanePose& pose, const Framing& framing, FrameReport& report);
  void apply_level(FrameReport& report, const Vec2& expansion_point, const PlanePose& current);
  void rerender(const PlanePose& pose, FrameReport& report);
  // rerender of a lit content: renders it (kept for the perspective level) and shows it.
  void rerender_content(const PlanePose& pose, FrameReport& report);
  void apply_translation(const Vec2& step);
  bool apply_affine(const Mat3& correction, const Vec2& point, FrameReport& report);
  bool apply_perspective(const Mat3& target, FrameReport& report);
  // Warps `source` by source_to_image into the displayed layer (reusing memory) and places
  // it; texel_to_image is the warp the layer then shows (for the measured error).
  void show(const Layer& source, const Mat3& source_to_image, const Mat3& texel_to_image,
            FrameReport& report);
  // Warps `source` into warped_ (memory reused; `only`'s pixels, those computed added to
  // `computed`), counts them. Mipmap: a kept source's kept pyramid (pyramid_of), else its own.
  void warp_reusing(const Layer& source, const Mat3& warp, FrameReport& report,
                    const PixelRows* only = nullptr, PixelRows* computed = nullptr);
  // A partly warped display: warps what its warp left out that the frame shows now (all).
  void complete_display(FrameReport& report, bool all = false);
  const MipPyramid* pyramid_of(const Layer& source) const;
  // Builds `pyramid` of `layer` when the sampling is mipmap: once per render of a layer.
  void keep_pyramid(const Layer& layer, MipPyramid& pyramid) const;
  void cache_from_display();
  void show_from_cache(FrameReport& report);
  // A lit content's last render: rendered_, or display_.layer while that is the render; a
  // render kept there moves to rendered_ (a swap) before that memory is replaced.
  const Layer& kept_render() const { return render_in_display_ ? display_.layer : rendered_; }
  void keep_render_from_display(Layer& display_memory);
  void finish_report(const PlanePose& pose, FrameReport& report) const;
  // The policy's view of a pose: the exact texel -> image warp, or its affine part.
  Mat3 target_warp(const PlanePose& pose) const;
  Vec2 translation_step(const Mat3& correction, const Vec2& point) const;
  // The texture rectangle's corners in texels, and where warps put them.
  std::array<Vec2, 4> texel_corners() const;
  std::vector<Vec2> displayed_corners_centred() const;
  double corner_distance(const Mat3& a, const Mat3& b) const;
  // The largest corner distance (pixels) from the shown layer to `reference` (texel -> image).
  double shown_error(const Mat3& reference) const;
  PlanePose sized_pose(const PlanePose& pose) const;

  Camera camera_;
  Layer texture_;
  MipPyramid texture_mips_;  // Sampling::kMipmap: the texture's pyramid, built once
  EngineSettings settings_;
  PlacedLayer display_;
  // The warp that made display_.layer (texel -> image pixels) and the layer's offset then:
  // the measured error follows the pixels from these, independently of displayed_.
  Mat3 layer_warp_{1.0};
  glm::ivec2 layer_origin_{0, 0};
  std::vector<Vec2> clipped_outline_;  // the shown polygon of a clipped frame
  bool clipped_ = false;               // the last frame was a clipped render
  Mat3 displayed_{1.0};
  Mat3 model_{1.0};
  Mat3 rendered_warp_{1.0};  // displayed_ at the last re-render (Talisman's fit starts from it)
  FitFiducials fit_;         // ModelUpdate::kAffineFit: this frame's fiducials
  Cache cache_;
  // Lit content: its last render (kept only when the policy reuses) and the texel -> layer
  // pixel warp it was rendered with; the pose it was lit at.
  Layer rendered_;
  bool render_in_display_ = false;  // kept_render() is display_.layer: shown, not copied
  MipPyramid rendered_mips_;        // Sampling::kMipmap: kept_render()'s pyramid
  Mat3 rendered_from_texel_{1.0};
  PlanePose rendered_pose_;
  // Scratch of every warp, swapped with the display or the cache: a few buffers, reused.
  WarpedLayer warped_;
  TermArray accumulated_{};
  // Today's reprojection: the pose and frame plane at the last render, this frame's plane
  // (set_frame_plane), the first pose shown (a stabilization plane's world), frames since.
  PlanePose render_pose_;
  Vec3 render_plane_{0.0};
  Vec3 frame_plane_{0.0};
  bool frame_plane_set_ = false;
  PlanePose origin_pose_;
  bool origin_set_ = false;
  int since_render_ = 0;
  // True while the shown layer is the whole plane and may be reused: false before the first
  // render and after a frame that was clipped or not visible.
  bool shown_ = false;
  int frame_ = 0;
  Measured measured_;
  ExpiryTrack expiry_;
  // Visible-only warps: the pixels shown, and the display's warp (done at layer_origin_).
  const PixelRows* shown_pixels_ = nullptr;
  PartialWarp partial_;
};

}  // namespace oflab
