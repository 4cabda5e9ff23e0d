// Scene cases of oflab-bench (manual/costs.md): scenes on core's worker threads.
#pragma once

namespace oflab::bench {

// Registers "scene/street/walk/threads": one iteration plays the shipped scene `street` under
// the viewer script `walk` (all its frames, default settings with the scene's content quality, as
// `oflab-cli animate --scene street --script walk`) four times at once, frame by frame: the engine
// (perspective) and the exact re-render (rerender) on 1 worker thread, then both on 2
// (core/image/thread_pool.h). The reported time is the 2-thread engine's (manual time). Counters,
// medians per frame after frame 0 in milliseconds of the frames' own time: engine_1t_ms,
// engine_2t_ms, rerender_1t_ms, rerender_2t_ms; engine_scaling (engine 1 thread over 2),
// rerender_scaling, and engine/rerender_1t, engine/rerender_2t (the engine against the exact
// re-render on the same threads). Ratios come from frames measured side by side, so a busy machine
// slows both sides alike. A missing dataset makes the case report an error.
// Registers "scene/four-cubes/translate/depth-reprojection/threads" alike: the scene
// `four-cubes` under `translate` (the holes lesson's run), with depth reprojection in the
// engine's place (every pixel splatted by its own depth, core/scene/depth_reprojection.h).
void register_scene_cases(int repetitions);

}  // namespace oflab::bench
