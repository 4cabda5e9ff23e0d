// The exact image of a textured plane (dissertation section 5.6.1's re-render): the texture
// warped by the exact texel -> image homography of its pose, whole (render_exact) or, for a
// plane reaching in front of the near plane or beyond the guard band, only its part clipped to
// the view frustum (render_clipped, render_clipped_content, render_clipped_piece). The plane
// engine (core/engine/engine.h) re-renders with these; the scene renderers (core/scene/) draw
// their clipped polygons with render_clipped_piece.
//
// Frames: texel coordinates (core/flow/plane.h) to top-left image pixels (core/flow/
// camera.h); a PlacedLayer's offset is its top-left pixel in the image.
#pragma once

#include <cstdint>
#include <string>

#include "content/layer_content.h"
#include "flow/camera.h"
#include "flow/plane.h"
#include "image/layer.h"
#include "image/polygon.h"
#include "image/warp.h"
#include "scene/view_culling.h"

namespace oflab {

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

// The exact image of `clipped`, the part of the plane's rectangle kept by clip_to_frustum
// (viewer frame, uv normalised texture coordinates of `texture`'s image), whatever lies
// behind the eye: one perspective warp of the clipped texture polygon with a depth-signed
// homography. `pose` gives the plane (its texture_size is taken from the texture). The
// texture's polygon is replaced by the clipped one during the call and restored after.
// Throws std::invalid_argument when the warp refuses (a sliver beyond its fixed-point
// range). Precondition: clipped is not empty and lies at Z > 0.
PlacedLayer render_clipped(const Camera& camera, Layer& texture, const PlanePose& pose,
                           const ViewPolygon& clipped, Sampling sampling,
                           WarpStats* stats = nullptr);

// The exact image of the clipped part of a plane (as render_clipped) drawn from a lit content:
// texels inside `texels` (the valid region, texels of pose.texture_size) where the view
// meets the plane in front of the eye. `stats` if non-null receives the render's counts.
// `memory` if non-null is an image whose memory the layer takes (a layer of the last frame:
// no allocation when it is large enough); it is left empty. Preconditions: content lit
// (content_is_lit), clipped not empty and at Z > 0.
PlacedLayer render_clipped_content(const Camera& camera, const LayerContent& content,
                                   const PlanePose& pose, const ConvexPolygon& texels,
                                   const ViewPolygon& clipped, ContentStats* stats = nullptr,
                                   Image* memory = nullptr);

// The exact image of a clipped part of a plane from whatever `content` draws: a texture by
// render_clipped (of `texture`, whose valid polygon is `texels` in texels of the texture),
// a lit content by render_clipped_content. Adds the pixels written to *pixels_written and
// the work in the cost model (a texture's pixels at kPerspectiveWarpCost, a lit content's
// work units at content_unit_cost) to *model_work. Throws std::invalid_argument as
// render_clipped. `memory` as render_clipped_content's (a lit content's layer only; a
// texture's warp leaves it as it is). Preconditions as render_clipped's.
PlacedLayer render_clipped_piece(const Camera& camera, const LayerContent& content, Layer& texture,
                                 const PlanePose& pose, const ConvexPolygon& texels,
                                 const ViewPolygon& clipped, Sampling sampling,
                                 std::int64_t* pixels_written, double* model_work,
                                 Image* memory = nullptr);

}  // namespace oflab
