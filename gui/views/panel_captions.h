// The caption lines under the animation view's panels (gui/views/animation_view.h): what an
// engine's frame drew, how far it is off and what it cost, and how closely a shown frame
// agrees with the exact one. Short enough for a projector's panel: pixel counts as "202 k"
// or "8.4 M", errors in pixels to two decimals. Qt strings over core values; no widgets.
#pragma once

#include <QString>
#include <QStringList>

#include "adapters/frame_images.h"
#include "engine/animator.h"
#include "engine/engine.h"
#include "engine/reuse_policy.h"
#include "image/image.h"

namespace oflab {

// Under a policy whose initial view is the affine part of the exact warp (section 6.5), the
// measured error has two parts: the affine view's own (its missing perspective, which no
// update removes) and what reuse adds against that view, each the largest over the frame's
// visible layers, in pixels. Empty for other policies and when no layer was drawn.
QString affine_view_line(const AnimationFrame& frame, const ReusePolicy& policy);

// The caption lines of an engine panel: the levels of this frame and its largest measured
// error (pixels), the affine view's part of it (affine_view_line), the plane a
// stabilized-plane policy warps by (from `settings`), then the pixels written and the time of
// this frame and of the run so far (`run_pixels` pixels, `run_ms` milliseconds), and under a
// visible-only warp (settings.warp_area) the pixels of them the warps computed, of this frame
// and of the run so far (`run_warped` pixels).
QStringList run_caption(const AnimationFrame& frame, const ReusePolicy& policy,
                        const EngineSettings& settings, double run_pixels, double run_ms,
                        double run_warped = 0.0);

// Under a heat map of a frame whose largest measured error (the corners' distance from their
// exact projection) is within a pixel: what its lit edges are, so they are not read as that
// error ("lit edges: sub-pixel shifts, resampling"); empty when the error is larger
// (then the map shows it) or nothing was drawn.
QStringList sub_pixel_note(const AnimationFrame& frame);

// The caption of a difference heat map of `shown` against `exact` (same size): the IoU of
// their coverage masks and the PSNR in dB ("equal" when they are identical).
QStringList agreement_caption(const Image& shown, const Image& exact);
// The same of figures already measured (difference_map_and_agreement).
QStringList agreement_caption(const FrameAgreement& agreement);

}  // namespace oflab
