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
//   translate: the whole-pixel part of C's motion of the expansion point;
//   affine: C's first-order (affine) part about the expansion point;
//   perspective: C itself (a new cache, then the affine step);
//   re-render: D = the exact warp, rendered straight from the texture.
#pragma once

#include <cstdint>
#include <string>

#include "flow/camera.h"
#include "engine/decision.h"
#include "engine/reuse_policy.h"
#include "flow/decomposition.h"
#include "image/layer.h"
#include "flow/motion.h"
#include "flow/plane.h"
#include "image/warp.h"

namespace oflab {

struct EngineSettings {
  // What may be reused and how levels are chosen (core/engine/reuse_policy.h); never null.
  const ReusePolicy* policy = &default_reuse_policy();
  TermArray thresholds{1.0, 1.0, 1.0, 1.0};  // pixels, budgets of none..perspective
  DeltaPolicy delta = DeltaPolicy::kDissertation;
  Sampling sampling = Sampling::kNearest;
  // Sampling limit: an affine step that would magnify the cache by more than this (largest
  // singular value of its Jacobian) re-renders instead, as magnifying loses detail.
  double max_magnification = 2.0;
};

// What the engine did in one frame. Error estimates are the engine's own bookkeeping;
// measured_error_px is the truth: the largest distance between the displayed polygon's
// corners and the exact projection (NaN when the plane is not visible).
struct FrameReport {
  int frame = 0;
  Level level = Level::kNone;
  bool visible = true;
  std::string note;           // why a frame is special: "not visible: ...", "sampling limit"
  TermArray flow{};           // this frame's flow measures, pixels
  TermArray carried{};        // accumulated estimates carried into the decision, pixels
  TermArray accumulated{};    // accumulated estimates after this frame, pixels
  double estimated_error_px = 0.0;  // pending error the level left, by the estimates
  double measured_error_px = 0.0;
  // Policies with an affine initial view only: the error an affine view of the current pose
  // has by itself (its missing perspective), part of measured_error_px that no update level
  // can remove.
  double affine_view_error_px = 0.0;
  // Wall time of the update: deciding the level, warping and placing the layer. The
  // diagnostics (measured and affine-view errors) are computed after it, untimed.
  double time_ms = 0.0;
  std::int64_t pixels_written = 0;  // pixels the warp kernels wrote this frame
};

// The exact image of a textured plane: the texture warped by texture_to_image (in top-left
// pixels), as a layer placed at (offset_x, offset_y) of the image. Empty when the plane is
// not visible (see plane_visibility_problem).
struct PlacedLayer {
  Layer layer;
  int offset_x = 0;
  int offset_y = 0;
};

// Empty when the plane can be drawn; else why not: a pose problem, a corner at or behind
// the eye (Z <= 1e-6), or a view within about 0.06 degrees of edge-on.
std::string plane_visibility_problem(const PlanePose& pose);

// The exact texel -> top-left image pixel homography of a pose, with a positive
// denominator over the visible plane. Precondition: plane_visibility_problem is empty.
Mat3 exact_texture_warp(const Camera& camera, const PlanePose& pose);

// Renders the plane exactly (one perspective warp of the texture). `stats` if non-null
// receives the warp statistics. Never throws for a visible plane with a valid texture.
PlacedLayer render_exact(const Camera& camera, const Layer& texture, const PlanePose& pose,
                         Sampling sampling, WarpStats* stats = nullptr);

class PlaneAnimator {
 public:
  // `texture` is premultiplied RGBA (any size; an empty texture draws nothing). The
  // texture's texel size is taken from the image, overriding pose.texture_size.
  PlaneAnimator(const Camera& camera, Layer texture, const EngineSettings& settings);

  // Frame 0: renders `pose` in the policy's initial view (exactly, or its affine part).
  FrameReport start(const PlanePose& pose);

  // The next frame: `previous` is the frame shown so far (pose and its motion towards the
  // next frame, velocities per frame), `current` the pose to show now.
  FrameReport advance(const PlanePose& previous, const RigidMotion& motion,
                      const PlanePose& current);

  const PlacedLayer& displayed() const { return display_; }
  const Mat3& displayed_warp() const { return displayed_; }
  const EngineSettings& settings() const { return settings_; }
  const ReusePolicy& policy() const { return *settings_.policy; }

 private:
  struct Cache {
    bool valid = false;
    Layer layer;
    Mat3 from_texel{1.0};  // texel -> cache layer pixels
    Mat3 to_display{1.0};  // cache layer pixels -> image pixels (affine)
  };

  void decide_and_update(const PlanePose& previous, const RigidMotion& motion,
                         const PlanePose& current, FrameReport& report);
  void advance_model(const PlanarFlowCoefficients& flow, const PlanePose& current);
  void apply_level(FrameReport& report, const Vec2& expansion_point, const PlanePose& current);
  void rerender(const PlanePose& pose, FrameReport& report);
  void apply_translation(const Mat3& correction, const Vec2& point);
  void place_display();
  // Warps `source` into the displayed layer (reusing memory) and places it.
  void show(const Layer& source, const Mat3& source_to_image, FrameReport& report);
  // Warps `source` into warped_, reusing its memory; counts the pixels written.
  void warp_reusing(const Layer& source, const Mat3& warp, FrameReport& report);
  void cache_from_display();
  void finish_report(const PlanePose& pose, FrameReport& report) const;
  LevelPixels level_pixels() const;
  bool apply_affine(const Mat3& correction, const Vec2& point, FrameReport& report);
  void apply_perspective(const Mat3& target, FrameReport& report);
  void rebuild_cache(const Mat3& target, FrameReport& report);
  void show_from_cache(FrameReport& report);
  std::vector<Vec2> displayed_corners_centred() const;
  double corner_error(const PlanePose& pose) const;
  PlanePose sized_pose(const PlanePose& pose) const;

  Camera camera_;
  Layer texture_;
  EngineSettings settings_;
  PlacedLayer display_;      // drawn at base_offset_ + round(shift_)
  glm::ivec2 base_offset_{0, 0};
  Vec2 shift_{0.0};          // exact translation applied since the layer was warped
  Mat3 displayed_{1.0};
  Mat3 model_{1.0};
  Cache cache_;
  // Scratch of every warp: swapped with the displayed or the cache layer after a warp, so
  // that in a steady state the frames reuse the same few layer buffers.
  WarpedLayer warped_;
  TermArray accumulated_{};
  bool shown_ = false;  // false until something visible has been rendered
  int frame_ = 0;
};

}  // namespace oflab
