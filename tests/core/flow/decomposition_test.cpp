// Eq. 20 and the corrected eq. 55 multiply back to the original homography; each Delta
// policy scales the cached step as documented (Jacobian of W_persp at the origin = D I).
#include "flow/decomposition.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

namespace oflab {
namespace {

Mat3 random_homography(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  return mat3_from_rows({1.0 + 0.5 * u(rng), 0.4 * u(rng), 50.0 * u(rng)},
                        {0.4 * u(rng), 1.0 + 0.5 * u(rng), 50.0 * u(rng)},
                        {1e-3 * u(rng), 1e-3 * u(rng), 1.0 + 0.2 * u(rng)});
}

double max_entry_difference(const Mat3& a, const Mat3& b) {
  double m = 0.0;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m = std::max(m, std::abs(entry(a, r, c) - entry(b, r, c)));
  return m;
}

TEST(Decomposition, TranslateLinearPerspectiveMultipliesBack) {
  std::mt19937 rng(41);
  for (int i = 0; i < 200; ++i) {
    const Mat3 w = random_homography(rng);
    const TranslateLinearPerspective d = decompose_translate_linear_perspective(w);
    EXPECT_LT(
        max_entry_difference(d.translation * d.linear * d.perspective, normalise_homography(w)),
        1e-12);
  }
}

TEST(Decomposition, AffinePerspectiveSplitMultipliesBackForEveryDeltaPolicy) {
  std::mt19937 rng(42);
  const DeltaPolicy policies[] = {DeltaPolicy::kOne, DeltaPolicy::kAbsDet, DeltaPolicy::kSqrtAbsDet,
                                  DeltaPolicy::kFourthRootAbsDet, DeltaPolicy::kDissertation};
  for (int i = 0; i < 100; ++i) {
    const Mat3 w = random_homography(rng);
    for (DeltaPolicy p : policies) {
      const AffinePerspectiveSplit s = split_affine_perspective(w, p);
      EXPECT_LT(max_entry_difference(s.affine * s.perspective, normalise_homography(w)), 1e-12);
      EXPECT_EQ(entry(s.affine, 2, 0), 0.0);
      EXPECT_EQ(entry(s.affine, 2, 1), 0.0);
    }
  }
}

// Jacobian of a homography at a point, by central differences (independent of the split).
glm::dmat2 numeric_jacobian(const Mat3& h, const Vec2& p) {
  const double e = 1e-6;
  const Vec2 dx =
      (apply_homography(h, p + Vec2(e, 0)) - apply_homography(h, p - Vec2(e, 0))) / (2 * e);
  const Vec2 dy =
      (apply_homography(h, p + Vec2(0, e)) - apply_homography(h, p - Vec2(0, e))) / (2 * e);
  return glm::dmat2(dx, dy);
}

TEST(Decomposition, EachDeltaPolicyScalesTheCachedStepAsDocumented) {
  std::mt19937 rng(43);
  for (int i = 0; i < 100; ++i) {
    const Mat3 w = random_homography(rng);
    const double det_a = glm::determinant(numeric_jacobian(w, Vec2(0.0)));
    const struct {
      DeltaPolicy policy;
      double want;
    } cases[] = {
        {DeltaPolicy::kOne, 1.0},
        {DeltaPolicy::kAbsDet, std::abs(det_a)},
        {DeltaPolicy::kSqrtAbsDet, std::sqrt(std::abs(det_a))},
        {DeltaPolicy::kFourthRootAbsDet, std::pow(std::abs(det_a), 0.25)},
        {DeltaPolicy::kDissertation, std::abs(det_a) < 1 ? std::sqrt(std::abs(det_a)) : 1}};
    for (const auto& c : cases) {
      const AffinePerspectiveSplit s = split_affine_perspective(w, c.policy);
      EXPECT_NEAR(s.delta, c.want, 1e-6);
      const glm::dmat2 j = numeric_jacobian(s.perspective, Vec2(0.0));
      EXPECT_NEAR(j[0][0], s.delta, 1e-6);
      EXPECT_NEAR(j[1][1], s.delta, 1e-6);
      EXPECT_NEAR(j[0][1], 0.0, 1e-6);
      EXPECT_NEAR(j[1][0], 0.0, 1e-6);
      // Area factors: cache delta^2, affine det A / delta^2.
      EXPECT_NEAR(glm::determinant(glm::dmat2(glm::dmat3(s.affine))), det_a / (s.delta * s.delta),
                  1e-6);
    }
  }
}

TEST(Decomposition, SqrtPolicyMakesTheAffinePartAreaPreserving) {
  const Mat3 w = mat3_from_rows({0.7, 0.1, 5.0}, {-0.05, 0.9, -3.0}, {2e-4, -1e-4, 1.0});
  const AffinePerspectiveSplit s = split_affine_perspective(w, DeltaPolicy::kSqrtAbsDet);
  EXPECT_NEAR(std::abs(glm::determinant(glm::dmat2(glm::dmat3(s.affine)))), 1.0, 1e-12);
}

TEST(Decomposition, RejectsOriginSentToInfinityAndNonFiniteMatrices) {
  const Mat3 at_infinity = mat3_from_rows({1, 0, 0}, {0, 1, 0}, {0.1, 0, 0});
  EXPECT_THROW(split_affine_perspective(at_infinity, DeltaPolicy::kOne), std::invalid_argument);
  Mat3 nan_matrix(1.0);
  entry(nan_matrix, 0, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(decompose_translate_linear_perspective(nan_matrix), std::invalid_argument);
}

TEST(Decomposition, DeltaPolicyNamesParseBack) {
  for (DeltaPolicy p : {DeltaPolicy::kOne, DeltaPolicy::kAbsDet, DeltaPolicy::kSqrtAbsDet,
                        DeltaPolicy::kFourthRootAbsDet, DeltaPolicy::kDissertation}) {
    DeltaPolicy q = DeltaPolicy::kOne;
    ASSERT_TRUE(parse_delta_policy(delta_policy_name(p), &q));
    EXPECT_EQ(p, q);
  }
  DeltaPolicy q;
  EXPECT_FALSE(parse_delta_policy("half", &q));
}

TEST(Decomposition, DeltaPolicyNameListJoinsEveryPolicyInOrder) {
  EXPECT_EQ(delta_policy_name_list(), "1, det, sqrt, fourth-root, dissertation");
  EXPECT_EQ(delta_policy_name_list("|"), "1|det|sqrt|fourth-root|dissertation");
  ASSERT_EQ(delta_policies().size(), 5u);
  EXPECT_EQ(delta_policies().front(), DeltaPolicy::kOne);
  EXPECT_EQ(delta_policies().back(), DeltaPolicy::kDissertation);
  DeltaPolicy q = DeltaPolicy::kDissertation;
  EXPECT_TRUE(parse_delta_policy("one", &q));
  EXPECT_EQ(q, DeltaPolicy::kOne);
}

}  // namespace
}  // namespace oflab
