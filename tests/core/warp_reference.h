// A straightforward per-pixel reference for the warp kernels, and random test inputs.
// The reference shares only the definition of the sampling position (the integer map of
// core/image/inverse_map.h) with the kernels: it classifies every output pixel centre against
// the warped polygon with half-plane tests (no scan conversion), evaluates the map
// directly with 128-bit integers (no incremental steps), takes exact floors and clamps
// per pixel, and interpolates in double. For mipmap sampling it builds its own pyramid in
// double (unrounded 2 x 2 means), finds each pixel's footprint by central differences of the
// map and a brute-force maximum over directions, and blends two bilinear samples in double.
#pragma once

#include <random>
#include <vector>

#include "flow/geometry.h"
#include "image/image.h"
#include "image/layer.h"
#include "image/polygon.h"
#include "image/warp_plan.h"

namespace oflab::testing {

enum class Coverage { kInside, kOutside, kBoundary };

// Where p lies relative to a convex polygon; kBoundary when it is within `tolerance`
// pixels of an edge line (the scan converter's half-open tie rule may go either way).
Coverage classify(const ConvexPolygon& polygon, const Vec2& p, double tolerance);

struct ReferencePixel {
  Coverage coverage = Coverage::kOutside;
  double value[4] = {0.0, 0.0, 0.0, 0.0};  // r, g, b, a before rounding (inside/boundary)
  Pixel rounded;                           // value rounded to the nearest level
};

// Reference result for every output pixel of `plan` (row-major, output size).
std::vector<ReferencePixel> reference_warp(const WarpPlan& plan, const Image& source);

// Counts the pixels where `output` disagrees with the reference: inside pixels must hold
// the reference value (exactly for nearest, within `level_tolerance` for bilinear),
// outside pixels must still hold `sentinel`, boundary pixels either. Writes the first few
// disagreements to `report`.
int count_mismatches(const std::vector<ReferencePixel>& reference, const Image& output,
                     Pixel sentinel, int level_tolerance, std::string* report);

// Random premultiplied image (every pixel well formed: r, g, b <= a).
Image random_image(std::mt19937& rng, int width, int height);

// A random convex polygon inside [0, width] x [0, height]: the whole rectangle, the
// rectangle cut by random half-planes, or the convex hull of random points.
ConvexPolygon random_polygon(std::mt19937& rng, int width, int height);

// A pixel value that no well-formed premultiplied pixel has (r > a): marks untouched
// output pixels.
constexpr Pixel kSentinel{201, 13, 77, 9};

// The homography turning the plane by `degrees` (clockwise on screen, y down) about the
// point (cx, cy), pixels.
Mat3 rotation_about(double degrees, double cx, double cy);

}  // namespace oflab::testing
