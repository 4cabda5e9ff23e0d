// The words of the animation view's frame inspector and cursor readout: why the engine
// chose this frame's level (core/engine/decision.h's rule, with the numbers it compared) and what
// is under the cursor. Qt strings over core values; no widgets.
#pragma once

#include <QString>

#include "engine/animator.h"

namespace oflab {

// Rich text. A frame that updated exactly one layer (a single plane, or a scene with one
// animated polygon): the chosen level and, for each cheaper level, the error it would have
// left (sum over its neglected terms of carried estimate + this frame's flow,
// core/engine/decision.h) against its threshold; the flow measures; the estimates carried on.
// Any other frame (several layers, or scene shifting's slices, which keep no per-term
// books): the layers per level, the culled and hidden counts and the measured error.
QString explain_frame(const AnimationFrame& frame, const EngineSettings& settings);

// One line about image pixel `pixel` (top-left pixels) of the animator's current frame: the
// level of the topmost drawn layer there (none when no outline holds it), and the engine's
// and the exact colour there (premultiplied RGBA).
QString pixel_readout(const Animator& animator, const Vec2& pixel, const Image& exact);

}  // namespace oflab
