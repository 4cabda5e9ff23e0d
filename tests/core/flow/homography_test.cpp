// Homographies against independent computations: exact projections of moved corners.
#include "flow/homography.h"

#include <gtest/gtest.h>

#include <random>

#include "random_cases.h"

namespace oflab {
namespace {

using testing::FlowCase;

std::array<Vec2, 4> corners_after(const FlowCase& c, double dt) {
  return projected_corners(c.camera, advance_pose(c.pose, rigid_step(c.motion, c.pose, dt)));
}

double taylor_corner_error(const FlowCase& c, double dt) {
  const Mat3 h = taylor_homography(planar_flow_coefficients(c.camera, c.pose, c.motion), dt);
  return max_corner_distance(h, projected_corners(c.camera, c.pose), corners_after(c, dt));
}

TEST(Homography, TaylorHomographyErrorShrinksQuadratically) {
  std::mt19937 rng(21);
  for (int i = 0; i < 100; ++i) {
    const FlowCase c = testing::random_flow_case(rng, i);
    const double e1 = taylor_corner_error(c, 0.02);
    const double e2 = taylor_corner_error(c, 0.01);
    if (e1 < 1e-9) continue;  // motions with no second-order-in-time residual
    EXPECT_NEAR(e1 / e2, 4.0, 0.4) << "case " << i;
  }
}

TEST(Homography, ExactHomographyMapsCornersToTheirExactImages) {
  std::mt19937 rng(22);
  for (int i = 0; i < 200; ++i) {
    const FlowCase c = testing::random_flow_case(rng, i);
    const double dt = 0.05 + 0.1 * (i % 4);
    const Mat3 h = exact_homography(c.camera, c.pose, c.motion, dt);
    EXPECT_LT(max_corner_distance(h, projected_corners(c.camera, c.pose), corners_after(c, dt)),
              1e-8);
  }
}

TEST(Homography, TimeDerivativeOfExactHomographyIsTheFlow) {
  std::mt19937 rng(23);
  for (int i = 0; i < 100; ++i) {
    const FlowCase c = testing::random_flow_case(rng, i);
    const PlanarFlowCoefficients k = planar_flow_coefficients(c.camera, c.pose, c.motion);
    const double h = 1e-5;
    const Mat3 hp = exact_homography(c.camera, c.pose, c.motion, h);
    const Mat3 hm = exact_homography(c.camera, c.pose, c.motion, -h);
    for (const Vec2& p : testing::sample_plane_pixels(c)) {
      const Vec2 v = (apply_homography(hp, p) - apply_homography(hm, p)) / (2.0 * h);
      EXPECT_LT(glm::length(v - flow_at(k, p)), 1e-5 * std::max(1.0, glm::length(v)));
    }
  }
}

TEST(Homography, TaylorHomographyAboutAnotherOriginAlsoConvergesQuadratically) {
  std::mt19937 rng(24);
  for (int i = 0; i < 50; ++i) {
    const FlowCase c = testing::random_flow_case(rng, i);
    const PlanarFlowCoefficients k = planar_flow_coefficients(c.camera, c.pose, c.motion);
    const PlanarFlowCoefficients r = reexpand(k, project_centred(c.camera, c.pose.point));
    auto error = [&](double dt) {
      return max_corner_distance(taylor_homography(r, dt), projected_corners(c.camera, c.pose),
                                 corners_after(c, dt));
    };
    if (error(0.02) < 1e-9) continue;
    EXPECT_NEAR(error(0.02) / error(0.01), 4.0, 0.4) << "case " << i;
  }
}

TEST(Homography, TextureToImageSendsTexelCornersToProjectedCorners) {
  std::mt19937 rng(25);
  for (int i = 0; i < 100; ++i) {
    FlowCase c = testing::random_flow_case(rng, i);
    c.pose.texture_size = glm::ivec2(243, 198);
    const Mat3 h = texture_to_image(c.camera, c.pose);
    const std::array<Vec2, 4> texel_corners = {Vec2(0, 0), Vec2(243, 0), Vec2(243, 198),
                                               Vec2(0, 198)};
    EXPECT_LT(max_corner_distance(h, texel_corners, projected_corners(c.camera, c.pose)), 1e-9);
  }
}

TEST(Homography, DefaultCaseCornerErrorsMatchTheWorkedExample) {
  const FlowCase c = testing::default_case();
  const ApproximationErrors e = approximation_corner_errors(c.camera, c.pose, c.motion, 1.0 / 30.0);
  EXPECT_NEAR(e.none, 11.80, 0.01);
  EXPECT_NEAR(e.translate, 3.50, 0.01);
  EXPECT_NEAR(e.affine, 0.458, 0.001);
  EXPECT_NEAR(e.taylor, 0.105, 0.001);
  EXPECT_LT(max_corner_distance(exact_homography(c.camera, c.pose, c.motion, 1.0 / 30.0),
                                projected_corners(c.camera, c.pose), corners_after(c, 1.0 / 30.0)),
            1e-9);
}

TEST(Homography, PixelHomographyIsTheCentredOneShifted) {
  const FlowCase c = testing::default_case();
  const Mat3 h = exact_homography(c.camera, c.pose, c.motion, 0.1);
  const Mat3 hp = centred_to_pixel_homography(c.camera, h);
  const Vec2 p(13.0, -40.0);
  const Vec2 want = centred_to_pixel(c.camera, apply_homography(h, p));
  const Vec2 got = apply_homography(hp, centred_to_pixel(c.camera, p));
  EXPECT_LT(glm::length(got - want), 1e-9);
}

}  // namespace
}  // namespace oflab
