// The trilinear row of the mipmap kernel (core/image/mipmap_kernel.h): one row segment of a
// perspective warp sampled bilinearly on two neighbouring mip levels and blended pixel by pixel
// (Williams 83, dissertation section 7.5.5). Level k is sampled exactly as the bilinear kernel
// samples it (run_bilinear_row, core/image/warp_kernels.h); with AVX2 both levels are sampled
// in one loop, level k + 1's positions derived from level k's.
#pragma once

#include <cstdint>

#include "image/image.h"
#include "image/inverse_map.h"

namespace oflab {

// Pixels x_begin .. x_end - 1 of output row y (output pixels, centred coordinates of the plan
// the maps come from) sampled trilinearly on two mip levels k and k + 1
// (core/image/mip_pyramid.h) into out[0 .. x_end - x_begin - 1]: out[i] = (a (256 - w) + b w +
// 128) / 256 per channel for w = weights[i] in [0, 256], a the sample of `source` through `map`
// and b that of `next_source` through `next_map`. With AVX2 the positions are found once, on
// level k, and level k + 1's derived from them (within one unit of 2^-16 of its own map's);
// each sample is within one level of the exact interpolation, as run_bilinear_row's. Without
// AVX2 (or with OFLAB_WARP_NO_AVX2 set) the two levels run run_bilinear_row one after the
// other and are blended by the same formula. Preconditions: as run_bilinear_row for both maps
// (division form, D > 0 over the segment, 0 <= x_begin <= x_end), next_map being map's level
// scaled by 1/2 (mipmap_kernel.cpp's level_plan), next_source level k + 1 of source, `weights`
// holding x_end - x_begin entries.
void run_trilinear_row(const InverseMap& map, const Image& source, const InverseMap& next_map,
                       const Image& next_source, int y, int x_begin, int x_end,
                       const std::uint16_t* weights, Pixel* out);

}  // namespace oflab
