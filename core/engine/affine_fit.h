// Talisman's reuse test (Torborg & Kajiya 96; Lengyel & Snyder 97, "Rendering with coherent
// layers"): a layer rendered once is shown again through the affine warp that maps its
// bounding polygon's vertices, where they were when the layer was rendered, onto their exact
// projections now, with least squared distance; fiducials say when that warp is no longer
// good enough. Used by the `talisman` reuse policy (core/engine/reuse_policy.h); see
// manual/policies.md.
#pragma once

#include <vector>

#include "flow/geometry.h"

namespace oflab {

// The affine map A (3x3, bottom row exactly (0, 0, 1)) minimising sum |A from_i - to_i|^2,
// in closed form: with the centroids f, g of `from` and `to`, L = (sum (to_i - g)(from_i - f)^T)
// (sum (from_i - f)(from_i - f)^T)^-1 and A = [[L, g - L f], [0, 1]].
// Units: whatever `from` and `to` are in (the engine uses top-left image pixels).
// Preconditions: from.size() == to.size() >= 3 and `from` not collinear; otherwise the 2x2
// scatter is singular and std::invalid_argument is thrown.
Mat3 least_squares_affine(const std::vector<Vec2>& from, const std::vector<Vec2>& to);

// The fiducials of a fitted warp (Lengyel & Snyder 97, section 4).
struct FitFiducials {
  // Geometric: the largest distance, pixels, between a fitted vertex (A from_i) and its true
  // projection to_i.
  double geometric_px = 0.0;
  // Sampling: the singular values of A's 2x2 part, largest and smallest (1, 1: the layer is
  // shown at the resolution it was rendered at).
  double sigma_max = 1.0;
  double sigma_min = 1.0;
  // Visibility: the polygon turned between front- and back-facing since its render (the
  // signed area of its projection changed sign).
  bool facing_changed = false;
};

struct AffineFit {
  Mat3 warp{1.0};  // A: image pixels as rendered -> image pixels now
  FitFiducials fiducials;
};

// Fits A = least_squares_affine(rendered, current) and measures its fiducials. `rendered`:
// the polygon's vertices in the image when its layer was rendered; `current`: the same
// vertices' exact projections now (same order). Same preconditions as least_squares_affine.
AffineFit fit_rendered_polygon(const std::vector<Vec2>& rendered, const std::vector<Vec2>& current);

// Twice the signed area of a polygon (shoelace formula), units squared; its sign says the
// vertices' turning direction.
double signed_area2(const std::vector<Vec2>& polygon);

}  // namespace oflab
