// Talisman's least-squares affine warp and its fiducials (see core/engine/affine_fit.h).
#include "engine/affine_fit.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace oflab {
namespace {

Vec2 centroid(const std::vector<Vec2>& points) {
  Vec2 c(0.0);
  for (const Vec2& p : points) c += p;
  return c / static_cast<double>(points.size());
}

// Singular values (largest, smallest) of the 2x2 part of an affine map.
std::pair<double, double> singular_values(const Mat3& a) {
  const double m11 = entry(a, 0, 0), m12 = entry(a, 0, 1);
  const double m21 = entry(a, 1, 0), m22 = entry(a, 1, 1);
  // Of A^T A: trace and determinant.
  const double tr = m11 * m11 + m12 * m12 + m21 * m21 + m22 * m22;
  const double det = m11 * m22 - m12 * m21;
  const double root = std::sqrt(std::max(0.0, 0.25 * tr * tr - det * det));
  const double big = std::sqrt(0.5 * tr + root);
  const double small = std::sqrt(std::max(0.0, 0.5 * tr - root));
  return {big, small};
}

}  // namespace

Mat3 least_squares_affine(const std::vector<Vec2>& from, const std::vector<Vec2>& to) {
  if (from.size() != to.size() || from.size() < 3) {
    throw std::invalid_argument("affine fit: needs as many targets as vertices, at least 3");
  }
  const Vec2 f = centroid(from), g = centroid(to);
  double sxx = 0.0, sxy = 0.0, syy = 0.0;         // scatter of `from`
  double ux = 0.0, uy = 0.0, vx = 0.0, vy = 0.0;  // cross scatter, rows of (to - g)(from - f)^T
  for (size_t i = 0; i < from.size(); ++i) {
    const Vec2 d = from[i] - f, e = to[i] - g;
    sxx += d.x * d.x, sxy += d.x * d.y, syy += d.y * d.y;
    ux += e.x * d.x, uy += e.x * d.y, vx += e.y * d.x, vy += e.y * d.y;
  }
  const double det = sxx * syy - sxy * sxy;
  if (!(std::abs(det) > 1e-12 * std::max(1.0, sxx * syy))) {
    throw std::invalid_argument("affine fit: the rendered vertices are collinear");
  }
  // L = cross * scatter^-1, scatter^-1 = [[syy, -sxy], [-sxy, sxx]] / det.
  const double l11 = (ux * syy - uy * sxy) / det, l12 = (uy * sxx - ux * sxy) / det;
  const double l21 = (vx * syy - vy * sxy) / det, l22 = (vy * sxx - vx * sxy) / det;
  const Vec2 t(g.x - (l11 * f.x + l12 * f.y), g.y - (l21 * f.x + l22 * f.y));
  return mat3_from_rows({l11, l12, t.x}, {l21, l22, t.y}, {0.0, 0.0, 1.0});
}

double signed_area2(const std::vector<Vec2>& polygon) {
  double sum = 0.0;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const Vec2& a = polygon[i];
    const Vec2& b = polygon[(i + 1) % polygon.size()];
    sum += a.x * b.y - b.x * a.y;
  }
  return sum;
}

AffineFit fit_rendered_polygon(const std::vector<Vec2>& rendered,
                               const std::vector<Vec2>& current) {
  AffineFit fit;
  fit.warp = least_squares_affine(rendered, current);
  for (size_t i = 0; i < rendered.size(); ++i) {
    const Vec3 q = fit.warp * Vec3(rendered[i], 1.0);
    fit.fiducials.geometric_px =
        std::max(fit.fiducials.geometric_px, glm::length(Vec2(q.x, q.y) - current[i]));
  }
  const auto [big, small] = singular_values(fit.warp);
  fit.fiducials.sigma_max = big;
  fit.fiducials.sigma_min = small;
  fit.fiducials.facing_changed = signed_area2(rendered) * signed_area2(current) <= 0.0;
  return fit;
}

}  // namespace oflab
