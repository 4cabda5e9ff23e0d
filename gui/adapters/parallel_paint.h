// Painting parts of one canvas image on core's worker threads (core/image/thread_pool.h).
// Qt's raster engine paints antialiased wide lines and filled paths on the calling thread
// only; a canvas cut into windows that do not overlap is painted by several threads at once,
// each with its own painter on a QImage over its window of the canvas's memory.
//
// Same pixels: each window's painter is moved by the window's whole-pixel corner, so a
// painting's coordinates are the canvas's and its pixels those painted on the canvas itself
// (tests/gui/views/animation_layout_test.cpp, flow_renderer_test.cpp). No text: fonts belong
// to the window's thread (paint texts after, on `painter`).
#pragma once

#include <QImage>
#include <QPainter>
#include <QRect>
#include <functional>
#include <vector>

namespace oflab {

// Paints `paint(window_painter, k)` for every window k of `windows` (canvas pixels; they must
// not overlap; each is clipped to the canvas) on the worker threads, and returns true; the
// window painters start untransformed in canvas coordinates, clipped to their window. Returns
// false, painting nothing, when `painter` is not painting an RGB32 QImage untransformed (a
// recording device, say) or two windows overlap: the caller then paints on `painter` itself.
// `paint` must not paint text and must be safe to run on several threads at once for different k.
bool paint_in_windows(QPainter& painter, const std::vector<QRect>& windows,
                      const std::function<void(QPainter&, int)>& paint);
// The same, each window painter clipped to `clip` (canvas pixels) as `painter` would be by
// setClipRect(clip) before any transform (Qt rounds such a clip as a device rectangle; set
// under the windows' moves it would be rasterised as a path, with other edge pixels).
bool paint_in_windows(QPainter& painter, const std::vector<QRect>& windows, const QRectF& clip,
                      const std::function<void(QPainter&, int)>& paint);

// The same on `image` itself (RGB32, ARGB32 or ARGB32 premultiplied; `image` detached and
// not being painted), without a clip: false, painting nothing, for another format or
// overlapping windows.
bool paint_image_in_windows(QImage& image, const std::vector<QRect>& windows,
                            const std::function<void(QPainter&, int)>& paint);

// `rect` (canvas pixels) cut into `count` (>= 1) strips of rows of nearly equal height, top to
// bottom; fewer when it has fewer rows.
std::vector<QRect> row_strips(const QRect& rect, int count);

}  // namespace oflab
