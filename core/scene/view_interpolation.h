// View interpolation: the `view-interpolation` policy of core/engine/reuse_policy.h
// (manual/policies.md "View interpolation").
//
// What it models. Chen and Williams, "View interpolation for image synthesis", SIGGRAPH 93:
// images rendered with their depth at a few viewpoints, and the views in between made from the
// two nearest renders, each pixel moved by its depth ("morph maps"), both images mapped and
// merged so that the nearer surface wins where both put a pixel, and what neither image saw
// left as a hole.
// This is oflab's own clean-room version, written from the publication: each render is
// forward-warped to the viewer of the in-between frame by its per-pixel depth with the true
// step (reproject_by_depth, core/scene/depth_reprojection.h: footprints splatted as in
// core/scene/splat_footprint.h). Chen and Williams interpolate each pixel's offset linearly
// between the two views instead, which is the same map when the camera moves parallel to the
// image plane and its first-order form otherwise; with the poses known, oflab warps exactly.
// The holes are counted and left empty (transparent), never filled silently.
//
// Merge. A pixel reached by one warped render takes its colour. A pixel reached by both takes
// the one whose surface is nearer at the pixel centre now: each polygon's plane moved to the
// viewer now (m' = R m / (1 + (R m).t) for the step x' = R x + t, since m.x = 1) gives its
// inverse depth there, m'.(x/f, y/f, 1), the background's being 0. When both show the same
// polygon, the render nearer in time wins (its splats are the less stretched), the earlier
// on a tie.
//
// Latency. The in-between frames need the later render: on a cadence of N frames, the frame
// just after a render waits N - 1 frames for the next (latency_frames, reuse_policy.h).
//
// Error (a diagnostic). As for depth reprojection: over the pixels showing a surface, the
// distance between the pixel centre and the exact projection now of the surface point at its
// source pixel's centre, pixels.
#pragma once

#include <cstdint>
#include <vector>

#include "flow/camera.h"
#include "flow/reprojection.h"
#include "image/image.h"
#include "scene/depth_reprojection.h"

namespace oflab {

// One render the in-between frame is made from: its frame (camera-sized, premultiplied), its
// depth (render_depth) and the rigid step from its viewer frame to the viewer now
// (viewer_step(render's view, view now)).
struct RenderedView {
  const Image& image;
  const DepthFrame& depth;
  RigidStep3 step;
};

struct InterpolatedFrame {
  Image image;                   // camera-sized, premultiplied; holes transparent
  std::vector<char> unreached;   // per pixel: 1 where neither warped render reached
  std::vector<char> from_later;  // per pixel: 1 where the pixel came from the later render
  std::vector<int> source;       // per pixel: the source pixel shown (in its render), -1: none
  // Unreached pixels where the view now shows a surface (with `now`; else every unreached
  // pixel), and those each single warped render leaves unreached there.
  std::int64_t hole_pixels = 0;
  std::int64_t earlier_hole_pixels = 0;
  std::int64_t later_hole_pixels = 0;
  std::int64_t pixels_written = 0;  // pixel writes of both renders' splats
  std::int64_t source_pixels = 0;   // source pixels warped (both renders' pixels)
  double max_error_px = 0.0;        // per-pixel error over the pixels showing a surface
  double mean_error_px = 0.0;
};

// The inverse depth 1/Z (world units^-1) at top-left pixel position (u, v) of the plane of
// plane vector m (core/flow/reprojection.h, m.x = 1 on the plane) moved by `step`; 0 for the
// background (m = 0) and for a plane through or behind the eye after the step.
double moved_plane_inverse_depth(const Camera& camera, const Vec3& m, const RigidStep3& step,
                                 double u, double v);

// The frame `t` of the way (0 <= t <= 1) from the earlier render to the later one, made from
// both (see above). `now`, when given, is the depth of the view now (render_depth): an
// unreached pixel is a hole where it shows a surface; without it every unreached pixel
// counts. Preconditions: both images and depths, and now, have the camera's size; each
// depth's planes cover every polygon index in its polygon. Footprints reaching Z <= near are
// dropped.
InterpolatedFrame interpolate_views(const RenderedView& earlier, const RenderedView& later,
                                    double t, const Camera& camera, double near,
                                    const DepthFrame* now = nullptr);

}  // namespace oflab
