// OpenCV's cv::warpAffine / cv::warpPerspective on the same cases, one thread, the same
// interpolation: a peer for the timings in manual/warping.md. Only built when CMake finds
// OpenCV (core, imgproc); OpenCV is never a dependency of oflab itself.
#pragma once

#include <vector>

#include "warp_cases.h"

namespace oflab::bench {

// Registers "opencv/<affine|perspective>/<nearest|bilinear>/<size>/<matrix>" cases and
// limits OpenCV to one thread. Matrices are converted to OpenCV's convention (pixel
// centres at integer coordinates): M_cv = T(-0.5, -0.5) * M * T(0.5, 0.5), with the
// output origin folded in. OpenCV writes every output pixel (BORDER_CONSTANT); the Mpx/s
// counter still counts the polygon pixels, so that it compares with oflab's directly.
void register_opencv_cases(const std::vector<WarpCase>& cases, bool bilinear_too, int repetitions);

}  // namespace oflab::bench
