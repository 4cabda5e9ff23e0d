// The pictures of the animation view, painted with Qt from core images: polygon outlines in
// their levels' colours and a legend of the levels, the difference of two frames as a heat
// map with its colour bar, and the comparison figures the tests use.
// Images are camera-sized; pixel (x, y) of a core Image is pixel (x, y) of the QImage.
#pragma once

#include <QColor>
#include <QImage>
#include <QPainter>
#include <QString>
#include <QTransform>
#include <vector>

#include "engine/animator.h"
#include "image/image.h"

namespace oflab {

// Any QImage as a premultiplied RGBA8 core image of the same size (the inverse of wrapping a
// core image: rows are Format_RGBA8888_Premultiplied).
Image image_from_qimage(const QImage& qimage);

// A QImage sharing the pixels of a premultiplied core image (Format_RGBA8888_Premultiplied,
// no copy): valid while `image` lives and is neither written nor reshaped.
QImage image_view(const Image& image);

// A premultiplied core image as an opaque QImage over `background`.
QImage flatten_image(const Image& image, const QColor& background);

// Draws each outline (image pixels mapped by `to_view` onto the painter) in its level's
// Okabe-Ito colour, `line_width` painter pixels wide.
void draw_level_outlines(QPainter& painter, const std::vector<LayerOutline>& outlines,
                         const QTransform& to_view, double line_width);

// A legend of the five levels inside `area`: a swatch of each level's colour and its name,
// in `text` at `text_px` pixels, in one row when it fits and in more rows when not.
void draw_level_legend(QPainter& painter, const QRectF& area, const QColor& text, int text_px);

// Per-pixel difference of two same-sized premultiplied images: the largest absolute
// channel difference (RGB and alpha, 0..255) coloured by the viridis map over
// [0, full_scale]. Precondition: a and b have the same size; full_scale > 0.
QImage difference_map(const Image& a, const Image& b, int full_scale);
// The same into `out` (Format_RGB32), reusing its pixels when it has a's size already and
// is not shared, so a view drawing a heat map every frame allocates nothing.
void difference_map_into(const Image& a, const Image& b, int full_scale, QImage& out);

// The colour bar of difference_map inside `area`: the viridis ramp from 0 (left) to
// full_scale (right), five ticks labelled in grey levels ("128+" at the top; every other one
// when five labels would come closer than a text size) and a caption (on two lines when one
// is wider than the area), in `text` at `text_px` pixels.
// difference_bar_height: the height (pixels) the bar needs at `width` pixels wide.
void draw_difference_bar(QPainter& painter, const QRectF& area, int full_scale, const QColor& text,
                         int text_px);
double difference_bar_height(double width, int text_px);

// How far two frames agree: intersection over union of their alpha masks (alpha > 127),
// and PSNR (dB, RGB of the premultiplied colours) over the pixels where both are covered.
// IoU is 1 when both are empty; PSNR is infinite for equal images.
struct FrameAgreement {
  double mask_iou = 1.0;
  double psnr_db = 0.0;
};
FrameAgreement frame_agreement(const Image& a, const Image& b);

// difference_map_into(a, b, full_scale, out) and frame_agreement(a, b) in one pass over the
// two images (each row read once, in bands on core's worker threads): the same map and the
// same figures, what a heat map and its caption show. Preconditions as difference_map_into.
FrameAgreement difference_map_and_agreement(const Image& a, const Image& b, int full_scale,
                                            QImage& out);

}  // namespace oflab
