// The mip level of every output pixel along a row of a perspective warp (Sampling::kMipmap,
// core/image/mipmap_kernel.h), as the trilinear kernel consumes it: index 256 lower + weight.
//
// At pixel centre p the inverse map h = [A c; g^T i] (output pixels -> level-0 source) has
// the Jacobian J = M / D^2 with D = g.p + i and M = A D - (A p + c) g^T. Along a row M is
// affine in x with a rank-one slope [0 beta], and the largest singular value of a 2 x 2
// matrix is exactly
//     sigma(M) = (|P| + |R|) / 2,  P = (m00 + m11, m01 - m10),  R = (m00 - m11, m01 + m10)
// (|P| = s1 + s2, |R| = s1 - s2), so |P|^2, |R|^2 and D are polynomials in x of degree 2,
// 2 and 1: no eigenvectors, one square root each. The level is log2(sigma(M) / D^2) clamped
// to [0, top], its index round(256 level).
//
// With AVX2 and FMA the levels are found in float (P, R and D as t b + c, t the pixel's
// offset in the segment, scaled by powers of two so that D is about 1 at its first pixel;
// one square root, sigma^2 = |P|^2 / 4 + |R|^2 / 4 + |P| |R| / 2; one division by D^4; log2
// by the exponent and an atanh series), on segments whose terms are well conditioned (each
// at most 16 times the smallest |P| of the segment, 8 times the smallest D): a level is
// then within 2e-5 of the exact one (1/200 of a weight step). On such a segment the level is
// smooth unless P or R vanishes, and its second derivative is bounded from the segment's
// terms (mip_row_levels.cpp, interpolation_error): where that bound keeps the linear
// interpolation between knots kMipLevelKnotStep pixels apart within half a step of the
// level, only the knots (pixels 0, 8, 16, ... and the segment's last) are computed, and
// each pixel's index is round(256 L) of the linearly interpolated unclamped level L,
// clamped to [0, top]: within one step of the exact level's index (half a step of
// interpolation, 1/200 of float, half of rounding). Elsewhere every pixel is computed, and
// each index is round(256 level) or, where 256 level lies within 1/200 of a half-integer,
// one step next to it. Other segments, and CPUs without AVX2 or FMA, take the same formula
// per pixel in double. Either way each index is within one step of level_pair(mip_level),
// which is what the mipmap kernel's bound (mipmap_kernel.h) takes.
#pragma once

#include <cstdint>

#include "flow/geometry.h"

namespace oflab {

// The distance in pixels between the knots of an interpolated segment (above).
inline constexpr int kMipLevelKnotStep = 8;

// The level indices of output pixels x_begin .. x_end - 1 of row y into out[0 ..
// x_end - x_begin - 1]: 256 lower + weight of level_pair(mip_level(J)) as above, within one
// step of it. dest_to_source: output pixel coordinates (corner origin) -> continuous level-0
// source coordinates, with D > 0 at every pixel centre of the segment; top: the pyramid's
// top level (0 .. 15). Precondition: x_begin <= x_end.
void mip_row_levels(const Mat3& dest_to_source, int top, int y, int x_begin, int x_end,
                    std::uint16_t* out);

// The same pixel by pixel in double (the portable path), for comparison in the tests.
void mip_row_levels_scalar(const Mat3& dest_to_source, int top, int y, int x_begin, int x_end,
                           std::uint16_t* out);

}  // namespace oflab
