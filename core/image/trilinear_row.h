// The trilinear row of the mipmap kernel (core/image/mipmap_kernel.h): one row segment of a
// perspective warp sampled bilinearly on two neighbouring mip levels and blended pixel by pixel
// (Williams 83, dissertation section 7.5.5). Level k is sampled exactly as the bilinear kernel
// samples it (run_bilinear_row, core/image/warp_kernels.h); with AVX2 both levels are sampled
// in one loop, level k + 1's positions derived from level k's.
#pragma once

#include <cstdint>
#include <vector>

#include "image/image.h"
#include "image/inverse_map.h"

namespace oflab {

// The levels of a perspective mipmap warp as the rows sample them: per level k (0 .. top,
// top <= 15) its bilinear map (division form, level k's positions: the level-0 ones scaled
// by 2^-k, mipmap_kernel.cpp's level_plan) and its image (level 0 the source).
// Optionally, per level, its copy with kMipBorder replicated texels on every side
// (MipPyramid::bordered_level; null for level 0, or `bordered` left empty): where a level
// pair has both, run_trilinear_levels_row samples the pixels whose taps leave the level by
// less than the border in its fast loop instead of clamping each tap (the same bytes).
struct MipLevelMaps {
  std::vector<InverseMap> maps;
  std::vector<const Image*> images;
  std::vector<const Image*> bordered;  // empty, or one per level (null: none)
};

// Pixels x_begin .. x_end - 1 of output row y (output pixels, centred coordinates of the plan
// the maps come from) sampled trilinearly on two mip levels k and k + 1
// (core/image/mip_pyramid.h) into out[0 .. x_end - x_begin - 1]: out[i] = (a (256 - w) + b w +
// 128) / 256 per channel for w = weights[i] in [0, 255], a the sample of `source` through `map`
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

// Pixels x_begin .. x_end - 1 of output row y sampled each at its own level pair: pixel x
// at indices[x - x_begin] (256 lower + weight, as mip_row_levels gives them; lower <= top,
// weight 0 on the top level), with the bytes of run_trilinear_row on levels lower and
// lower + 1 with that weight (run_bilinear_row's where the weight is 0): each pixel's
// position is exact in double whatever run it is part of, and its taps are clamped only
// where they would leave its lower level. The row is cut where the lower level changes
// without a separate pass: eight indices at a time are read and compared inside the
// sampling loop, and the pixels before a change still take the fast loop. out[0] is pixel
// x_begin. Returns false, writing nothing, when the AVX2 loops are off or a level's steps
// are not exact in double (the caller then takes run_trilinear_row per stretch).
// Preconditions: x_begin <= x_end, D > 0 over the row's pixels, every level's map in
// division form, `indices` readable up to x_end - x_begin + 7 entries (seven of padding,
// any values).
bool run_trilinear_levels_row(const MipLevelMaps& levels, const std::uint16_t* indices, int y,
                              int x_begin, int x_end, Pixel* out);

}  // namespace oflab
