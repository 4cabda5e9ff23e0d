// Frame generation by extrapolation along per-pixel motion vectors: the `mv-extrapolation`
// and `mv-no-inpaint` policies of core/engine/reuse_policy.h
// (manual/policies.md "Frame generation by extrapolation").
//
// What it models. Engines render, beside each frame, its depth and its per-pixel motion
// vectors (where each pixel's surface point was in the frame before, as temporal
// anti-aliasing needs them). Frame generation (NVIDIA DLSS 3, AMD FSR 3, and on mobile
// extrapolation such as Mob-FGSR) makes frames that were not rendered from these buffers.
// This is oflab's own clean-room version of the extrapolating form, written from the
// published descriptions, not from any vendor's code: the generated frame k frames after a
// render is the render splatted forward along its motion vectors extrapolated linearly,
// q = p + k (p - p_prev), without knowing the viewer's new pose; what no splat reaches is a
// disocclusion, masked, and filled (with inpainting) by a pyramid of the valid pixels, as
// AMD's FidelityFX FSR 3 frame interpolation describes its disocclusion mask and inpainting
// pyramid (AMD FidelityFX SDK documentation, "Frame interpolation", 2023, MIT licence). The
// pyramid fill is push-pull (Gortler, Grzeszczuk, Szeliski and Cohen, "The Lumigraph",
// SIGGRAPH 96, section 3.4.2), core/image/push_pull.h.
//
// Splats. As in depth reprojection (core/scene/depth_reprojection.h) each source pixel's
// footprint (its pixel square grown by kSplatMargin, the corners on its polygon's plane) is
// moved, here along the extrapolated motion vectors of its corners, and the pixel centres
// inside it take its colour: the nearest extrapolated surface wins (z-test on the inverse
// depth extrapolated as the position is: w + k (w - w_prev)), and among one polygon's splats
// the one whose centre lands nearest. The background (no polygon) moves as directions, the
// plane at infinity.
//
// Disocclusion mask. The pixels no splat reaches, grown by one pixel (3 x 3): a silhouette's
// splats overshoot by up to the margin, so the ring around what no splat reaches is where the
// generated frame is least sure. Inpainting fills only the unreached pixels; the ring keeps
// its splats' colour.
//
// Error (a diagnostic: the generator never sees the new pose). With the true step from the
// render to the view now, the measured error of a pixel showing a surface is the distance
// between its centre and the exact projection now of its source pixel centre's surface point,
// as for depth reprojection: the error of extrapolating the motion plus the splat's
// resampling. Inpainted pixels show no surface point and have no position error; they are
// counted instead (holes, inpainted pixels).
#pragma once

#include <cstdint>
#include <vector>

#include "flow/camera.h"
#include "flow/reprojection.h"
#include "image/image.h"
#include "scene/depth_reprojection.h"

namespace oflab {

struct GeneratedFrame {
  Image image;                  // camera-sized, premultiplied
  std::vector<char> unreached;  // per pixel: 1 where no splat reached
  std::vector<char> mask;       // per pixel: the disocclusion mask (unreached grown by 1 px)
  std::vector<int> source;      // per pixel: the source pixel index shown, -1 for none
  // Unreached pixels where the view now shows a surface (with `now`; else every unreached
  // pixel), the pixels of the mask, and the unreached pixels inpainting filled.
  std::int64_t hole_pixels = 0;
  std::int64_t mask_pixels = 0;
  std::int64_t inpainted_pixels = 0;
  std::int64_t pixels_written = 0;  // pixel writes of the splats
  std::int64_t source_pixels = 0;   // source pixels moved (every pixel of the render)
  // Per-pixel displacement error against the true step (see above), pixels; 0 without it.
  double max_error_px = 0.0;
  double mean_error_px = 0.0;
};

// Where the surface point seen at top-left pixel position (u, v) of a render lands after
// `frames_ahead` more frames of linear extrapolation along its motion vector, and its
// extrapolated inverse depth. m is its polygon's plane vector in the render's viewer frame
// (core/flow/reprojection.h; m = 0: the background, moved as a direction) and `back` the rigid
// step from the render's viewer frame to the one before it (viewer_step(render, previous)):
// the motion vector is p - p_prev, p_prev the point's projection in the frame before. False
// when the point lies behind the eye in either frame, or its depth reaches Z <= near in the
// frame before or (extrapolated) after.
bool extrapolate_point(const Camera& camera, const RigidStep3& back, const Vec3& m, double u,
                       double v, int frames_ahead, double near, Vec2& moved, double& moved_w);

// Generates the frame `frames_ahead` (>= 1) frames after `rendered` (camera-sized, with its
// `depth`) by extrapolation along its motion vectors (`back`, see extrapolate_point); with
// `inpaint` the unreached pixels are filled by push-pull, else left transparent. hole_pixels
// counts every unreached pixel until measure_generated_frame says which show a surface.
// Runs in bands of rows on the worker threads (core/image/thread_pool.h): the frame and its
// figures are the same bytes on any number of threads as one pass over the source pixels in
// order would paint them. Preconditions: rendered and depth have the camera's size;
// depth.planes covers every polygon index in depth.polygon.
GeneratedFrame extrapolate_by_motion(const Image& rendered, const DepthFrame& depth,
                                     const Camera& camera, const RigidStep3& back, int frames_ahead,
                                     bool inpaint, double near);

// The diagnostics of a generated frame `g` of the render whose depth is `depth`: its
// per-pixel error against `truth`, the true step from the render to the view now, and its
// holes, the unreached pixels where `now` (the depth seen now, render_depth) shows a
// surface. Precondition: now has the size of depth.
void measure_generated_frame(const DepthFrame& depth, const Camera& camera, const RigidStep3& truth,
                             const DepthFrame& now, GeneratedFrame& g);

}  // namespace oflab
