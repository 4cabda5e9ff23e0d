// Reuse policies: the registry of the ways the engine (core/engine/engine.h) may reuse the
// previous image of a plane. A policy is data plus one function: the initial view it shows,
// how its model of the displayed warp advances, the update levels it allows and how it
// chooses one each frame. The CLI (`oflab-cli animate --mode`, `oflab-cli policies`), the
// GUI, session files and help texts all read this table; adding a policy is adding an
// entry to reuse_policies() (core/engine/reuse_policy.cpp), see manual/animation.md.
//
// The first four entries are the dissertation's modes:
//   perspective  Algorithm 1, corrected (section 5.6.1): every level, Taylor model;
//   affine       section 6.5: no perspective level, affine initial view and flow model;
//   exact        the perspective level uses the exact frame-to-frame homography;
//   rerender     the baseline: no reuse, every frame rendered exactly.
// The rivals and the printed rule, for comparison (manual/policies.md):
//   dissertation Algorithm 1 as printed (section 5.4.5): per-term cascade, printed measures;
//   talisman     Lengyel & Snyder 97: a least-squares affine warp of the layer as rendered,
//                re-rendered when a fiducial (geometric, sampling, visibility) is over its limit.
// A policy over all the layers of a frame:
//   budget       section 7.5.2 and Horvitz & Lengyel 97: a per-frame budget (pixels or
//                milliseconds, EngineSettings::budget) allocated over the layers by cost and
//                benefit (core/engine/budget.h).
// A policy that schedules ahead (core/engine/lookahead.h):
//   lookahead    section 7.5.4: each layer's expiry predicted from its error's growth and the
//                growth's time derivative; pixel-writing updates moved ahead of it onto
//                frames with fewer pixels planned, so that no frame's cost peaks.
// Today's reprojection, on a fixed cadence (render every N-th frame, warp the frames between;
// EngineSettings::cadence; manual/policies.md "Today's reprojection"):
//   timewarp            asynchronous timewarp: every layer by the rotation-only homography
//                       K R K^-1 (the plane at infinity);
//   stabilized-plane    late-stage reprojection: every layer by the homography of one
//                       stabilization plane for the whole frame (EngineSettings::stabilization);
//   depth-reprojection  post-rendering 3D warping: the composited frame forward-warped by each
//                       pixel's depth (core/scene/depth_reprojection.h), holes marked;
//   cadence             each layer by its own plane's exact homography: the fair comparison.
// Frame generation by extrapolation (the family of DLSS 3 / FSR 3 frame generation), scenes only:
//   mv-extrapolation    the last render splatted forward along its per-pixel motion vectors,
//                       without the new pose, disocclusions masked and filled by pyramid
//                       (push-pull) inpainting (core/scene/frame_generation.h);
//   mv-no-inpaint       the same with the disocclusions left empty.
// View interpolation (Chen & Williams 93), scenes only:
//   view-interpolation  the frames between two renders made from both: each render forward-warped
//                       by its depth to the viewer now, nearest surface kept
//                       (core/scene/view_interpolation.h); it waits for the later render, so it
//                       shows each frame cadence - 1 frames late.
// Textured depth meshes (Sillion, Drettakis & Bodelet 97), scenes only:
//   depth-mesh          the near part rendered every frame, the far part (beyond a split depth)
//                       drawn as a mesh lifted from its rendered depth and textured with its
//                       render, rebuilt on the cadence (core/scene/depth_mesh.h).
// The dissertation's other named rival (section 2.4.7):
//   hierarchical-cache  Shade et al. 96: BSP nodes cached as images on quads facing the viewer,
//                       warped by the quad's homography, re-rendered by an angular error at
//                       the nodes' box corners or outside a safety sphere (scenes only;
//                       core/scene/hierarchical_cache.h).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "engine/affine_fit.h"
#include "engine/decision.h"

namespace oflab {

// The displayed warp a policy shows after a re-render (frame 0 and every re-render level).
enum class InitialView {
  kExact,       // the exact texel -> image warp of the pose (exact_texture_warp)
  kAffinePart,  // its affine part about the texture centre (section 6.5): the frame is an
                // affine image, whose missing perspective no update level can remove
};

// How the engine's model warp B (engine.h) follows the plane from frame to frame.
enum class ModelUpdate {
  kTaylor,           // B <- H1 B, H1 the first-order Taylor homography of the frame's flow
  kAffineTaylor,     // the same with the perspective terms px, py zeroed (an affine flow model)
  kExact,            // B <- the exact texture warp of the current pose: the model misses nothing
                     // of higher order, so the engine takes the higher-order term as zero
  kFrameHomography,  // one homography for every layer of the frame, from the last render:
                     // B <- P(R + t m^T)P^-1 B_render with (R, t) the rigid motion of the
                     // viewer frame since the render and m the plane vector (1/Z =
                     // m.(x/f, y/f, 1)) of the policy's FramePlane at the render; exact for
                     // points on that plane, wrong by the parallax of every other depth
  kAffineFit,        // Talisman: B <- A R, R the warp of the last render and A the least-squares
                     // affine map of the texture corners as rendered (R) onto their exact
                     // projections now (affine_fit.h); the fit is checked against the exact
                     // projection every frame, so no error is carried in the books
};

// Which flow measures a policy's books and choice read (FrameInputs::flow, FrameReport::flow).
enum class FlowBooks {
  kCorners,  // measure_flow: per-corner bounds about the expansion point (corrected)
  kPrinted,  // measure_printed_flow: section 5.4.5 as printed (bounding-box size, |Omega|^2)
};

// When a policy renders: the threshold rule of Algorithm 1 (every policy's `choose` reads the
// error books and thresholds), or a fixed cadence (render every N-th frame, warp between:
// cadence_choice; asynchronous spacewarp renders every 2nd).
enum class Schedule { kThreshold, kCadence };

// The plane whose homography ModelUpdate::kFrameHomography applies to every layer.
enum class FramePlane {
  kInfinity,       // the plane at infinity: K R K^-1, rotation only (timewarp)
  kStabilization,  // EngineSettings::stabilization: a given plane, or the automatic fit
};

// What a frame warp moves: each layer by its own warp (the engine), the composited frame
// pixel by pixel by its depth (the scene engine, core/scene/depth_reprojection.h), or one
// cached image per node of the scene's BSP tree (core/scene/hierarchical_cache.h; scenes
// only: a single plane has no tree to group).
enum class FrameWarp { kPerLayer, kPerPixelDepth, kNodeImages };

// Where a per-pixel frame warp (FrameWarp::kPerPixelDepth) moves each pixel of the last render:
// by the viewer's true step since the render (depth reprojection, which knows the new pose),
// along the render's per-pixel motion vectors extrapolated to the new time without the new pose
// (frame generation by extrapolation, core/scene/frame_generation.h), or, with the render that
// follows as well, both moved by the viewer's true step to the pose between them (view
// interpolation, core/scene/view_interpolation.h: it waits for the later render); or only the
// far part's pixels, as the vertices of a mesh lifted by their depth and drawn from the viewer
// now, the near part rendered (textured depth meshes, core/scene/depth_mesh.h).
enum class PixelMotion { kViewerStep, kMotionVectors, kBetweenRenders, kFarMesh };
// "per-layer", "per-pixel-depth" or "node-images".
const char* frame_warp_name(FrameWarp warp);

// Talisman's sampling limits on the singular values of the fitted warp's 2x2 part
// (FitFiducials): the layer may be magnified at most 2x (the engine's default sampling
// limit, EngineSettings::max_magnification), minified at most 2x, and stretched at most 2x
// more along one axis than along the other. Its geometric limit is the affine level's
// threshold (thresholds[2]), so that it keeps the same pixel budget as the other policies.
constexpr double kTalismanMaxMagnification = 2.0;
constexpr double kTalismanMinMagnification = 0.5;
constexpr double kTalismanMaxAnisotropy = 2.0;

// Pixels each level would write, indexed by static_cast<int>(Level).
using LevelPixels = std::array<std::int64_t, kLevelCount>;

// Everything a policy sees when it chooses the level of one frame of one plane.
struct FrameInputs {
  TermArray flow{};        // this frame's flow measures (measure_flow), pixels
  TermArray carried{};     // accumulated errors carried into the decision, pixels
  TermArray thresholds{};  // budgets of none..perspective, pixels (see choose_level)
  LevelPixels pixels{};    // cost of each level for this layer (estimate_level_pixels)
  // The exact error each level none..perspective would leave: the largest corner distance,
  // pixels, between the warp that level would show and the policy's own view of the
  // current pose (the engine has the poses). Where the first-order books underestimate,
  // this is what bounds the shown error.
  TermArray pending{};
  // ModelUpdate::kAffineFit only: the fiducials of this frame's fitted warp (affine_fit.h).
  FitFiducials fit{};
  // Frames since the layer was last rendered, this one included (>= 1), and the fixed
  // cadence of EngineSettings::cadence (1..8): what cadence_choice reads.
  int since_render = 1;
  int cadence = 2;
};

// The cost estimate of FrameInputs::pixels, before any warp is run, from the layers the
// engine holds: `displayed_px` is the pixel count (width x height) of the displayed layer
// and `cache_px` that of the perspective cache (the displayed layer's when there is none).
//   none, translate: 0 (the layer is reused, or placed again on whole pixels);
//   affine: displayed_px (the cache warped onto a layer of about the displayed size);
//   perspective: cache_px + displayed_px (a new cache of about the old one's size, then
//     the affine step);
//   rerender: displayed_px (the texture warped straight onto a layer of that size).
// Upper bounds: the kernels write only the pixels inside the warped polygon.
LevelPixels estimate_level_pixels(std::int64_t displayed_px, std::int64_t cache_px);

struct ReusePolicy {
  const char* name;     // the identifier of --mode, session files and JSON "mode"
  const char* summary;  // one line for `oflab-cli policies` and tooltips
  InitialView initial_view;
  ModelUpdate model;
  LevelSet allowed;  // levels it may choose; re-render is always allowed
  // The level of this frame; must be one of `allowed` (re-render is always acceptable).
  Level (*choose)(const ReusePolicy& policy, const FrameInputs& inputs);
  FlowBooks books = FlowBooks::kCorners;
  // True when the rule keeps the measured error of every shown frame within the thresholds
  // (up to resampling): the corrected rules and Talisman's geometric fiducial do; the
  // printed rule does not (that is what it is compared for).
  bool bounded = true;
  // True when the levels of a frame are allocated over all its layers within a per-frame
  // budget (core/engine/budget.h allocate_frame); `choose` is then what a layer would take
  // were the budget unlimited.
  bool shares_budget = false;
  // True when the frame's layers are scheduled together ahead of their predicted expiries
  // (core/engine/lookahead.h spread_updates): `choose` is a layer's own choice, which the
  // schedule may bring forward (a writing level or a re-render now instead of later).
  bool spreads_updates = false;
  // Today's reprojection (manual/policies.md): the schedule, the plane of a kFrameHomography
  // model and what the frame warp moves (the delay it adds: latency_frames below).
  Schedule schedule = Schedule::kThreshold;
  FramePlane frame_plane = FramePlane::kInfinity;
  FrameWarp frame_warp = FrameWarp::kPerLayer;
  // FrameWarp::kPerPixelDepth: how the pixels move, and whether the disocclusions of a
  // motion-vector extrapolation are filled by pyramid inpainting (else left empty).
  PixelMotion pixel_motion = PixelMotion::kViewerStep;
  bool inpaint = false;
  // For `oflab-cli policies`: the system it models (with its source) and where it breaks.
  const char* models = "";
  const char* breaks = "";

  bool allows(Level level) const { return allowed[static_cast<int>(level)]; }
  // False when only re-render is allowed: the engine then re-renders without measuring.
  bool allows_reuse() const;
};

// The threshold rule of Algorithm 1 (choose_level) over the policy's allowed levels, a
// level being acceptable only when its exact pending error also stays within its
// threshold; the choice of perspective, affine and exact.
Level threshold_choice(const ReusePolicy& policy, const FrameInputs& inputs);

// Algorithm 1's printed cascade (printed_cascade) over the books; the choice of dissertation.
Level printed_choice(const ReusePolicy& policy, const FrameInputs& inputs);

// Talisman's choice: affine when every fiducial of inputs.fit is within its limit (geometric
// <= thresholds[2], the sampling limits above, no change of facing), else re-render.
Level talisman_choice(const ReusePolicy& policy, const FrameInputs& inputs);

// The fixed cadence: re-render when inputs.since_render >= inputs.cadence (frame 0 and every
// cadence-th frame after a render), else perspective (the policy's model warp, whatever
// the error); the choice of timewarp, stabilized-plane, depth-reprojection and cadence.
Level cadence_choice(const ReusePolicy& policy, const FrameInputs& inputs);

// The frames of delay `policy` adds on a fixed cadence of `cadence` (>= 1) frames: 0 for every
// policy that extrapolates from the last render; cadence - 1 for one that interpolates between
// two renders (PixelMotion::kBetweenRenders): the first frame after a render can be shown only
// once the next render, cadence frames after the first, is made, so every frame is shown
// cadence - 1 frames after its viewer was known.
int latency_frames(const ReusePolicy& policy, int cadence);

// True when the policy's frames can have holes (FrameWarp::kPerPixelDepth, kNodeImages) and
// its reports therefore carry hole pixels; every policy on a fixed cadence reports them too (0 for
// the per-layer warps, which show every layer whole).
bool reports_holes(const ReusePolicy& policy);

// True when the policy plays scenes only: the hierarchical cache (a single plane has no BSP
// tree to group), motion-vector extrapolation (core/scene/frame_generation.h works on a
// scene's rendered frame and depth) and view interpolation (the same, and the views to come
// of a viewer script) and the depth mesh (its near and far parts are a scene's polygons). `why`
// receives the reason, for one-line refusals.
bool needs_scene(const ReusePolicy& policy, std::string* why = nullptr);

// What `policy` did to a layer it showed at `level`, in that policy's own words, for captions
// and legends: Algorithm 1's level names ("none" .. "rerender", level_name) for the policies
// of the threshold rule; "rendered" or "generated" for motion-vector extrapolation;
// "rendered" or "interpolated" for view interpolation; "rendered" or "meshed" for the depth mesh;
// "rendered" or "reprojected" for the other policies on a fixed cadence (its warp
// level is a reprojection of the last render, not a Taylor level); "rendered" or "cached" for
// the hierarchical cache (a node's cached image warped onto its quad). Never null.
const char* level_word(const ReusePolicy& policy, Level level);

// Every policy, in the order help texts and the GUI list them (perspective first). The
// entries live as long as the program; pointers to them may be kept and compared.
const std::vector<ReusePolicy>& reuse_policies();

// The policy called `name`, or nullptr when there is none.
const ReusePolicy* find_reuse_policy(const std::string& name);

// The policy called `name`; throws std::invalid_argument naming it and the known policies
// when there is none. For names written in code; parse user input with find_reuse_policy.
const ReusePolicy& reuse_policy(const std::string& name);

// "perspective": the policy of a default EngineSettings.
const ReusePolicy& default_reuse_policy();

// The policy names in registry order, joined by `separator`: "perspective, affine, exact,
// rerender" for error messages ("one of ..."), or "perspective|affine|..." for usage lines.
std::string reuse_policy_names(const std::string& separator = ", ");

}  // namespace oflab
