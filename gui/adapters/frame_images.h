// The pictures of the animation view, painted with Qt from core images: the engine's frame
// with each polygon outlined in its level's colour and a legend, the exact frame, their
// difference as a heat map with a colour bar, and the comparison figures the tests use.
// Images are camera-sized; pixel (x, y) of a core Image is pixel (x, y) of the QImage.
#pragma once

#include <QColor>
#include <QImage>
#include <QString>
#include <vector>

#include "image/image.h"
#include "engine/animator.h"

namespace oflab {

// Any QImage as a premultiplied RGBA8 core image of the same size (the inverse of wrapping a
// core image: rows are Format_RGBA8888_Premultiplied).
Image image_from_qimage(const QImage& qimage);

// A premultiplied core image as an opaque QImage over `background`.
QImage flatten_image(const Image& image, const QColor& background);

// Draws each outline (image pixels) in its level's Okabe-Ito colour, `line_width` pixels
// wide, and a legend of the five levels with this frame's count of polygons per level in
// the top-left corner. `text` is the legend's text colour; `text_scale` multiplies the
// legend's text size (12 pixels or 1/32 of the image height, whichever is larger).
void draw_level_overlay(QImage& image, const std::vector<LayerOutline>& outlines,
                        const std::array<int, kLevelCount>& counts, const QColor& text,
                        double line_width, double text_scale = 1.0);

// Writes a title in the top-right corner (which panel this is), `text_scale` times 12
// pixels or 1/28 of the image height, whichever is larger.
void draw_panel_title(QImage& image, const QString& title, const QColor& text,
                      double text_scale = 1.0);

// Per-pixel difference of two same-sized premultiplied images: the largest absolute
// channel difference (RGB and alpha, 0..255) coloured by the viridis map over
// [0, full_scale], with a vertical colour bar labelled in grey levels on the right.
// Precondition: a and b have the same size; full_scale > 0.
QImage difference_heat_map(const Image& a, const Image& b, int full_scale, const QColor& text);

// How far two frames agree: intersection over union of their alpha masks (alpha > 127),
// and PSNR (dB, RGB of the premultiplied colours) over the pixels where both are covered.
// IoU is 1 when both are empty; PSNR is infinite for equal images.
struct FrameAgreement {
  double mask_iou = 1.0;
  double psnr_db = 0.0;
};
FrameAgreement frame_agreement(const Image& a, const Image& b);

}  // namespace oflab
