// Shrinking without shimmering (dissertation section 7.5.5, beyond its experiments): a plane
// with a finely woven texture (datasets/textures/fabric.png) receding to a quarter of its size
// (datasets/scripts/recede.json) played under each sampling of the warps (core/image/warp.h:
// nearest, bilinear, mipmap) and measured against an exact supersampled render by
// experiments/sampling_comparison.h. The figures: the PSNR per frame, its mean over the reused
// frames whose layer is minified by more than kMinifiedFactor (the gap mipmap gains over
// bilinear there), and the warps' median time per reused frame (the ratio of mipmap's to
// bilinear's). `oflab-cli experiments --only sampling` prints them; the report's chapter
// charts them.
#pragma once

#include <string>
#include <vector>

#include "experiments/experiments.h"
#include "experiments/sampling_comparison.h"

namespace oflab {

// The figures as text lines (what `experiments --only sampling` prints as progress).
std::vector<std::string> sampling_summary_lines(const SamplingComparison& comparison);

// The report's chapter: the PSNR per frame of the three samplings with the minification,
// the table of the minified frames' PSNR and the warps' times.
ReportSection sampling_section(const SamplingComparison& comparison, ExperimentContext& context);

}  // namespace oflab
