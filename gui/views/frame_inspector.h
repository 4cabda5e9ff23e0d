// The words of the animation view's frame inspector and cursor readout: why the engine
// chose this frame's level (core/engine/decision.h's rule, with the numbers it compared) and what
// is under the cursor. Qt strings over core values; no widgets.
#pragma once

#include <QString>

#include "engine/animator.h"

namespace oflab {

class AnimationModel;

// Rich text. A frame that updated exactly one layer (a single plane, or a scene with one
// animated polygon): what the frame shows (a re-render is the policy's initial view, the
// exact projection or its affine part of section 6.5, with the measured distance to the
// exact projection; "exact" only when that distance is below kExactTolerancePx), the
// chosen level and, for each cheaper level, the error it would have left (sum over its
// neglected terms of carried estimate + this frame's flow, core/engine/decision.h)
// against its threshold; the flow measures; the estimates carried on. A plane that is not
// visible: that, and why. Any other frame (several layers, or scene shifting's slices,
// which keep no per-term books): the layers per level, the culled and hidden counts and
// the measured error.
QString explain_frame(const AnimationFrame& frame, const EngineSettings& settings);

// Measured corner distances below this many pixels are called exact (rounding of the
// warps and of the corner test).
constexpr double kExactTolerancePx = 0.01;

// Plain text: what a single layer's frame shows and how far it is from the exact
// projection, e.g. "re-rendered as the affine initial view of section 6.5 (the affine
// part of the exact warp about the texture centre): 6.20 px off the exact projection".
// Precondition: report.visible.
QString describe_shown_view(const FrameReport& report, const ReusePolicy& policy);

// Empty when the model's source follows the scene panel (its plane and motion); otherwise
// what the animation and analysis views play instead, for the scene panel's note.
QString scene_panel_note(const AnimationModel& model);

// Why nothing of `frame` is on screen, empty when a layer is drawn: the note of a layer
// that is not visible (e.g. "not visible: a corner is at or behind the eye"), "outside the
// image" when every layer was culled outside the view, "seen from behind or edge-on" when
// they were culled as back-facing.
QString not_drawn_reason(const AnimationFrame& frame);

// One line about image pixel `pixel` (top-left pixels) of the animator's current frame: the
// position of that pixel's centre in centred pixels (the principal point at (0, 0), Y down,
// as the flow view and the coefficients use), the level of the topmost drawn layer there
// (none when no outline holds it), and the engine's and the exact colour there
// (premultiplied RGBA). Empty outside the frame.
QString pixel_readout(const Animator& animator, const Vec2& pixel, const Image& exact);

}  // namespace oflab
