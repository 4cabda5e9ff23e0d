// The price list of a frame's work (manual/costs.md): the plane engine (core/engine/engine.h),
// the exact renders (core/engine/exact_render.h) and the scene renderers count the work of
// their layer updates with it, so that a frame's work is deterministic and comparable across
// machines and policies.
#pragma once

namespace oflab {

// The dissertation's cost model (section 6.4.4), in pixels of a perspective warp: a
// perspective warp costs 1 per pixel written, an affine warp 1/2.1, a translation 1/35 of the
// layer's area; a re-render costs what its content does (content_unit_cost per work unit,
// the texture's being one perspective warp).
constexpr double kPerspectiveWarpCost = 1.0;
constexpr double kAffineWarpCost = 1.0 / 2.1;
constexpr double kTranslationCost = 1.0 / 35.0;

}  // namespace oflab
