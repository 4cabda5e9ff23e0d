// Eq. 20 and corrected eq. 55 (manual/flow-math.md section 5).
#include "flow/decomposition.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "flow/named_values.h"

namespace oflab {
namespace {

struct Normalised {
  double a, b, c, d, e, f, g, h;
};

Normalised normalised_entries(const Mat3& w) {
  for (int r = 0; r < 3; ++r) {
    for (int col = 0; col < 3; ++col) {
      if (!std::isfinite(entry(w, r, col))) {
        throw std::invalid_argument("homography has a non-finite entry");
      }
    }
  }
  const double w33 = entry(w, 2, 2);
  double scale = 0.0;
  for (int i = 0; i < 3; ++i) scale = std::max(scale, std::abs(entry(w, 2, i)));
  if (std::abs(w33) <= 1e-12 * scale || w33 == 0.0) {
    throw std::invalid_argument(
        "homography sends the source origin to infinity (W33 = 0): it cannot be decomposed");
  }
  const Mat3 n = w * (1.0 / w33);
  return {entry(n, 0, 0), entry(n, 0, 1), entry(n, 0, 2), entry(n, 1, 0),
          entry(n, 1, 1), entry(n, 1, 2), entry(n, 2, 0), entry(n, 2, 1)};
}

glm::dmat2 jacobian_of(const Normalised& n) {
  // glm::dmat2 is column-major: columns (A11, A21) and (A12, A22).
  return glm::dmat2(n.a - n.c * n.g, n.d - n.f * n.g, n.b - n.c * n.h, n.e - n.f * n.h);
}

// Jacobian (2x2, column-major) of homography h at point p.
glm::dmat2 homography_jacobian(const Mat3& h, const Vec2& p) {
  const Vec3 q = h * Vec3(p, 1.0);
  const Vec2 u(q.x / q.z, q.y / q.z);
  const double g = entry(h, 2, 0), k = entry(h, 2, 1);
  return glm::dmat2((entry(h, 0, 0) - u.x * g) / q.z, (entry(h, 1, 0) - u.y * g) / q.z,
                    (entry(h, 0, 1) - u.x * k) / q.z, (entry(h, 1, 1) - u.y * k) / q.z);
}

}  // namespace

Mat3 affine_part_at(const Mat3& h, const Vec2& p) {
  const glm::dmat2 j = homography_jacobian(h, p);
  const Vec2 t = apply_homography(h, p) - j * p;
  return mat3_from_rows({j[0][0], j[1][0], t.x}, {j[0][1], j[1][1], t.y}, {0.0, 0.0, 1.0});
}

double largest_singular_value(const Mat3& m) {
  const glm::dmat2 a(entry(m, 0, 0), entry(m, 1, 0), entry(m, 0, 1), entry(m, 1, 1));
  const glm::dmat2 ata = glm::transpose(a) * a;
  const double tr = ata[0][0] + ata[1][1], det = glm::determinant(ata);
  return std::sqrt(0.5 * tr + std::sqrt(std::max(0.0, 0.25 * tr * tr - det)));
}

TranslateLinearPerspective decompose_translate_linear_perspective(const Mat3& w) {
  const Normalised n = normalised_entries(w);
  const glm::dmat2 a = jacobian_of(n);
  TranslateLinearPerspective out;
  out.translation = translation_matrix(n.c, n.f);
  out.linear = mat3_from_rows({a[0][0], a[1][0], 0.0}, {a[0][1], a[1][1], 0.0}, {0.0, 0.0, 1.0});
  out.perspective = mat3_from_rows({1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {n.g, n.h, 1.0});
  return out;
}

glm::dmat2 origin_jacobian(const Mat3& w) { return jacobian_of(normalised_entries(w)); }

namespace {

// Every policy with its name, in the order of the enum.
constexpr NamedValue<DeltaPolicy> kDeltaNames[] = {{DeltaPolicy::kOne, "1"},
                                                   {DeltaPolicy::kAbsDet, "det"},
                                                   {DeltaPolicy::kSqrtAbsDet, "sqrt"},
                                                   {DeltaPolicy::kFourthRootAbsDet, "fourth-root"},
                                                   {DeltaPolicy::kDissertation, "dissertation"}};

}  // namespace

bool parse_delta_policy(const std::string& text, DeltaPolicy* policy) {
  if (text == "one") {
    *policy = DeltaPolicy::kOne;
    return true;
  }
  return parse_named_value(kDeltaNames, text, policy);
}

const char* delta_policy_name(DeltaPolicy policy) {
  return name_of_value(kDeltaNames, policy, "1");
}

std::string delta_policy_name_list(const std::string& separator) {
  return named_value_list(kDeltaNames, separator);
}

const std::vector<DeltaPolicy>& delta_policies() {
  static const std::vector<DeltaPolicy> policies = [] {
    std::vector<DeltaPolicy> all;
    for (const NamedValue<DeltaPolicy>& d : kDeltaNames) all.push_back(d.value);
    return all;
  }();
  return policies;
}

double delta_for(DeltaPolicy policy, double det_a) {
  const double m = std::abs(det_a);
  if (!std::isfinite(m) || m == 0.0) return 1.0;
  switch (policy) {
    case DeltaPolicy::kOne:
      return 1.0;
    case DeltaPolicy::kAbsDet:
      return m;
    case DeltaPolicy::kSqrtAbsDet:
      return std::sqrt(m);
    case DeltaPolicy::kFourthRootAbsDet:
      return std::sqrt(std::sqrt(m));
    case DeltaPolicy::kDissertation:
      return m < 1.0 ? std::sqrt(m) : 1.0;
  }
  return 1.0;
}

AffinePerspectiveSplit split_affine_perspective(const Mat3& w, DeltaPolicy policy) {
  const Normalised n = normalised_entries(w);
  const glm::dmat2 a = jacobian_of(n);
  const double delta = delta_for(policy, glm::determinant(a));
  AffinePerspectiveSplit out;
  out.delta = delta;
  out.perspective = mat3_from_rows({delta, 0.0, 0.0}, {0.0, delta, 0.0}, {n.g, n.h, 1.0});
  out.affine = mat3_from_rows({a[0][0] / delta, a[1][0] / delta, n.c},
                              {a[0][1] / delta, a[1][1] / delta, n.f}, {0.0, 0.0, 1.0});
  return out;
}

}  // namespace oflab
