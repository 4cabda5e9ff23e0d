// The geometry of the animation view's panels, painted onto a canvas of the view's own size:
// rows of equal cells, each with a title band above its image and a caption band below (so
// titles, numbers and legends never cover the frame), one shared framing of the camera
// image for every panel (zoom to fit the plane over its loop, or over the frames around the
// one shown, times the teacher's zoom), and the exact outlines of what is animated, drawn on
// every panel.
//
// Units: camera pixels (top-left origin of the camera image) for frames and outlines,
// canvas pixels for cells.
#pragma once

#include <QFontMetrics>
#include <QRectF>
#include <QStringList>
#include <QTransform>
#include <vector>

#include "engine/animator.h"
#include "engine/script.h"
#include "scene/viewer_script.h"

namespace oflab {

// One panel on the canvas.
struct PanelCell {
  QRectF title;    // band above the image: which panel this is
  QRectF image;    // the framed camera image
  QRectF caption;  // band below the image: its numbers
};

// `columns` equal cells side by side filling `row`, `gap` pixels apart, each with a title band
// `title_px` and a caption band `caption_px` high. Precondition: columns >= 1.
std::vector<PanelCell> panel_row(const QRectF& row, int columns, double gap, double title_px,
                                 double caption_px);

// `text` broken into lines no wider than `width` canvas pixels in `metrics`: at " · " first,
// then before " (", then after ", " (the separators of the panels' captions), each break as
// far right as fits. A piece with no separator that fits stays whole (the painter elides
// it). Never drops or reorders characters other than the separators' spaces and the dot.
QStringList wrapped_caption(const QString& text, const QFontMetrics& metrics, double width);

// The share (0..1) of `picture` inside the convex hull of `points` (same units, e.g. canvas
// pixels): how much of a view what it draws covers. 0 for fewer than three points or an
// empty picture.
double hull_share(const std::vector<QPointF>& points, const QRectF& picture);

// Fraction of the content's size added on every side when fitting it.
constexpr double kFitMargin = 0.02;

// The part of the camera image (camera pixels) every panel shows: `content` grown by
// kFitMargin of its size on every side, widened or heightened about its centre to `aspect`
// (width / height of the panels' image areas), then shrunk about its centre by `zoom`
// (1 = fit, 2 = twice as large). An empty content frames `camera_size` whole.
// Preconditions: aspect > 0, zoom > 0.
QRectF panel_frame(const QRectF& content, const QSizeF& camera_size, double aspect, double zoom);

// Maps camera pixels of `frame` onto canvas pixels of `target` (same aspect: a uniform
// scale and a shift).
QTransform frame_to_panel(const QRectF& frame, const QRectF& target);

// The bounding box (camera pixels) of the plane's part inside the image (plane_image_polygon
// with `near`) at each frame of `script`, in frame order; empty where the plane is not seen.
std::vector<QRectF> script_frame_bounds(const MotionScript& script, double near);

// The bounding box (camera pixels) of the exact outlines (exact_outlines below) of `scene`'s
// polygons at each frame of the viewer script `walk`, seen with its camera, in frame order;
// empty where no polygon is seen.
std::vector<QRectF> scene_frame_bounds(const Scene& scene, const ViewerScript& walk, double near);

// The union of `bounds[k]` over frames k in [frame - reach, frame + reach] that exist (all of
// them when reach < 0): what zoom-to-fit frames, over the whole loop or around one frame.
// Empty when none of those frames sees anything. Precondition: reach is -1 or >= 0.
QRectF bounds_around(const std::vector<QRectF>& bounds, int frame, int reach);

// script_frame_bounds and scene_frame_bounds over every frame: what zoom-to-fit frames over
// the whole loop. Empty when the plane (every polygon) is never seen.
QRectF script_image_bounds(const MotionScript& script, double near);
QRectF scene_image_bounds(const Scene& scene, const ViewerScript& walk, double near);

// The exact image outlines (camera pixels) of the polygons of `scene` seen from `view` with
// `camera`: each polygon's outline clipped to the near plane `near` and the image border,
// skipping edge-on polygons, back-facing one-sided ones (a two-sided sheet, the plane of the
// plane and script sources, is outlined from behind too, as the engines draw it) and those
// wholly outside the picture.
std::vector<std::vector<Vec2>> exact_outlines(const Scene& scene, const ViewerPose& view,
                                              const Camera& camera, double near);

}  // namespace oflab
