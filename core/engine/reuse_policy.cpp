// The registry of reuse policies (see core/engine/reuse_policy.h and manual/animation.md).
#include "engine/reuse_policy.h"

#include <algorithm>
#include <stdexcept>

namespace oflab {
namespace {

constexpr LevelSet kNoPerspective{true, true, true, false, true};
constexpr LevelSet kOnlyRerender{false, false, false, false, true};
constexpr LevelSet kAffineOnly{false, false, true, false, true};

constexpr LevelSet kWarpOrRerender{false, false, false, true, true};

Level always_rerender(const ReusePolicy&, const FrameInputs&) { return Level::kRerender; }

ReusePolicy described(ReusePolicy p, const char* models, const char* breaks) {
  p.models = models;
  p.breaks = breaks;
  return p;
}

// A policy of today's reprojection: a fixed cadence, the perspective level showing its model.
ReusePolicy on_cadence(const char* name, const char* summary, ModelUpdate model, FramePlane plane,
                       FrameWarp warp, const char* models, const char* breaks) {
  ReusePolicy p{name, summary, InitialView::kExact, model, kWarpOrRerender, cadence_choice};
  p.bounded = false;  // a cadence shows its warp whatever the error
  p.schedule = Schedule::kCadence;
  p.frame_plane = plane;
  p.frame_warp = warp;
  return described(p, models, breaks);
}

// Shade et al. 96: the scene engine plays it (core/scene/hierarchical_cache.h); `choose` is
// never asked, a node's rule being its angle and sphere (cache_render_cause).
ReusePolicy hierarchical_cache() {
  ReusePolicy p{"hierarchical-cache",
                "Shade et al. 96: BSP nodes cached as images on quads, angular error, scenes only",
                InitialView::kExact,
                ModelUpdate::kExact,
                kWarpOrRerender,
                always_rerender};
  p.bounded = false;  // an angle at eight box corners does not bound the pixels in between
  p.frame_warp = FrameWarp::kNodeImages;
  return described(p,
                   "hierarchical image caching (Shade, Lischinski, Salesin, DeRose & Snyder 96; "
                   "dissertation section 2.4.7): a node's image on one quad",
                   "depth inside a node close to the viewer: one quad per node, an angle at the "
                   "box corners only");
}

// Section 7.5.4: the corrected rule per layer, its updates scheduled ahead of the predicted
// expiries (core/engine/lookahead.h).
ReusePolicy lookahead() {
  ReusePolicy p{"lookahead",
                "section 7.5.4: each layer's expiry predicted, updates spread ahead of it",
                InitialView::kExact,
                ModelUpdate::kTaylor,
                kAllLevels,
                threshold_choice};
  p.spreads_updates = true;
  return described(p,
                   "predictive reuse (dissertation section 7.5.4; regulation after Horvitz & "
                   "Lengyel 97): expiry predicted from the flow and its time derivative",
                   "motion that changes faster than its derivative predicts: early updates "
                   "then cost pixels without flattening the peaks");
}

// Frame generation by extrapolation along motion vectors (core/scene/frame_generation.h): a
// per-pixel warp on the fixed cadence, without the new pose.
ReusePolicy mv_extrapolation(const char* name, const char* summary, bool inpaint,
                             const char* breaks) {
  ReusePolicy p = on_cadence(
      name, summary, ModelUpdate::kExact, FramePlane::kInfinity, FrameWarp::kPerPixelDepth,
      "frame generation by extrapolation along motion vectors (the family of DLSS 3 / FSR 3 "
      "frame generation; disocclusion mask and inpainting pyramid after AMD FidelityFX FSR 3)",
      breaks);
  p.pixel_motion = PixelMotion::kMotionVectors;
  p.inpaint = inpaint;
  return p;
}

// View interpolation (Chen & Williams 93; core/scene/view_interpolation.h): the frames between
// two renders warped from both by depth to the true pose, shown late.
ReusePolicy view_interpolation() {
  ReusePolicy p = on_cadence(
      "view-interpolation",
      "view interpolation: the frames between two renders warped from both by depth, late",
      ModelUpdate::kExact, FramePlane::kInfinity, FrameWarp::kPerPixelDepth,
      "view interpolation (Chen & Williams 93): in-between views from two rendered views and "
      "their depth; the interpolating form of frame generation",
      "latency: each frame waits for the next render (cadence - 1 frames); what neither "
      "render saw is a hole");
  p.pixel_motion = PixelMotion::kBetweenRenders;
  return p;
}

// Textured depth meshes (Sillion, Drettakis & Bodelet 97; core/scene/depth_mesh.h): the far
// part drawn as a mesh of its last render's depth, the near part rendered every frame.
ReusePolicy depth_mesh() {
  ReusePolicy p = on_cadence(
      "depth-mesh",
      "textured depth meshes: near part rendered, far part a mesh of its rendered depth",
      ModelUpdate::kExact, FramePlane::kInfinity, FrameWarp::kPerPixelDepth,
      "textured depth meshes (Sillion, Drettakis & Bodelet 97): a far impostor of urban "
      "scenery, lifted by its depth, the near part rendered",
      "depth discontinuities in the far part: rubber sheets, or holes where they are dropped; "
      "triangles across a crease cut the corner");
  p.pixel_motion = PixelMotion::kFarMesh;
  return p;
}

}  // namespace

LevelPixels estimate_level_pixels(std::int64_t displayed_px, std::int64_t cache_px) {
  return {0, 0, displayed_px, cache_px + displayed_px, displayed_px};
}

bool ReusePolicy::allows_reuse() const {
  for (int l = 0; l < static_cast<int>(Level::kRerender); ++l) {
    if (allowed[l]) return true;
  }
  return false;
}

Level threshold_choice(const ReusePolicy& policy, const FrameInputs& inputs) {
  return choose_level(inputs.carried, inputs.flow, inputs.thresholds, policy.allowed,
                      inputs.pending);
}

Level printed_choice(const ReusePolicy&, const FrameInputs& inputs) {
  return printed_cascade(inputs.carried, inputs.flow, inputs.thresholds);
}

Level talisman_choice(const ReusePolicy&, const FrameInputs& inputs) {
  const FitFiducials& f = inputs.fit;
  const bool geometric = f.geometric_px <= inputs.thresholds[static_cast<int>(Level::kAffine)];
  const bool sampling = f.sigma_max <= kTalismanMaxMagnification &&
                        f.sigma_min >= kTalismanMinMagnification &&
                        f.sigma_max <= kTalismanMaxAnisotropy * f.sigma_min;
  return geometric && sampling && !f.facing_changed ? Level::kAffine : Level::kRerender;
}

Level cadence_choice(const ReusePolicy&, const FrameInputs& inputs) {
  return inputs.since_render >= inputs.cadence ? Level::kRerender : Level::kPerspective;
}

int latency_frames(const ReusePolicy& policy, int cadence) {
  return policy.pixel_motion == PixelMotion::kBetweenRenders ? std::max(0, cadence - 1) : 0;
}

bool reports_holes(const ReusePolicy& policy) {
  return policy.frame_warp != FrameWarp::kPerLayer || policy.schedule == Schedule::kCadence;
}

bool needs_scene(const ReusePolicy& policy, std::string* why) {
  const char* reason = nullptr;
  if (policy.frame_warp == FrameWarp::kNodeImages) {
    reason = "a single plane has no BSP tree to group into nodes";
  } else if (policy.pixel_motion == PixelMotion::kMotionVectors) {
    reason = "its motion vectors and depth are a rendered scene frame's";
  } else if (policy.pixel_motion == PixelMotion::kBetweenRenders) {
    reason = "its two views' depths are rendered scene frames, the later one a viewer script's";
  } else if (policy.pixel_motion == PixelMotion::kFarMesh) {
    reason = "its near and far parts are a scene's polygons";
  }
  if (reason && why) *why = reason;
  return reason != nullptr;
}

const char* frame_warp_name(FrameWarp warp) {
  switch (warp) {
    case FrameWarp::kPerLayer:
      return "per-layer";
    case FrameWarp::kPerPixelDepth:
      return "per-pixel-depth";
    case FrameWarp::kNodeImages:
      return "node-images";
  }
  return "per-layer";
}

const std::vector<ReusePolicy>& reuse_policies() {
  static const std::vector<ReusePolicy> policies = {
      described(
          {"perspective", "Algorithm 1, corrected: every level, first-order Taylor flow model",
           InitialView::kExact, ModelUpdate::kTaylor, kAllLevels, threshold_choice},
          "the dissertation's optic-flow reuse (section 5.6.1, corrected): a plane per layer",
          "keeps every layer within its thresholds; pays re-renders where the flow is not "
          "first-order"),
      described(
          {"affine", "section 6.5: affine initial view and flow model, no perspective level",
           InitialView::kAffinePart, ModelUpdate::kAffineTaylor, kNoPerspective, threshold_choice},
          "the dissertation's affine mode (section 6.5)",
          "its affine view misses the plane's perspective, which no level removes"),
      described({"exact", "every level, but the model follows the exact warp of each pose",
                 InitialView::kExact, ModelUpdate::kExact, kAllLevels, threshold_choice},
                "optic-flow reuse with an exact model (oflab)",
                "needs the exact pose of every layer each frame"),
      described({"rerender", "the baseline: no reuse, every frame rendered exactly",
                 InitialView::kExact, ModelUpdate::kExact, kOnlyRerender, always_rerender},
                "conventional rendering", "never: it saves nothing"),
      described(
          {"dissertation", "Algorithm 1 as printed: per-term cascade, bounding-box size, |Omega|^2",
           InitialView::kExact, ModelUpdate::kTaylor, kAllLevels, printed_choice,
           FlowBooks::kPrinted, false},
          "Algorithm 1 as printed (section 5.4.5)",
          "does not bound the error; |Omega|^2 re-renders whatever rotates"),
      described(
          {"talisman", "Lengyel & Snyder 97: least-squares affine warp of the layer, fiducials",
           InitialView::kExact, ModelUpdate::kAffineFit, kAffineOnly, talisman_choice},
          "Talisman's layer compositor (Torborg & Kajiya 96, Lengyel & Snyder 97)",
          "perspective motion that no affine warp fits: it re-renders"),
      described(
          {"budget", "section 7.5.2: a per-frame pixel or time budget allocated over the layers",
           InitialView::kExact, ModelUpdate::kTaylor, kAllLevels, threshold_choice,
           FlowBooks::kCorners, false, true},
          "a per-frame budget (section 7.5.2; Horvitz & Lengyel 97)",
          "a budget too small for the motion starves layers and lets the error grow"),
      on_cadence("timewarp",
                 "asynchronous timewarp: rotation-only homography K R K^-1, fixed cadence",
                 ModelUpdate::kFrameHomography, FramePlane::kInfinity, FrameWarp::kPerLayer,
                 "asynchronous timewarp (Oculus/Meta ATW, SteamVR): the plane at infinity",
                 "translation: blind to it and to parallax, error grows with inverse depth"),
      on_cadence(
          "stabilized-plane",
          "late-stage reprojection: one stabilization plane's homography for the frame",
          ModelUpdate::kFrameHomography, FramePlane::kStabilization, FrameWarp::kPerLayer,
          "late-stage reprojection with a stabilization plane (HoloLens; OpenXR planar "
          "reprojection)",
          "content away from the plane: error grows with distance from it under translation"),
      on_cadence("depth-reprojection",
                 "post-rendering 3D warping: the frame forward-warped by per-pixel depth",
                 ModelUpdate::kExact, FramePlane::kInfinity, FrameWarp::kPerPixelDepth,
                 "post-rendering 3D warping (Mark, McMillan & Bishop 97), positional timewarp",
                 "disocclusion: what was hidden at the render is a hole (marked, never filled "
                 "silently)"),
      on_cadence("cadence", "each layer by its own plane's exact homography, fixed cadence",
                 ModelUpdate::kExact, FramePlane::kInfinity, FrameWarp::kPerLayer,
                 "oflab's plane per layer on a fixed cadence (asynchronous spacewarp's schedule)",
                 "only resampling and the sampling limit: the fair comparison for the three"),
      hierarchical_cache(),
      mv_extrapolation(
          "mv-extrapolation",
          "frame generation: the render splatted along its motion vectors, holes inpainted", true,
          "acceleration and turns (the vectors are of the last step), and disocclusions: "
          "inpainting guesses what was hidden"),
      mv_extrapolation("mv-no-inpaint",
                       "frame generation along motion vectors, disocclusions left empty", false,
                       "as mv-extrapolation, with its disocclusions left as holes"),
      view_interpolation(),
      depth_mesh(),
      lookahead(),
  };
  return policies;
}

const char* level_word(const ReusePolicy& policy, Level level) {
  if (policy.frame_warp == FrameWarp::kNodeImages) {
    return level == Level::kRerender ? "rendered" : "cached";
  }
  if (policy.pixel_motion == PixelMotion::kMotionVectors) {
    return level == Level::kRerender ? "rendered" : "generated";
  }
  if (policy.pixel_motion == PixelMotion::kBetweenRenders) {
    return level == Level::kRerender ? "rendered" : "interpolated";
  }
  if (policy.pixel_motion == PixelMotion::kFarMesh) {
    return level == Level::kRerender ? "rendered" : "meshed";
  }
  if (policy.schedule == Schedule::kCadence) {
    return level == Level::kRerender ? "rendered" : "reprojected";
  }
  return level_name(level);
}

const ReusePolicy* find_reuse_policy(const std::string& name) {
  for (const ReusePolicy& p : reuse_policies()) {
    if (name == p.name) return &p;
  }
  return nullptr;
}

const ReusePolicy& reuse_policy(const std::string& name) {
  const ReusePolicy* p = find_reuse_policy(name);
  if (!p) {
    throw std::invalid_argument("unknown reuse policy '" + name + "' (one of " +
                                reuse_policy_names() + ")");
  }
  return *p;
}

const ReusePolicy& default_reuse_policy() { return reuse_policies().front(); }

std::string reuse_policy_names(const std::string& separator) {
  std::string names;
  for (const ReusePolicy& p : reuse_policies()) {
    names += (names.empty() ? "" : separator) + std::string(p.name);
  }
  return names;
}

}  // namespace oflab
