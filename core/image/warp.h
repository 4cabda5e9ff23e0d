// Affine and perspective warps of layer images (dissertation appendix A.1, with errata
// 28-30 of manual/theory.md#errata fixed). The project's hot path; see manual/warping.md.
//
// Frames and units. A warp matrix M maps continuous pixel coordinates of the source
// layer (x right, y down, origin at the top-left corner of pixel (0, 0)) to continuous
// destination pixel coordinates: dest = apply_homography(M, source). Pixel (x, y) covers
// [x, x+1) x [y, y+1) and its centre is (x + 0.5, y + 0.5); this holds in the source, the
// destination, the scan conversion and the reference alike.
//
// What is written. Output pixel p is written iff its centre lies inside the warped
// polygon M(clipped source polygon) under the half-open rule of core/image/scan_conversion.h;
// no other output pixel is touched. Its value is sampled at M^-1(centre of p), as defined
// exactly in core/image/inverse_map.h: nearest takes the source pixel containing that point
// (floor), exactly as defined there; bilinear interpolates the four source pixels whose
// centres surround it, within one level per channel of the exact interpolation (16-bit
// weights, positions within 2^-12 pixel of the exact ones). Taps beyond the source
// image are clamped to its border pixels.
//
// Horizon. For a perspective M only the part of the source polygon where M's denominator
// is >= horizon_epsilon times its largest value over the polygon is warped
// (clip_near_horizon in core/image/polygon.h); the side where M's denominator is negative is
// never drawn. Pass M with a positive denominator on the visible side (M33 > 0 when the
// source origin is visible). Affine matrices are normalised to M33 = 1 first, so their
// sign does not matter.
//
// Errors. Every function here throws std::invalid_argument, with a message naming the
// problem, for: a non-finite matrix entry; a singular matrix (|det| <= 1e-12 after
// scaling the largest entry to 1); the affine kernel asked for a non-affine matrix; a
// horizon_epsilon outside [1e-4, 0.5]; a warped layer larger than kMaxImageDimension; a
// minification or horizon proximity beyond the exact fixed-point range (inverse_map.h).
// Empty cases are not errors: an empty source layer, a polygon wholly behind the horizon
// or wholly outside the output write nothing (pixels_written == 0, or an empty layer).
#pragma once

#include <cstdint>
#include <string>

#include "flow/geometry.h"
#include "image/image.h"
#include "image/layer.h"
#include "image/mip_pyramid.h"
#include "image/pixel_rows.h"

namespace oflab {

enum class Sampling { kNearest, kBilinear, kMipmap };
constexpr int kSamplingCount = 3;

// The one vocabulary of samplings: sampling_name gives "nearest", "bilinear" or "mipmap"
// (the words of options, session files and JSON); parse_sampling accepts exactly those and
// returns false, leaving *sampling unchanged, for anything else; sampling_name_list joins
// the names with `separator`: "nearest, bilinear, mipmap" for error messages,
// "nearest|bilinear|mipmap" for usage lines.
const char* sampling_name(Sampling sampling);
bool parse_sampling(const std::string& text, Sampling* sampling);
std::string sampling_name_list(const std::string& separator = ", ");

// Which kernel runs. kAutomatic picks kAffine when M's bottom row is (0, 0, 1) after
// division by M33 (exactly), else kPerspective. kPerspective accepts affine matrices too
// (used to compare the kernels on the same case).
enum class WarpKernel { kAutomatic, kAffine, kPerspective };

// Default relative horizon margin (see clip_near_horizon).
constexpr double kDefaultHorizonEpsilon = 1e-3;

struct WarpOptions {
  Sampling sampling = Sampling::kNearest;
  WarpKernel kernel = WarpKernel::kAutomatic;
  double horizon_epsilon = kDefaultHorizonEpsilon;
  // Sampling::kMipmap only: the source image's pyramid (build_mip_pyramid), kept by the
  // caller with its layer so that it is built once per layer, not once per warp. Null: the
  // warp builds one for itself. A pyramid of another size than the source's image is refused
  // (std::invalid_argument); one built from other pixels of that size is the caller's error.
  const MipPyramid* pyramid = nullptr;
  // A partial warp: when set, only output pixels whose destination pixel (output pixel plus
  // the output's origin) is in `only` are computed, with, for the affine kernel's bilinear
  // sampling, the rest of their blocks of kPartialWarpBlock columns; the others inside the
  // polygon keep what the output held. Every pixel computed is the same bytes as in the whole
  // warp: each pixel of the other kernels depends on its own exact position only, and the
  // affine bilinear blocks start where its fixed-point runs restart (mipmap: as bilinear, a
  // blended level pair writing the wanted pixels only). Null: the whole polygon.
  const PixelRows* only = nullptr;
  // With `only`: when set, the destination pixels the partial warp computed are added to it:
  // the wanted pixels inside the polygon and, under the affine kernel's bilinear sampling,
  // the rest of their blocks (the whole warp's bytes too; a caller completing the layer later
  // need not compute them again). Ignored without `only`.
  PixelRows* computed_pixels = nullptr;
};

// Columns of the affine bilinear kernel's block in a partial warp (WarpOptions::only).
constexpr int kPartialWarpBlock = 64;

struct WarpStats {
  std::int64_t pixels_written = 0;   // output pixels inside the warped polygon
  std::int64_t pixels_computed = 0;  // of those, the pixels sampled (all but a partial warp's)
  WarpKernel kernel_used = WarpKernel::kAffine;  // kAffine or kPerspective
};

// Result of warping into a new layer: `layer` pixel (0, 0) has its top-left corner at
// destination coordinates (offset_x, offset_y); layer.polygon is the warped polygon in the
// layer's own pixel coordinates (destination minus offset).
struct WarpedLayer {
  Layer layer;
  int offset_x = 0;
  int offset_y = 0;
  WarpStats stats;
};

// True if M's bottom row is exactly (0, 0, M33) with M33 != 0.
bool is_affine(const Mat3& m);

// Warps `source` by `source_to_dest` into `output`, whose pixel (0, 0) has its top-left
// corner at destination coordinates (output_origin_x, output_origin_y). Overwrites the
// output pixels inside the warped polygon (no blending; use composite_over for that) and
// leaves all others untouched. Throws std::invalid_argument as listed above.
WarpStats warp_layer_into(const Layer& source, const Mat3& source_to_dest, Image& output,
                          int output_origin_x, int output_origin_y,
                          const WarpOptions& options = {});

// Warps `source` into a new layer sized to the bounding box of the warped polygon
// (integer-aligned), transparent outside the polygon. An empty result (empty layer,
// offsets 0) when nothing is visible. Throws std::invalid_argument as listed above,
// including when the box exceeds kMaxImageDimension in either direction.
WarpedLayer warp_layer(const Layer& source, const Mat3& source_to_dest,
                       const WarpOptions& options = {});

// warp_layer into `result`, reusing the memory of its image when it is large enough (no
// allocation of pixels then: an animation that warps into the same results every frame
// allocates pixels only while its layers grow). Precondition: `result` is empty or holds
// a layer transparent outside its polygon (any result of a warp, or a copy of one). The
// outcome equals warp_layer's, pixel for pixel: the kernel writes the pixels inside the
// warped polygon, and of the others only those the previous layer covered are cleared,
// the rest being transparent already. Throws std::invalid_argument as warp_layer, and
// then leaves `result` unchanged.
void warp_layer_reusing(const Layer& source, const Mat3& source_to_dest, WarpedLayer& result,
                        const WarpOptions& options = {});

// The two kernels, for benchmarks and tests: warp_layer_into with options.kernel forced.
// warp_affine_into throws std::invalid_argument if M is not affine.
WarpStats warp_affine_into(const Layer& source, const Mat3& source_to_dest, Image& output,
                           int output_origin_x, int output_origin_y, Sampling sampling);
WarpStats warp_perspective_into(const Layer& source, const Mat3& source_to_dest, Image& output,
                                int output_origin_x, int output_origin_y, Sampling sampling);

}  // namespace oflab
