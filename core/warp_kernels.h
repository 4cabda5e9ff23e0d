// The warp kernels (dissertation appendix A.1): scan conversion of the warped polygon with
// two active edges, then per span an incremental walk through the exact inverse map.
//  - affine: 64-bit fixed point, two integer additions per pixel;
//  - perspective: numerators and denominator stepped exactly in double (they are integers
//    below 2^53), one pair of divisions per pixel; floor of the correctly rounded
//    quotient equals the exact floor (inverse_map.h), so no tie-breaking is needed.
// Each span is first split so that its middle part samples strictly inside the source
// image: the floor of a linear or linear-fractional function is monotone along a span,
// so checking the two ends suffices and the inner loops have no bounds checks. The few
// pixels at either end whose sample would leave the image take a clamped path.
#pragma once

#include <cstdint>

#include "core/image.h"
#include "core/warp_plan.h"

namespace oflab {

// Run the plan's kernel (plan.affine_kernel) with its sampling. Preconditions:
// output.width() == plan.output_width, output.height() == plan.output_height, and
// `source` is the image of the layer the plan was prepared for. Returns the number of
// output pixels written. Never reads or writes outside either image.
std::int64_t run_warp_kernel(const WarpPlan& plan, const Image& source, Image& output);

}  // namespace oflab
