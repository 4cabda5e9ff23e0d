// The mipmap cases of oflab-bench (manual/warping.md#mipmap-sampling): one minifying warp
// timed under bilinear and mipmap sampling alternately in the same run, the mipmap pyramid
// built once beforehand as the engine keeps it with its layer. Names
// mipmap-vs-bilinear/<kernel>/<size>/<matrix>; counters bilinear_ms and mipmap_ms (medians
// of the per-call times over the run) and ratio (mipmap_ms / bilinear_ms).
#pragma once

namespace oflab::bench {

void register_mipmap_cases(int repetitions);

}  // namespace oflab::bench
