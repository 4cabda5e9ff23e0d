// The warp kernels (dissertation appendix A.1, errata 28-30 fixed), in two passes:
//  1. scan conversion of the warped polygon with two active edges (scan_conversion.h);
//     the pixels at either end of a span whose samples would leave the source image
//     (rounding at the source border, bilinear taps beyond it) are sampled exactly with
//     clamping. The floor of a linear or linear-fractional function is monotone along a
//     row, so checking the two ends suffices and the rest of the span is one "fast run"
//     whose inner loop needs no bounds checks;
//  2. the fast runs, in vertical strips of 512 output columns so that consecutive rows
//     reuse the same source cache lines and pages, stepping incrementally:
//     - affine: 64-bit fixed point (inverse_map.h), two integer additions per pixel;
//     - perspective: numerators and denominator stepped exactly in double (they are
//       integers below 2^53), one packed division per two pixels giving both pixels'
//       reciprocals of D, and products with them. For nearest sampling the numerators
//       are offset by 1/2, which keeps every quotient at least 1/(2D) from an integer,
//       so the truncated products are the exact floors (warp_kernels.cpp), nearest
//       sampling needs no tie-breaking and equals the per-pixel reference. With AVX2
//       (below) one division gives four pixels' reciprocals;
//     - bilinear: 16.16 fixed-point positions and a SIMD blend (bilinear_blend.h), two
//       pixels per step with SSE2, four with AVX2 where the CPU has it (chosen at run
//       time; setting the environment variable OFLAB_WARP_NO_AVX2 keeps SSE2); both are
//       within one level of the exact interpolation.
// No virtual calls or std::function: the four kernels are template instantiations.
#pragma once

#include <cstdint>
#include <vector>

#include "image/image.h"
#include "image/scan_conversion.h"
#include "image/warp_plan.h"

namespace oflab {

// Runs the plan's kernel (plan.affine_kernel) with its sampling, nearest or bilinear (a
// mipmap plan runs in core/image/mipmap_kernel.h, which calls this per level), over the whole
// polygon or a partial warp's pixels (plan.only, WarpOptions::only in core/image/warp.h).
// Preconditions: output.width() == plan.output_width, output.height() ==
// plan.output_height, and `source` is the image of the layer the plan was prepared for.
// Returns the number of output pixels inside the polygon (WarpStats::pixels_written) and
// adds to *computed, when given, the pixels it sampled. Never reads or writes outside either
// image.
std::int64_t run_warp_kernel(const WarpPlan& plan, const Image& source, Image& output,
                             std::int64_t* computed = nullptr);

// One row segment of a perspective bilinear warp: pixels x_begin .. x_end - 1 of output row
// y sampled from `source` through `map` into out[0 .. x_end - x_begin - 1], exactly as
// run_warp_kernel samples them (the ends whose taps need clamping one by one, the rest in
// the fast loop). The mipmap kernel runs it per level on the row segments where that level
// serves, and the trilinear row (core/image/trilinear_row.h) on two levels. Preconditions: map is
// in division form (affine_shift < 0) with D > 0 over the segment's pixels (make_inverse_map over a
// region holding them), 0 <= x_begin <= x_end.
void run_bilinear_row(const InverseMap& map, const Image& source, int y, int x_begin, int x_end,
                      Pixel* out);

// One level of an affine bilinear warp taken apart, for the mipmap kernel's affine warps
// (core/image/mipmap_kernel.h), which sample two levels row by row into rows of their own and
// blend them there: every pixel has the bytes run_warp_kernel gives it for the same plan (pass
// 1's clamped ends, the fast runs cut at the same strips of columns and, in a partial warp,
// the same blocks).
class AffineBilinearLevel {
 public:
  // Preconditions: plan.affine_kernel and plan.sampling == Sampling::kBilinear; `source` is
  // the image the plan samples. Both outlive the level.
  AffineBilinearLevel(const WarpPlan& plan, const Image& source);

  // Pass 1: the next span of the plan's polygon (scan order, non-empty, inside the output),
  // with its fast run. Every span is added before the first sample().
  void add(const PixelSpan& span);

  // Pass 2 (any thread; spans in any order): the pixels of the k-th added span that the plan
  // wants (all of them without plan.only; with it, the wanted ones and the rest of their
  // blocks) into row[x], row[x] being output pixel x of the span's row. Returns the pixels
  // sampled.
  std::int64_t sample(int k, Pixel* row) const;

 private:
  struct Run {
    PixelSpan span;
    int fast_begin;  // the fast run [fast_begin, fast_end); empty: fast_begin >= fast_end
    int fast_end;
  };
  const WarpPlan& plan_;
  const Image& source_;
  std::vector<Run> runs_;
  int strip_begin_;  // the first fast pixel of any span: the strips' grid starts there
};

// True when the kernels run their AVX2 loops: the CPU has AVX2 and the environment variable
// OFLAB_WARP_NO_AVX2 is not set (read once). Other AVX2 loops (mip_row_levels.h) follow it.
bool warp_avx2_enabled();

}  // namespace oflab
