// Per-pixel depth reprojection (post-rendering 3D warping, Mark, McMillan and Bishop 97) and
// the automatic stabilization plane: the `depth-reprojection` and `stabilized-plane` policies
// of core/engine/reuse_policy.h (manual/policies.md "Today's reprojection").
//
// Depth. A rendered frame keeps, per pixel, the inverse depth w = 1/Z (viewer frame, world
// units^-1) of the surface at the pixel centre and which polygon it is; pixels showing no
// polygon are the background at infinity (w = 0), which moves as timewarp moves it (the
// plane at infinity). The slope of each surface is its polygon's plane (as a renderer's
// normal buffer gives it), so a pixel's square footprint is carried to the new view exactly.
//
// Forward warp, by splatting. Every source pixel is moved by its own depth: its footprint
// (the pixel square on its surface, grown by kSplatMargin on every side) is projected into
// the new view and every pixel centre inside it takes the source pixel's colour: the nearest
// surface wins (a z-test on the new inverse depth), and among the splats of one polygon the
// one whose centre lands nearest (so the result is nearest-neighbour resampling). Footprints
// of one surface overlap, so magnification leaves no cracks, and the margin reaches the
// polygon's edge, which a pixel-centre rule leaves up to half a pixel short. A pixel no
// footprint reaches is unreached; it is a hole when the view now shows a surface there (a
// disocclusion, or a part of the view outside the rendered frame); revealed empty
// background is not one. Holes are marked and counted, and filled only by an explicit
// HoleFill, which paints the unreached pixels (all the warp itself can know).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "flow/camera.h"
#include "flow/reprojection.h"
#include "image/image.h"
#include "scene/scene.h"
#include "scene/viewer_script.h"

namespace oflab {

// The depth of a frame: per pixel (row-major) the inverse depth and the polygon seen at the
// pixel centre (-1: background, w = 0), and each polygon's plane vector (core/flow/
// reprojection.h) in the frame's viewer frame.
struct DepthFrame {
  int width = 0;
  int height = 0;
  std::vector<double> inverse_depth;  // 1/Z, world units^-1; 0 for the background
  std::vector<int> polygon;           // scene polygon index, -1 for the background
  std::vector<Vec3> planes;           // per scene polygon, meaningful where it is seen
  int covered() const;                // pixels showing a polygon
};

// The depth of `scene` seen from `view` with `camera`: each front-facing polygon clipped to
// the view frustum (near plane Z = near > 0) and scan-converted (pixel-centre rule of
// core/image/scan_conversion.h), nearest surface kept. Geometry only: texels of any alpha
// count as surface. `only`, when given (one entry per polygon), keeps the polygons whose entry is
// non-zero (the depth mesh's near part), the others are left out.
DepthFrame render_depth(const Scene& scene, const Camera& camera, const ViewerPose& view,
                        double near, const std::vector<char>* only = nullptr);

// The rigid step (core/flow/reprojection.h) from the viewer frame of `from` to that of `to`:
// R = Q_to Q_from^T, t = s_to - R s_from.
RigidStep3 viewer_step(const ViewerPose& from, const ViewerPose& to);

// The automatic stabilization plane: the plane vector m minimising
// sum over covered pixels (1/Z - m.(x/f, y/f, 1))^2, x, y the centred pixel centre, i.e. the
// least-squares fit of inverse depth, affine in the image, over the visible surfaces (each
// visible pixel weighs the same). Inverse depth is what a plane's homography gets wrong in
// proportion to (the parallax of a translation t is |t| times the error in 1/Z), so this is
// the plane of least parallax for a small translation. Exact for a single visible plane.
// Returns false (m untouched) when fewer than 3 pixels are covered or the fit is singular.
bool fit_inverse_depth_plane(const DepthFrame& depth, const Camera& camera, Vec3& m);

// What fills the holes of a reprojected frame (the hole mask and count are kept in every
// mode): none (transparent), stretch (each hole pixel takes the farther of the nearest
// reached pixels left and right of it on its row: disocclusions reveal what lies behind),
// background (an opaque mid grey).
enum class HoleFill { kNone, kStretch, kBackground };
constexpr int kHoleFillCount = 3;
const char* hole_fill_name(HoleFill fill);
// The fill called `name`; false when there is none.
bool parse_hole_fill(const std::string& name, HoleFill& fill);
// "none, stretch, background" (joined by `separator`).
std::string hole_fill_name_list(const std::string& separator = ", ");

// Source pixels of margin each splat footprint is grown by on every side (see above): a
// silhouette may therefore overshoot by up to this much, magnified.
constexpr double kSplatMargin = 0.5;

// The colour HoleFill::kBackground paints.
constexpr Pixel kHoleBackground{128, 128, 128, 255};

struct Reprojection {
  Image image;                  // camera-sized, premultiplied
  std::vector<char> unreached;  // per pixel: 1 where no footprint reached
  std::vector<char> hole;       // per pixel: 1 for a hole (unreached, a surface seen now)
  std::vector<int> source;      // per pixel: the source pixel index shown, -1 for none
  std::int64_t hole_pixels = 0;
  std::int64_t pixels_written = 0;  // pixel writes of the splats (a pixel may be written twice)
  std::int64_t source_pixels = 0;   // source pixels warped (every pixel of the frame)
  // Per-pixel displacement error over the pixels showing a surface: the distance between
  // the pixel centre and the exact projection now of the source pixel centre's surface point
  // (its depth, moved by the step), pixels.
  double max_error_px = 0.0;
  double mean_error_px = 0.0;
};

// Forward-warps `rendered` (camera-sized, with its `depth`) from the view it was rendered in
// to the view after `step` (viewer_step). `now`, when given, is the depth of the view after
// the step (render_depth): an unreached pixel is a hole where it shows a surface; without
// it every unreached pixel counts. Preconditions: rendered, depth and now have the camera's
// size; depth.planes covers every polygon index in depth.polygon. Footprints reaching
// Z <= near are dropped (their pixels stay unreached).
Reprojection reproject_by_depth(const Image& rendered, const DepthFrame& depth,
                                const Camera& camera, const RigidStep3& step, HoleFill fill,
                                double near, const DepthFrame* now = nullptr);

}  // namespace oflab
