// The benchmark cases of oflab-bench (manual/warping.md): the dissertation's appendix A.2
// table and larger RGBA frames, each a source layer, a warp matrix (source pixel
// coordinates -> destination pixel coordinates, pixel centres at +0.5) and an output.
#pragma once

#include <benchmark/benchmark.h>

#include <cstdint>
#include <string>
#include <vector>

#include "flow/geometry.h"
#include "image/layer.h"
#include "image/warp.h"

namespace oflab::bench {

struct WarpCase {
  std::string size;    // "243x198"
  std::string matrix;  // "identity", "rot45", "M", "rotation", "tilt", ...
  Layer source;
  Mat3 warp;  // source pixel coordinates -> destination pixel coordinates
  int output_width = 0;
  int output_height = 0;
  int origin_x = 0;  // destination coordinates of output pixel (0, 0)'s corner
  int origin_y = 0;
  bool affine = true;  // whether the affine kernel can run this matrix
  // Output pixels inside the warped polygon (what the kernels write): the pixel count
  // behind every Mpx/s counter, for oflab, OpenCV and the copy alike.
  std::int64_t polygon_pixels = 0;
};

// Dissertation appendix A.2: 243 x 198 and 121 x 99 images; identity, 45-degree rotation
// about the image centre, and M = [[0.8, 0.6, 0], [-0.4, 0.8, 0], [0.1, -0.3, 1]] applied
// in normalised image units (pixel coordinates minus the image centre, divided by the
// image width, on both axes), with "M-affine" its upper two rows alone. Outputs are sized
// to the warped polygon's bounding box, as the dissertation's warp did.
std::vector<WarpCase> appendix_a2_cases();

// Fraction of the case's polygon pixels where a peer's output (output_width x
// output_height, premultiplied RGBA in oflab's byte order) equals oflab's warp of the same
// case (nearest) or is within 2 levels per channel (bilinear): a check that a peer warps
// the same case. Peers round positions and weights differently (OpenCV to 1/1024 pixel and
// 1/32, pixman to 1/65536 pixel and 1/128), so pixels on sampling boundaries may differ.
double agreement(const WarpCase& c, const Image& peer_output, Sampling sampling);

// Sets the counters every peer case reports: "agree" (agreement() of the peer's output of
// one call onto a transparent frame) and "Mpx/s" (the case's polygon pixels per second).
void set_peer_counters(benchmark::State& state, const WarpCase& c, const Image& peer_output,
                       Sampling sampling);

// 1024 x 768 and 1920 x 1080 sources warped into same-sized frames: "rotation" is 45
// degrees about the frame centre, "tilt" a camera pitch of 20 degrees (focal length =
// frame width) composed with a 0.85 zoom about the centre.
std::vector<WarpCase> frame_cases();

}  // namespace oflab::bench
