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
#include <optional>
#include <vector>

#include "display/panel_framing.h"
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

// The framing rule itself (content bounds, margin, aspect, zoom, the exact outlines) is the
// teaching layer's (session/display/panel_framing.h), shared with the page; below, what the
// window needs of it in Qt's rectangles.

// `box` as a rectangle; a null rectangle for none.
QRectF frame_rect(const std::optional<BoundingBox>& box);
// `rect` as a box; none for an empty rectangle.
std::optional<BoundingBox> frame_box(const QRectF& rect);

// panel_frame (panel_framing.h) of `content` (none when empty).
QRectF panel_frame(const QRectF& content, const QSizeF& camera_size, double aspect, double zoom);

// Maps camera pixels of `frame` onto canvas pixels of `target` (same aspect: a uniform
// scale and a shift).
QTransform frame_to_panel(const QRectF& frame, const QRectF& target);

// script_frame_bounds and scene_frame_bounds over every frame: what zoom-to-fit frames over
// the whole loop. Empty when the plane (every polygon) is never seen.
QRectF script_image_bounds(const MotionScript& script, double near);
QRectF scene_image_bounds(const Scene& scene, const ViewerScript& walk, double near);

}  // namespace oflab
