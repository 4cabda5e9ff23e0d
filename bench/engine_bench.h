// Engine cases of oflab-bench (manual/animation.md): a shipped motion script played through
// the single-plane engine (core/engine/engine.h) under a reuse policy, beside the bare warp
// kernel drawing the same frames.
#pragma once

namespace oflab::bench {

// Registers "engine/<script>/<mode>" for the scripts rotation, translation-1 and zoom and
// every reuse policy, nearest sampling, the default texture. One iteration plays the
// script once (after one untimed pass) and, interleaved frame by frame, warps the texture
// by each frame's exact warp into a camera-sized frame with the bare kernel
// (warp_layer_into, memory allocated once). The reported time is the engine's own timed
// part (FrameReport::time_ms summed over the frames, manual time); counters, per frame
// after frame 0: frame_ms (median engine time), kernel_ms (median kernel time of the exact
// warp of the same pose: the pixels a re-render writes), engine/kernel (their ratio),
// engine_px and kernel_px (mean pixels written). Scripts and texture come from datasets/
// (or $OFLAB_DATASETS); a missing one makes the case report an error.
void register_engine_cases(int repetitions);

}  // namespace oflab::bench
