// The mip pyramid of a layer image and the level a minifying warp samples (Williams 83,
// "Pyramidal parametrics"; dissertation section 7.5.5, manual/warping.md#mipmap-sampling).
//
// Levels. Level 0 is the layer image itself (not copied); level k + 1 is level k reduced by a
// 2 x 2 box filter: pixel (i, j) of level k + 1 is the rounded mean of pixels (2i, 2j),
// (2i + 1, 2j), (2i, 2j + 1) and (2i + 1, 2j + 1) of level k, a tap beyond an odd edge
// clamped to the last column (row). Level k is ceil(w / 2^k) x ceil(h / 2^k) pixels and the
// top level is 1 x 1. Pixels are premultiplied RGBA8 (core/image/image.h), so the mean of a
// transparent and an opaque pixel is the half-covered pixel, as filtering needs.
//
// Borders. Each level k >= 1 is also kept with kMipBorder texels replicated on every side
// (bordered_level: pixel (i, j) is level k's pixel (clamp(i - kMipBorder), clamp(j -
// kMipBorder)), each coordinate clamped to the level), so that a sampling loop whose taps
// leave the level by at most kMipBorder texels reads the clamped texels without clamping.
//
// Coordinates. A continuous point s of level 0 (top-left pixel coordinates) is s / 2^k on
// level k: level k's pixel (i, j) covers level 0's [2^k i, 2^k (i + 1)) x [2^k j, 2^k (j + 1)).
//
// Level choice. For a warp whose inverse map has the 2 x 2 Jacobian J at an output pixel
// (source pixels per output pixel, core/image/warp.h), the footprint of the output pixel on
// the source is the ellipse J(unit disc); its larger axis is J's largest singular value
// sigma, and the level is log2(sigma) clamped to [0, top]. Level 0 (sigma <= 1) is
// magnification or no scaling: the warp then samples bilinearly, exactly as
// Sampling::kBilinear does.
#pragma once

#include <vector>

#include "flow/geometry.h"
#include "image/image.h"

namespace oflab {

// Texels replicated on each side of the bordered copies of levels 1 and up.
constexpr int kMipBorder = 2;

struct MipPyramid {
  int base_width = 0;  // level 0, the layer image the pyramid was built from
  int base_height = 0;
  std::vector<Image> reduced;   // levels 1 .. top (reduced[k - 1] is level k)
  std::vector<Image> bordered;  // the same with kMipBorder replicated texels on every side

  // The highest level (0 for an empty or 1 x 1 image).
  int top() const { return static_cast<int>(reduced.size()); }
  // Level k >= 1. Precondition: 1 <= k <= top().
  const Image& level(int k) const { return reduced[static_cast<std::size_t>(k - 1)]; }
  // Level k >= 1 with its border: (width + 2 kMipBorder) x (height + 2 kMipBorder) pixels,
  // level k's pixel (0, 0) at (kMipBorder, kMipBorder). Precondition: 1 <= k <= top() and
  // has_borders().
  const Image& bordered_level(int k) const { return bordered[static_cast<std::size_t>(k - 1)]; }
  // True if every level has its bordered copy (build_mip_pyramid makes them).
  bool has_borders() const { return bordered.size() == reduced.size(); }
  // True if the pyramid was built from an image of this size.
  bool fits(const Image& image) const {
    return image.width() == base_width && image.height() == base_height;
  }
};

// The number of levels above level 0 of a width x height image: ceil(log2(max(w, h))),
// 0 for an empty image. Precondition: width, height >= 0.
int mip_top_level(int width, int height);

// `coarse` (reshaped here, its memory reused) as the next level of `fine`: the 2 x 2 box
// reduction above, ceil(w / 2) x ceil(h / 2) pixels, each channel the rounded mean
// (a + b + c + d + 2) / 4 of its four taps, a tap beyond an odd edge clamped. Large images
// are reduced in bands of rows on the worker threads (the same bytes). Precondition: `fine`
// is not `coarse`.
void halve_image(const Image& fine, Image& coarse);

// Builds the pyramid of `image` into `pyramid` (the levels and their bordered copies), reusing the
// memory of its levels (a layer re-rendered at the same size allocates nothing).
void build_mip_pyramid(const Image& image, MipPyramid& pyramid);

// The factor x factor box mean of `image` (each channel's rounded mean): the image a
// supersampled render of factor^2 samples per pixel reduces to. Throws std::invalid_argument
// unless factor >= 1 divides both sides of the image.
Image box_reduce(const Image& image, int factor);

// The largest singular value of the 2 x 2 matrix [[j00, j01], [j10, j11]] (>= 0): the longer
// axis of the footprint ellipse. Closed form of the eigenvalues of J^T J.
double footprint_axis(double j00, double j01, double j10, double j11);

// The continuous level log2(footprint_axis(J)) clamped to [0, top]. J in source pixels per
// output pixel, rows (du/dx, du/dy) and (dv/dx, dv/dy); a singular or non-finite J gives
// the clamped log of what footprint_axis returns (0 for all-zero J, top for infinity).
double mip_level(double j00, double j01, double j10, double j11, int top);

}  // namespace oflab
