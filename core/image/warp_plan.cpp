// Warp preparation: validation, horizon clip (erratum 30), warped polygon, inverse map.
#include "image/warp_plan.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace oflab {
namespace {

constexpr double kSingularDeterminant = 1e-12;
constexpr double kMinHorizonEpsilon = 1e-4;
constexpr double kMaxHorizonEpsilon = 0.5;

// Checks the entries and scales the matrix so that its largest entry is 1.
Mat3 validated_and_scaled(const Mat3& m) {
  double largest = 0.0;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      const double value = entry(m, r, c);
      if (!std::isfinite(value)) {
        throw std::invalid_argument("warp: the matrix has a non-finite entry");
      }
      largest = std::max(largest, std::abs(value));
    }
  }
  if (largest == 0.0) throw std::invalid_argument("warp: the matrix is singular (all zero)");
  return m * (1.0 / largest);
}

// Singularity as a scale-free quantity: |det| over Hadamard's bound (the product of the
// column lengths), which is 1 for a similarity and 0 for a rank-deficient matrix. The
// translation must not count, or a far but harmless shift would look singular: for an
// affine map only the 2 x 2 linear block is tested, for a perspective map the matrix
// is first composed with a translation to the centre of the source polygon.
void check_not_singular(const Mat3& m, bool affine, const Vec2& source_centre) {
  double ratio = 0.0;
  if (affine) {
    const Vec2 c0(entry(m, 0, 0), entry(m, 1, 0));
    const Vec2 c1(entry(m, 0, 1), entry(m, 1, 1));
    const double bound = glm::length(c0) * glm::length(c1);
    ratio = bound > 0.0 ? std::abs(c0.x * c1.y - c0.y * c1.x) / bound : 0.0;
  } else {
    const Mat3 centred = m * translation_matrix(source_centre.x, source_centre.y);
    const double bound =
        glm::length(centred[0]) * glm::length(centred[1]) * glm::length(centred[2]);
    ratio = bound > 0.0 ? std::abs(glm::determinant(centred)) / bound : 0.0;
  }
  if (!(ratio > kSingularDeterminant)) {
    throw std::invalid_argument(
        "warp: the matrix is singular (|det| <= 1e-12 of the product of its column lengths)");
  }
}

}  // namespace

bool is_affine(const Mat3& m) {
  return entry(m, 2, 0) == 0.0 && entry(m, 2, 1) == 0.0 && entry(m, 2, 2) != 0.0;
}

PreparedWarp prepare_warp(const Layer& source, const Mat3& source_to_dest,
                          const WarpOptions& options) {
  if (!(options.horizon_epsilon >= kMinHorizonEpsilon &&
        options.horizon_epsilon <= kMaxHorizonEpsilon)) {
    throw std::invalid_argument("warp: horizon_epsilon must lie in [1e-4, 0.5]");
  }
  PreparedWarp prepared;
  prepared.matrix = validated_and_scaled(source_to_dest);
  const bool affine = is_affine(prepared.matrix);
  Vec2 source_centre(0.0);
  if (!source.polygon.empty()) {
    const BoundingBox box = source.polygon.bounds();
    source_centre = Vec2(0.5 * (box.x_min + box.x_max), 0.5 * (box.y_min + box.y_max));
  }
  check_not_singular(prepared.matrix, affine, source_centre);
  if (affine) {
    // An affine map has no horizon: normalise so that its denominator is exactly 1.
    prepared.matrix = normalise_homography(prepared.matrix);
    entry(prepared.matrix, 2, 2) = 1.0;
  }
  switch (options.kernel) {
    case WarpKernel::kAutomatic:
      prepared.affine_kernel = affine;
      break;
    case WarpKernel::kAffine:
      if (!affine) {
        throw std::invalid_argument(
            "warp: the affine kernel was requested for a matrix whose bottom row is not "
            "(0, 0, 1)");
      }
      prepared.affine_kernel = true;
      break;
    case WarpKernel::kPerspective:
      prepared.affine_kernel = false;
      break;
  }
  if (source.empty()) return prepared;
  const ConvexPolygon visible =
      affine ? source.polygon
             : clip_near_horizon(source.polygon, prepared.matrix, options.horizon_epsilon);
  if (visible.empty()) return prepared;
  prepared.warped_polygon = transform(visible, prepared.matrix);
  return prepared;
}

WarpPlan plan_warp(const PreparedWarp& prepared, Sampling sampling, int output_width,
                   int output_height, int origin_x, int origin_y) {
  WarpPlan plan;
  plan.affine_kernel = prepared.affine_kernel;
  plan.sampling = sampling;
  plan.output_width = output_width;
  plan.output_height = output_height;
  plan.origin_x = origin_x;
  plan.origin_y = origin_y;
  if (prepared.warped_polygon.empty() || output_width <= 0 || output_height <= 0) return plan;

  plan.polygon = translated(prepared.warped_polygon, -origin_x, -origin_y);
  const ConvexPolygon region = clip_to_box(
      plan.polygon,
      BoundingBox{0.0, 0.0, static_cast<double>(output_width), static_cast<double>(output_height)});
  if (region.empty()) return plan;

  // Output pixel coordinates -> destination -> source -> sampling position.
  Mat3 dest_to_sample = glm::inverse(prepared.matrix) * translation_matrix(origin_x, origin_y);
  plan.dest_to_source = dest_to_sample;
  if (sampling != Sampling::kNearest) {  // bilinear, and mipmap's level 0
    dest_to_sample = translation_matrix(-0.5, -0.5) * dest_to_sample;
  }
  if (plan.affine_kernel) {
    // The inverse of an affine matrix has bottom row (0, 0, 1) up to rounding of the
    // exact zeros, which stay exact: set them explicitly.
    entry(dest_to_sample, 2, 0) = 0.0;
    entry(dest_to_sample, 2, 1) = 0.0;
    entry(dest_to_sample, 2, 2) = 1.0;
    entry(plan.dest_to_source, 2, 0) = 0.0;
    entry(plan.dest_to_source, 2, 1) = 0.0;
    entry(plan.dest_to_source, 2, 2) = 1.0;
  }
  plan.map = make_inverse_map(dest_to_sample, region, plan.affine_kernel);
  plan.empty = false;
  return plan;
}

}  // namespace oflab
