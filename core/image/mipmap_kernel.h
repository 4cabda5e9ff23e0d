// The mipmap warp kernel (Sampling::kMipmap; Williams 83, dissertation section 7.5.5): each
// output pixel is sampled from the source's mip pyramid (core/image/mip_pyramid.h) at the
// level of its footprint, trilinearly: bilinear on levels floor(L) and floor(L) + 1, blended
// with weight frac(L) rounded to a multiple of 1/256 (a weight of 0 or 1 samples one level
// only). Positions on level k are the level-0 sampling position M^-1(centre) scaled by
// 2^-k (mip_pyramid.h), minus (0.5, 0.5) to index pixel centres.
//  - affine: J is constant, so one level pair serves the whole warp: the bilinear kernel
//    (core/image/warp_kernels.h) runs on level floor(L) into the output and, when the weight
//    is not 0, on the next level into a scratch image, and the two are blended span by span.
//    L = 0 (magnification) is the bilinear kernel itself, pixel for pixel.
//  - perspective: L varies per pixel, J(x) = (A D(x) - (A x + c) g^T) / D(x)^2 for the
//    inverse map [A c; g^T i]. When a bound shows that no pixel of the region minifies
//    (max over its vertices of |N(x)|_F over min D(x)^2, both extreme at a vertex, at most 1),
//    the bilinear kernel runs unchanged; otherwise every pixel is sampled with its own level,
//    the bilinear taps clamped at the level's border, within one level per channel of the
//    bilinear kernel where L = 0.
#pragma once

#include <cstdint>

#include "image/image.h"
#include "image/mip_pyramid.h"
#include "image/warp_plan.h"

namespace oflab {

// Runs a plan made for Sampling::kMipmap (plan.map is its level-0 bilinear map and
// plan.dest_to_source the continuous inverse map). Preconditions: as run_warp_kernel, and
// `pyramid` built from `source` (pyramid.fits(source)). Returns the pixels inside the
// polygon, the pixels the bilinear kernel would write, and adds to *computed, when given, the
// pixels it sampled. A partial warp (plan.only, WarpOptions::only) gives each wanted pixel
// the bytes of the whole warp: a per-pixel level depends on the pixel alone, a one-level
// affine warp is the bilinear kernel's partial warp, and a blended affine pair samples both
// levels into scratch images and blends into the output the wanted pixels only.
std::int64_t run_mipmap_kernel(const WarpPlan& plan, const Image& source, const MipPyramid& pyramid,
                               Image& output, std::int64_t* computed = nullptr);

}  // namespace oflab
