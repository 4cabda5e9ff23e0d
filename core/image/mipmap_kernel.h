// The mipmap warp kernel (Sampling::kMipmap; Williams 83, dissertation section 7.5.5): each
// output pixel is sampled from the source's mip pyramid (core/image/mip_pyramid.h) at the
// level of its footprint, trilinearly: bilinear on levels floor(L) and floor(L) + 1, blended
// with weight frac(L) rounded to a multiple of 1/256 (a weight of 0 or 1 samples one level
// only). Positions on level k are the level-0 sampling position M^-1(centre) scaled by
// 2^-k (mip_pyramid.h), minus (0.5, 0.5) to index pixel centres.
//  - affine: J is constant, so one level pair serves the whole warp: the bilinear kernel
//    (core/image/warp_kernels.h) runs on level floor(L) and, when the weight is not 0, on
//    the next level too, span by span (AffineBilinearLevel) into rows of the thread, and the
//    two are blended in the output row while both are in the cache. In that blend each level
//    of 1 and up is sampled on its bordered copy (mip_pyramid.h), its positions moved by
//    kMipBorder texels exactly, so that no pixel's taps need clamping one by one (the taps
//    along the polygon's edges read the copy's replicated texels, which clamping gives): every
//    pixel within one level of its level's exact bilinear sample, and, where the stepped
//    positions are exact (a matrix exact in binary), the bytes of the bilinear warp of the
//    level itself.
//    L = 0 (magnification) is the bilinear kernel itself, pixel for pixel.
//  - perspective: L varies per pixel, J(x) = (A D(x) - (A x + c) g^T) / D(x)^2 for the
//    inverse map [A c; g^T i]. When a bound shows that no pixel of the region minifies
//    (max over its vertices of |N(x)|_F over min D(x)^2, both extreme at a vertex, at most 1),
//    the bilinear kernel runs unchanged. Otherwise each row span gets every pixel's level
//    index (256 lower + weight) from the exact largest singular value of J
//    (core/image/mip_row_levels.h: within one step of level_pair(mip_level); on a span whose
//    level bends little, by a bound on its second derivative, the level is found at knots
//    8 pixels apart and interpolated linearly in between, else at every pixel, eight at a
//    time);
//    then one loop samples the span eight pixels at a time on each pixel's lower level and,
//    where a weight is not 0, the next level too, both sampled at once and blended pixel by
//    pixel with each pixel's weight, stopping where the lower level changes (the integer
//    part changes a few times a row at most) and going on there with the next level pair
//    (run_trilinear_levels_row in core/image/trilinear_row.h; without AVX2 the span is cut
//    into stretches of one lower level first, each run by run_trilinear_row).
//    Bound: every channel is within 2 levels of mipmap_pixel, the exact per-pixel definition:
//    a level pair one step from level_pair(mip_level) moves the blend by under one level, and
//    each level's bilinear sample is within one level of the per-pixel one (the same 16-bit
//    weights to one unit of 2^-16, each rounded once), so before the blend's rounding the two
//    differ by under 2 levels (tests/core/image/mipmap_test.cpp checks it on a tilt spanning
//    more than three levels).
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
// levels' partial warps into rows of the thread and blends into the output the wanted pixels
// only.
std::int64_t run_mipmap_kernel(const WarpPlan& plan, const Image& source, const MipPyramid& pyramid,
                               Image& output, std::int64_t* computed = nullptr);

// The mipmap sample of output pixel (x, y) by the definition, computed alone: the exact level
// mip_level of the inverse map's Jacobian at the pixel centre, its level_pair, and the two
// levels' bilinear samples with taps clamped at each level's border, blended. dest_to_source
// is a plan's (output pixel coordinates -> continuous level-0 source coordinates), positive
// denominator at the pixel. The perspective kernel stays within 2 levels of it (above).
Pixel mipmap_pixel(const Mat3& dest_to_source, const Image& source, const MipPyramid& pyramid,
                   int x, int y);

}  // namespace oflab
