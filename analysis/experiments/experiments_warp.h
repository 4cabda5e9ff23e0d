// Warp timing (dissertation appendix A.2): the affine and perspective kernels
// (core/image/warp.h, nearest sampling) on the butterfly at 243 x 198 and at half size
// (121 x 99), with the identity, a 45-degree rotation about the image centre, and
//   M = [[0.8, 0.6, 0], [-0.4, 0.8, 0], [0.1, -0.3, 1]]
// applied in normalised image units (pixel coordinates minus the image centre, divided by
// the image width, on both axes; the same convention as oflab-bench). The affine kernel
// cannot apply M's perspective row; it runs M's upper two rows, as the published affine
// column must have. Each output is sized to the warped polygon's bounding box.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "experiments/experiments.h"

namespace oflab {

struct WarpTimingSpec {
  int repetitions = 5000;  // timed calls per case and kernel (after a short warm-up)
};
// Full: 5000 repetitions (the dissertation's 3000-5000); quick: 200.
WarpTimingSpec warp_timing_spec(bool quick);

struct WarpTiming {
  std::string size;    // "243x198"
  std::string matrix;  // "identity", "rot45", "M"
  std::string kernel;  // "affine", "perspective"
  double median_ms = 0.0;
  std::int64_t pixels_written = 0;
  int repetitions = 0;
};

struct WarpTimingResult {
  std::vector<WarpTiming> timings;  // sizes x matrices x kernels
  const WarpTiming* find(const std::string& size, const std::string& matrix,
                         const std::string& kernel) const;
};

WarpTimingResult run_warp_timing(const WarpTimingSpec& spec,
                                 const std::function<void(const std::string&)>& progress);

ReportSection warp_timing_section(const WarpTimingResult& result, ExperimentContext& context);

}  // namespace oflab
