// Image comparisons for the GUI tests.
//
// Tolerance: screenshots are compared by PSNR on 8-bit RGB after both images are scaled
// (smoothly) to the baseline's size, which is a quarter of the view's width or less.
// PSNR = 10 log10(255^2 / MSE) over all channels; 30 dB is an RMS error of 8 grey levels,
// which absorbs anti-aliasing and font-hinting differences between Mesa builds but not a
// lost arrow field (a flow view without its arrows scores below 25 dB; a test checks it).
#pragma once

#include <QImage>
#include <QString>

#include "adapters/frame_images.h"

namespace oflab::test {

constexpr double kBaselinePsnrDb = 30.0;

// Agreement of two exact renderings of one frame by different rasterisers (core's warp, VTK's
// OpenGL): alpha masks overlap with IoU >= kExactAgreementIou (edges may differ by a pixel)
// and, over the pixels both cover, PSNR >= kExactAgreementPsnrDb (texel choices at
// pixel-centre ties differ, which on the high-contrast butterfly costs a few dB, while a
// wrong camera, mirrored texture or shifted plane scores far below: a one-pixel shift of
// the whole frame scores under 14 dB).
constexpr double kExactAgreementIou = 0.95;
constexpr double kExactAgreementPsnrDb = 18.0;

// PSNR in dB of b against a (same size, RGB); infinity when they are equal.
double psnr_db(const QImage& a, const QImage& b);

// The image scaled smoothly to `size`, as RGB32.
QImage scaled_rgb(const QImage& image, const QSize& size);

// Number of distinct RGB colours (a rendered view has many; a blank one has one or two).
int distinct_colours(const QImage& image);

// Fraction of pixels that differ by more than `threshold` in any channel (same size).
double changed_fraction(const QImage& a, const QImage& b, int threshold = 8);

// Directory for images written by failing tests (created on demand).
QString output_dir();

// Compares `rendered` with baselines/<name>.png (tests/gui/baselines) at the baseline's size
// with kBaselinePsnrDb, failing the test below it or when the baseline is missing; either way
// writes the rendered image, scaled, to output_dir() as NAME-actual.png. With
// OFLAB_UPDATE_BASELINES set, rewrites the baseline `width` pixels wide instead and reports
// the test as skipped, never as passed.
void expect_matches_baseline(const QImage& rendered, const QString& name, int width);

// frame_agreement (gui/adapters/frame_images.h) of two camera frames. When the IoU is
// below `min_iou` or the PSNR below `min_psnr_db`, writes both, flattened over black, to
// output_dir() as NAME-LABEL_A.png and NAME-LABEL_B.png, so a failing test leaves them.
FrameAgreement agreement_writing_failures(const Image& a, const Image& b, double min_iou,
                                          double min_psnr_db, const QString& name,
                                          const QString& label_a, const QString& label_b);

}  // namespace oflab::test
