// Preparation of a warp, shared by the kernels (core/image/warp_kernels.h) and the per-pixel
// reference used in the tests: validation of the matrix, the horizon clip of the source
// polygon, the warped polygon in output pixel coordinates and the exact inverse map.
// Conventions and errors as in core/image/warp.h.
#pragma once

#include <vector>

#include "image/inverse_map.h"
#include "image/layer.h"
#include "image/pixel_rows.h"
#include "image/polygon.h"
#include "image/warp.h"

namespace oflab {

// A validated warp before the output is known.
struct PreparedWarp {
  Mat3 matrix;                   // source -> destination, scaled (M33 = 1 when affine)
  bool affine_kernel = true;     // the kernel that will run
  ConvexPolygon warped_polygon;  // image of the horizon-clipped source polygon, in
                                 // destination coordinates; empty if nothing is visible
};

// Validates `source_to_dest` and `options` and warps the source polygon.
// Throws std::invalid_argument as documented in core/image/warp.h.
PreparedWarp prepare_warp(const Layer& source, const Mat3& source_to_dest,
                          const WarpOptions& options);

// Everything a kernel needs for one output image.
struct WarpPlan {
  bool empty = true;  // nothing to draw: the kernels return at once
  bool affine_kernel = true;
  Sampling sampling = Sampling::kNearest;
  ConvexPolygon polygon;  // warped polygon in output pixel coordinates
  InverseMap map;         // output pixel -> sampling position (inverse_map.h); mipmap:
                          // level 0's bilinear map
  // Output pixel coordinates -> continuous source coordinates (M^-1 with the output's
  // origin; no half-pixel shift): where the mipmap kernel finds each pixel's footprint.
  Mat3 dest_to_source{1.0};
  int output_width = 0;
  int output_height = 0;
  int origin_x = 0;  // destination coordinates of output pixel (0, 0)'s corner
  int origin_y = 0;
  const PixelRows* only = nullptr;  // a partial warp's wanted pixels (WarpOptions::only)
  // With `only`, when WarpOptions::computed_pixels is set: per output row, the destination
  // columns the kernels computed (each row written by one band at a time); else null.
  std::vector<std::vector<ColumnRun>>* computed = nullptr;
};

// Notes output pixels [x_begin, x_end) of row y as computed by a partial warp, if the plan
// keeps that record (WarpPlan::computed). Precondition: 0 <= y < plan.output_height.
inline void record_computed(const WarpPlan& plan, int y, int x_begin, int x_end) {
  if (plan.computed && x_begin < x_end) {
    (*plan.computed)[static_cast<std::size_t>(y)].push_back(
        ColumnRun{x_begin + plan.origin_x, x_end + plan.origin_x});
  }
}

// Plans the warp of a prepared warp into an output of the given size whose pixel (0, 0)
// has its corner at destination coordinates (origin_x, origin_y).
// Throws std::invalid_argument (see make_inverse_map) when the map is out of range.
WarpPlan plan_warp(const PreparedWarp& prepared, Sampling sampling, int output_width,
                   int output_height, int origin_x, int origin_y);

}  // namespace oflab
