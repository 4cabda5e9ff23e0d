// The mipmap cases of oflab-bench (manual/warping.md#mipmap-sampling): one minifying warp
// timed under bilinear sampling, mipmap sampling (the default blend, over the middle half of
// each octave) and mipmap sampling blended over whole octaves (MipBlend::kTrilinear) in turn
// in the same run, the mipmap pyramid built once beforehand as the engine keeps it with its
// layer. Names mipmap-vs-bilinear/<kernel>/<size>/<matrix>; counters bilinear_ms, mipmap_ms
// and trilinear_ms (medians of the per-call times over the run), ratio (mipmap_ms /
// bilinear_ms) and trilinear_ratio (trilinear_ms / bilinear_ms).
#pragma once

namespace oflab::bench {

void register_mipmap_cases(int repetitions);

}  // namespace oflab::bench
