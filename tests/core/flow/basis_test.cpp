// The three bases: conversions are exact inverses, and a plane excites only px, py at
// second order. Derivatives are checked against finite differences of the flow itself.
#include "flow/basis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "random_cases.h"

namespace oflab {
namespace {

TaylorTerms random_terms(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  TaylorTerms t;
  double* fields[] = {&t.v1,    &t.v2,    &t.v1_x,  &t.v1_y,  &t.v2_x,  &t.v2_y,
                      &t.v1_xx, &t.v1_xy, &t.v1_yy, &t.v2_xx, &t.v2_xy, &t.v2_yy};
  for (double* f : fields) *f = u(rng);
  return t;
}

void expect_same(const TaylorTerms& a, const TaylorTerms& b) {
  const Vec2 pts[] = {{0, 0}, {1, 0}, {0, 1}, {2, -3}, {-1.5, 0.5}, {4, 4}};
  for (const Vec2& p : pts) {
    EXPECT_LT(glm::length(taylor_flow_at(a, p) - taylor_flow_at(b, p)), 1e-12);
  }
}

TEST(Basis, WaxmanUllmanConversionRoundTrips) {
  std::mt19937 rng(31);
  for (int i = 0; i < 100; ++i) {
    const TaylorTerms t = random_terms(rng);
    expect_same(from_waxman_ullman(to_waxman_ullman(t)), t);
  }
}

TEST(Basis, PlanarBasisConversionRoundTrips) {
  std::mt19937 rng(32);
  for (int i = 0; i < 100; ++i) {
    const TaylorTerms t = random_terms(rng);
    expect_same(from_planar_basis(to_planar_basis(t)), t);
  }
}

TEST(Basis, TaylorTermsAreTheFlowDerivatives) {
  std::mt19937 rng(33);
  for (int i = 0; i < 50; ++i) {
    const auto c = testing::random_flow_case(rng, i);
    // Expand about the image of the plane centre, where the plane is certainly seen.
    const Vec2 o = project_centred(c.camera, c.pose.point);
    const PlanarFlowCoefficients k =
        reexpand(planar_flow_coefficients(c.camera, c.pose, c.motion), o);
    const TaylorTerms t = taylor_terms(k);
    const double h = 1.0;  // the flow is quadratic, so central differences are exact
    auto v = [&](double x, double y) {
      return exact_flow_at(c.camera, c.pose, c.motion, o + Vec2(x, y));
    };
    const Vec2 dx = (v(h, 0) - v(-h, 0)) / (2 * h);
    const Vec2 dy = (v(0, h) - v(0, -h)) / (2 * h);
    const Vec2 dxx = (v(h, 0) - 2.0 * v(0, 0) + v(-h, 0)) / (h * h);
    const Vec2 dyy = (v(0, h) - 2.0 * v(0, 0) + v(0, -h)) / (h * h);
    const Vec2 dxy = (v(h, h) - v(h, -h) - v(-h, h) + v(-h, -h)) / (4 * h * h);
    const double tol = 1e-7 * std::max(1.0, std::abs(t.v1_x) + std::abs(t.v2_y));
    EXPECT_NEAR(t.v1_x, dx.x, tol);
    EXPECT_NEAR(t.v2_x, dx.y, tol);
    EXPECT_NEAR(t.v1_y, dy.x, tol);
    EXPECT_NEAR(t.v2_y, dy.y, tol);
    EXPECT_NEAR(t.v1_xx, dxx.x, tol);
    EXPECT_NEAR(t.v2_xx, dxx.y, tol);
    EXPECT_NEAR(t.v1_yy, dyy.x, tol);
    EXPECT_NEAR(t.v2_yy, dyy.y, tol);
    EXPECT_NEAR(t.v1_xy, dxy.x, tol);
    EXPECT_NEAR(t.v2_xy, dxy.y, tol);
  }
}

TEST(Basis, APlaneExcitesOnlyTwoSecondOrderTerms) {
  std::mt19937 rng(34);
  for (int i = 0; i < 100; ++i) {
    const auto c = testing::random_flow_case(rng, i);
    const PlanarFlowCoefficients k = planar_flow_coefficients(c.camera, c.pose, c.motion);
    const PlanarBasisTerms p = to_planar_basis(taylor_terms(k));
    EXPECT_EQ(p.v1_yy, 0.0);
    EXPECT_EQ(p.v2_xx, 0.0);
    EXPECT_NEAR(p.non_planar_x, 0.0, 1e-18);
    EXPECT_NEAR(p.non_planar_y, 0.0, 1e-18);
    EXPECT_DOUBLE_EQ(p.px, k.px);
    EXPECT_DOUBLE_EQ(p.py, k.py);
    const PlanarFlowCoefficients back = planar_coefficients(p);
    EXPECT_NEAR(back.j12, k.j12, 1e-12 * std::max(1.0, std::abs(k.j12)));
    EXPECT_NEAR(back.j21, k.j21, 1e-12 * std::max(1.0, std::abs(k.j21)));
  }
}

TEST(Basis, FirstOrderPlanarBasisMatchesTheDissertationsExpressions) {
  // scale = (n1 V1 + n2 V2)/2 - n3 V3, rotation = Omega3 + (n1 V2 - n2 V1)/2.
  std::mt19937 rng(35);
  for (int i = 0; i < 50; ++i) {
    const auto c = testing::random_flow_case(rng, i);
    const Vec3 n = plane_vector(c.pose);
    const Vec3 v = eye_velocity(c.motion, c.pose);
    const PlanarBasisTerms p =
        to_planar_basis(taylor_terms(planar_flow_coefficients(c.camera, c.pose, c.motion)));
    EXPECT_NEAR(p.scale, 0.5 * (n.x * v.x + n.y * v.y) - n.z * v.z, 1e-12);
    EXPECT_NEAR(p.rotation, c.motion.omega.z + 0.5 * (n.x * v.y - n.y * v.x), 1e-12);
  }
}

}  // namespace
}  // namespace oflab
