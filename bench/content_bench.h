// Content cases of oflab-bench (manual/costs.md): what one work unit of a lit layer content
// (core/content/layer_content.h) costs in pixels of a perspective warp, the calibration
// behind content_unit_cost.
#pragma once

namespace oflab::bench {

// Registers "content/shaded/cost-per-unit" and "content/impostor/cost-per-unit": one
// iteration renders the content (quality 4) of a 2 x 1.5 plane turned 30 degrees, 4 units
// in front of a 640 x 480 camera, then warps a texture of the same plane by its exact
// (perspective) warp. Counters: unit_ns (render time per work unit: shaded sample or
// impostor fragment), warp_ns (warp time per pixel written) and unit_cost (their ratio, the
// figure content_unit_cost holds), render_ms and warp_ms (medians).
void register_content_cases(int repetitions);

}  // namespace oflab::bench
