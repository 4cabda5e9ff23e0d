// Image similarity for tests and reports.
#pragma once

#include "image/image.h"

namespace oflab {

// Peak signal-to-noise ratio in dB (peak 255) over the four premultiplied channels of the
// pixels where either image is not fully transparent. Identical images (or two fully
// transparent ones) give kIdenticalPsnrDb. Precondition: same size (throws
// std::invalid_argument otherwise).
constexpr double kIdenticalPsnrDb = 99.0;
double psnr_db(const Image& a, const Image& b);

}  // namespace oflab
