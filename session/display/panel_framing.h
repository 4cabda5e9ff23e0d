// How the animation view frames its panels (session/state/window_state.h PanelFraming), for
// every front-end: the image bounds of a source's frames, their union around the frame shown,
// the part of the camera image every panel shows, and the exact outlines of what is animated.
// The desktop (gui/views/panel_layout.h, in Qt's rectangles) and the page (web/) call these,
// so both frame the same part of the same frame.
//
// Units: camera pixels (top-left origin of the camera image).
#pragma once

#include <optional>
#include <vector>

#include "engine/animator.h"
#include "engine/script.h"
#include "image/polygon.h"
#include "scene/viewer_script.h"

namespace oflab {

// Per frame of a source, in frame order: the bounding box of what is seen, or none.
using FrameBounds = std::vector<std::optional<BoundingBox>>;

// The bounding box of the plane's part inside the image (plane_image_polygon with `near`) at
// each frame of `script`; none where the plane is not seen.
FrameBounds script_frame_bounds(const MotionScript& script, double near);

// The bounding box of the exact outlines (exact_outlines below) of `scene`'s polygons at each
// frame of the viewer script `walk`, seen with its camera; none where no polygon is seen.
FrameBounds scene_frame_bounds(const Scene& scene, const ViewerScript& walk, double near);

// The union of bounds[k] over the frames k in [frame - reach, frame + reach] that exist (all
// of them when reach < 0): what zoom-to-fit frames, over the whole loop or around one frame.
// None when none of those frames sees anything. Precondition: reach is -1 or >= 0.
std::optional<BoundingBox> bounds_around(const FrameBounds& bounds, int frame, int reach);

// What the panels frame (session/state/window_state.h PanelFraming): the bounds over the
// whole loop, or with `around_frame` those of the frames around `frame` (kFramingFrames
// either side) where they see anything. None when nothing is ever seen.
std::optional<BoundingBox> framed_content(const FrameBounds& bounds, int frame, bool around_frame);

// Fraction of the content's size added on every side when fitting it.
constexpr double kFitMargin = 0.02;

// The part of the camera image every panel shows: `content` grown by kFitMargin of its size
// on every side, widened or heightened about its centre to `aspect` (width / height of the
// panels' image areas), then shrunk about its centre by `zoom` (1 = fit, 2 = twice as large).
// No content frames the camera image (camera_width x camera_height) whole.
// Preconditions: camera sizes > 0, aspect > 0, zoom > 0.
BoundingBox panel_frame(const std::optional<BoundingBox>& content, double camera_width,
                        double camera_height, double aspect, double zoom);

// The aspect (width over height) of the panels' frame: that of `content`, so that each panel
// hugs what it frames in its cell (a tall band of squares in a wide cell leaves no empty
// sides), held within kHugAspect of a square; the cell's own (`cell_aspect`) when nothing is
// framed or the panels are zoomed in (a zoom then uses the whole cell).
constexpr double kHugAspect = 4.0;
double hugging_aspect(double cell_aspect, const std::optional<BoundingBox>& content, double zoom);

// The share (0..1) of `shown` (a part of the camera image, non-empty) covered by the union
// of the convex `outlines` (camera pixels): over a grid of kFillGrid cells across `shown`
// (and as many down as its aspect gives, at least 1), the cells whose centres lie inside an
// outline (core's scan conversion), over all cells. What the panel_fill claim measures of the
// animation view's exact panel, on the desktop and on the page.
constexpr int kFillGrid = 400;
double outline_fill(const std::vector<std::vector<Vec2>>& outlines, const BoundingBox& shown);

// The exact image outlines (camera pixels) of the polygons of `scene` seen from `view` with
// `camera`: each polygon's outline clipped to the near plane `near` and the image border,
// skipping edge-on polygons, back-facing one-sided ones (a two-sided sheet, the plane of the
// plane and script sources, is outlined from behind too, as the engines draw it) and those
// wholly outside the picture.
std::vector<std::vector<Vec2>> exact_outlines(const Scene& scene, const ViewerPose& view,
                                              const Camera& camera, double near);

}  // namespace oflab
