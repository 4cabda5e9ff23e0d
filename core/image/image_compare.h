// Image similarity for tests and reports: PSNR and SSIM against the exact frame.
#pragma once

#include "image/image.h"

namespace oflab {

// Peak signal-to-noise ratio in dB (peak 255) over the four premultiplied channels of the
// pixels where either image is not fully transparent. Identical images (or two fully
// transparent ones) give kIdenticalPsnrDb. Precondition: same size (throws
// std::invalid_argument otherwise).
constexpr double kIdenticalPsnrDb = 99.0;
double psnr_db(const Image& a, const Image& b);

// The structural similarity index (Wang, Bovik, Sheikh and Simoncelli, "Image quality
// assessment: from error visibility to structural similarity", IEEE TIP 13(4), 2004) as their
// reference implementation defines it: on luma Y = 0.299 R + 0.587 G + 0.114 B (ITU-R BT.601)
// of the premultiplied colour (the image over black), 8-bit constants C1 = (0.01 x 255)^2 and
// C2 = (0.03 x 255)^2, a Gaussian window of 11 x 11 pixels with sigma 1.5 (weights normalised
// to sum 1), SSIM(x, y) = (2 mu_x mu_y + C1)(2 sigma_xy + C2) /
// ((mu_x^2 + mu_y^2 + C1)(sigma_x^2 + sigma_y^2 + C2)) at every position where the whole
// window lies inside the image ("valid"), and the mean over those positions. 1 for identical
// images. Every pixel counts, transparent ones as black. Preconditions: same size, at least
// kSsimWindow pixels in each dimension (throws std::invalid_argument otherwise).
constexpr int kSsimWindow = 11;
constexpr double kSsimSigma = 1.5;
double mean_ssim(const Image& a, const Image& b);

}  // namespace oflab
