// One test per corrected erratum of chapters 4-5 (numbers as in manual/theory.md#errata).
// Each shows that the printed form disagrees with an independent computation and the
// corrected form agrees. Errata 22-27 belong to the engine, 28-30 to the warp kernels.
#include <gtest/gtest.h>

#include <random>

#include "flow/basis.h"
#include "flow/decomposition.h"
#include "flow/homography.h"
#include "random_cases.h"

namespace oflab {
namespace {

using testing::FlowCase;

PlanarFlowCoefficients coefficients(const FlowCase& c) {
  return planar_flow_coefficients(c.camera, c.pose, c.motion);
}

TEST(Errata, Erratum03TaylorSecondOrderTermNeedsOneHalf) {
  const FlowCase c = testing::default_case();
  const TaylorTerms t = taylor_terms(coefficients(c));
  const Vec2 p(120.0, -70.0);
  const Vec2 exact = exact_flow_at(c.camera, c.pose, c.motion, p);
  EXPECT_LT(glm::length(taylor_flow_at(t, p) - exact), 1e-9);
  // As printed: the quadratic part without the factor 1/2.
  const Vec2 printed =
      taylor_flow_at(t, p) +
      0.5 * Vec2(t.v1_xx * p.x * p.x + 2 * t.v1_xy * p.x * p.y + t.v1_yy * p.y * p.y,
                 t.v2_xx * p.x * p.x + 2 * t.v2_xy * p.x * p.y + t.v2_yy * p.y * p.y);
  EXPECT_GT(glm::length(printed - exact), 1.0);
}

TEST(Errata, Erratum06And09StrainAndSpinUseTheRightDerivatives) {
  const WaxmanUllmanTerms w = to_waxman_ullman(taylor_terms(coefficients(testing::default_case())));
  const PlanarFlowCoefficients k = coefficients(testing::default_case());
  EXPECT_DOUBLE_EQ(w.e_yy, k.j22);  // dv2/dy, not v2 itself
  EXPECT_NE(w.e_yy, k.ty);
  EXPECT_DOUBLE_EQ(w.omega, 0.5 * (k.j21 - k.j12));     // curl / 2
  const double printed_omega = 0.5 * (-k.j11 + k.j22);  // eq. 36 as printed: equals squash
  EXPECT_GT(std::abs(printed_omega - w.omega), 0.1);
}

TEST(Errata, Erratum07DepthUsesFocalLengthTimesN3) {
  const FlowCase c = testing::default_case();
  const Vec2 p(150.0, 80.0);
  const double f = c.camera.focal_px;
  const Vec3 r = plane_point_at_pixel(c.pose, f, p);
  const Vec3 n = c.pose.normal;
  const double z0 = glm::dot(n, c.pose.point) / n.z;
  EXPECT_NEAR(r.z, f * z0 * n.z / (p.x * n.x + p.y * n.y + f * n.z), 1e-12);
}

TEST(Errata, Erratum08PerspectiveTermsAreQuarterAndHalfCombinations) {
  const PlanarFlowCoefficients k = coefficients(testing::default_case());
  const TaylorTerms t = taylor_terms(k);
  EXPECT_DOUBLE_EQ(0.25 * t.v1_xx + 0.5 * t.v2_xy, k.px);
  const double printed_px = 0.5 * t.v2_yy + t.v1_xy;  // = 2 py: labels swapped, factor 2
  EXPECT_NEAR(printed_px, 2.0 * k.py, 1e-18);
  EXPECT_GT(std::abs(printed_px - k.px), 1e-4);
}

TEST(Errata, Erratum10PerspectiveTermPxComesFromOmega2AndPyFromOmega1) {
  FlowCase c = testing::default_case();
  c.motion.velocity = Vec3(0.0);
  c.motion.omega = Vec3(0.0, 0.5, 0.0);
  PlanarFlowCoefficients k = coefficients(c);
  EXPECT_NEAR(k.px, 0.5 / c.camera.focal_px, 1e-15);
  EXPECT_EQ(k.py, 0.0);
  c.motion.omega = Vec3(0.5, 0.0, 0.0);
  k = coefficients(c);
  EXPECT_EQ(k.px, 0.0);
  EXPECT_NEAR(k.py, -0.5 / c.camera.focal_px, 1e-15);
}

TEST(Errata, Erratum12RotationAboutTheAxisEntersV2WithPlusSign) {
  FlowCase c = testing::default_case();
  c.motion.velocity = Vec3(0.0);
  c.motion.omega = Vec3(0.0, 0.0, 0.7);
  const double h = 1.0;
  const Vec2 d = (exact_flow_at(c.camera, c.pose, c.motion, {h, 0}) -
                  exact_flow_at(c.camera, c.pose, c.motion, {-h, 0})) /
                 (2 * h);
  EXPECT_NEAR(d.y, +0.7, 1e-12);  // v2 = ... + x Omega3
}

TEST(Errata, Erratum15AccelerationIsNotOrderOmegaSquared) {
  FlowCase c = testing::default_case();
  c.pose.point = Vec3(0.0, 0.0, 2.0);
  c.pose.normal = Vec3(0.0, 0.0, 1.0);
  c.motion.velocity = Vec3(0.0, 0.0, -0.4);  // approaching, no rotation
  c.motion.omega = Vec3(0.0);
  const Vec2 p(50.0, -30.0);
  const Vec2 a = image_acceleration(c.camera, c.pose, c.motion, p);
  const double k = 2.0 * (0.4 / 2.0) * (0.4 / 2.0);  // 2 (V3/Z0)^2
  EXPECT_NEAR(a.x, k * p.x, 1e-12);
  EXPECT_NEAR(a.y, k * p.y, 1e-12);
}

// Eq. 52/53 and Algorithm 1 as printed: bottom row (+px t, +py t, 1).
Mat3 printed_sign_homography(const PlanarFlowCoefficients& c, double dt) {
  Mat3 h = taylor_homography(c, dt);
  entry(h, 2, 0) = -entry(h, 2, 0);
  entry(h, 2, 1) = -entry(h, 2, 1);
  return h;
}

TEST(Errata, Erratum16And17PrintedPerspectiveSignMakesTheErrorFirstOrder) {
  const FlowCase c = testing::default_case();
  const PlanarFlowCoefficients k = coefficients(c);
  auto error = [&](const Mat3& h, double dt) {
    return max_corner_distance(
        h, projected_corners(c.camera, c.pose),
        projected_corners(c.camera, advance_pose(c.pose, rigid_step(c.motion, c.pose, dt))));
  };
  const double dt = 1.0 / 30.0;
  const double corrected_ratio =
      error(taylor_homography(k, dt), dt) / error(taylor_homography(k, dt / 2), dt / 2);
  const double printed_ratio =
      error(printed_sign_homography(k, dt), dt) / error(printed_sign_homography(k, dt / 2), dt / 2);
  EXPECT_NEAR(corrected_ratio, 4.0, 0.2);
  EXPECT_NEAR(printed_ratio, 2.0, 0.2);
  EXPECT_NEAR(error(printed_sign_homography(k, dt), dt), 0.976, 0.002);
}

TEST(Errata, Erratum18OffsetAddedToTheHomogeneousVectorIsNotProjective) {
  const FlowCase c = testing::default_case();
  const Mat3 w = texture_to_image(c.camera, c.pose);
  const AffinePerspectiveSplit s = split_affine_perspective(w, DeltaPolicy::kSqrtAbsDet);
  const Vec2 texel(200.0, 30.0);
  const Vec2 want = apply_homography(w, texel);
  // Corrected: translation inside W_aff.
  EXPECT_LT(glm::length(apply_homography(s.affine * s.perspective, texel) - want), 1e-9);
  // Printed: W_aff (no translation) * W_persp * x + (c', f', 0) before the division.
  Mat3 linear_only = s.affine;
  entry(linear_only, 0, 2) = entry(linear_only, 1, 2) = 0.0;
  const Vec3 q = linear_only * s.perspective * Vec3(texel, 1.0) +
                 Vec3(entry(s.affine, 0, 2), entry(s.affine, 1, 2), 0.0);
  EXPECT_GT(glm::length(Vec2(q.x / q.z, q.y / q.z) - want), 2.0);
}

TEST(Errata, Erratum19SqrtDeltaPutsAllScalingInTheCache) {
  const FlowCase c = testing::default_case();
  const Mat3 w = texture_to_image(c.camera, c.pose);
  const double det_a = glm::determinant(origin_jacobian(w));
  const AffinePerspectiveSplit s = split_affine_perspective(w, DeltaPolicy::kSqrtAbsDet);
  // Area factor of W_persp at the origin is delta^2 = |det A|: all of it.
  EXPECT_NEAR(s.delta * s.delta, std::abs(det_a), 1e-12);
  const AffinePerspectiveSplit d = split_affine_perspective(w, DeltaPolicy::kAbsDet);
  EXPECT_NEAR(d.delta * d.delta, det_a * det_a, 1e-12);  // over-shrunk, not "all"
}

TEST(Errata, Erratum20And21InitialHomographyUsesRightUpAndPosition) {
  const FlowCase c = testing::default_case();
  const PlaneAxes a = plane_axes(c.pose);
  // [R U N] is left-handed with R = N x U: never a rotation.
  EXPECT_NEAR(glm::determinant(Mat3(a.right, a.up, a.normal)), -1.0, 1e-12);
  // K [R U P] maps plane coordinates (s, r) to the projection of P + s R + r U.
  const Mat3 k_rup = centred_intrinsics(c.camera) * Mat3(a.right, a.up, c.pose.point);
  const Vec3 world = c.pose.point + 0.3 * a.right - 0.2 * a.up;
  EXPECT_LT(
      glm::length(apply_homography(k_rup, Vec2(0.3, -0.2)) - project_centred(c.camera, world)),
      1e-9);
}

}  // namespace
}  // namespace oflab
