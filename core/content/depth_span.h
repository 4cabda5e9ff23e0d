// One span of a flat face drawn with a depth buffer, as the impostor content draws its faces
// (core/content/layer_content.cpp): the face's 1/Z at each pixel, the depth test, the
// face's colour where it passes. An AVX2 loop draws eight pixels at a time where the CPU has
// it, with the bytes of the pixel-by-pixel loop (tests/core/content/depth_span_test.cpp).
#pragma once

#include <cstdint>

#include "image/image.h"

namespace oflab {

// A face's 1/Z along one row of layer pixels: c0 + a x + by at pixel x (summed in that
// order, in double), rounded to float. Units: 1 / world units along the viewing axis.
struct DepthRow {
  double a = 0.0;   // d(1/Z)/dx per pixel
  double c0 = 0.0;  // the face's 1/Z at pixel (0, 0)'s centre
  double by = 0.0;  // d(1/Z)/dy times the row's y
};

// Pixels x_begin .. x_end - 1 of the row: where the face's 1/Z is not <= z[x] (larger is
// nearer; a NaN passes), z[x] takes it and row[x] takes `colour`. Returns how many of those
// stores landed on a pixel with alpha 0 (the layer starts transparent, so: first stores).
// `wide` false takes the pixel-by-pixel loop everywhere (the tests' reference); true takes
// the AVX2 loop where the CPU has it and OFLAB_WARP_NO_AVX2 is unset (warp_avx2_enabled).
// Preconditions: x_begin <= x_end, z and row valid over [x_begin, x_end).
std::int64_t draw_depth_span(const DepthRow& plane, Pixel colour, int x_begin, int x_end, float* z,
                             Pixel* row, bool wide = true);

}  // namespace oflab
