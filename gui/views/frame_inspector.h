// The words of the animation view's frame inspector and cursor readout: why the engine
// chose this frame's level (core/engine/decision.h's rule, with the numbers it compared) and what
// is under the cursor. Qt strings over core values; no widgets.
#pragma once

#include <QString>

#include "models/animation_session.h"

namespace oflab {

// Rich text: the chosen level and, for each cheaper level, the error it would have left
// (sum over its neglected terms of carried estimate + this frame's flow, core/engine/decision.h)
// against its threshold; the flow measures; the estimates carried on. For a scene: the
// polygons per level, culled and hidden counts are not kept, only levels and the error.
QString explain_frame(const FrameRecord& record, const EngineSettings& settings);

// One line about image pixel `pixel` (top-left pixels) of the current frame: for a single
// plane inside the displayed polygon, the flow vector there (pixels per frame), the level,
// and the geometric error (distance between where the engine shows that texel and where
// the exact projection puts it); for a scene, the engine's and the exact colour there.
QString pixel_readout(const AnimationSession& session, const Vec2& pixel, const Image& exact);

}  // namespace oflab
