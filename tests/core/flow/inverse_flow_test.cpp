// From the eight planar flow coefficients back to planes and motions: every solution maps
// forward, through planar_flow_coefficients, to the same coefficients; one of them is the
// plane and motion that made the flow; the named degenerate cases; the two solutions
// played forward agree at first and then separate.
#include "flow/inverse_flow.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>

#include "flow/basis.h"
#include "random_cases.h"

namespace oflab {
namespace {

using testing::FlowCase;

// The coefficients in the units of the flow matrix (tx/f, ty/f, J, f px, f py), so that one
// relative error covers all eight.
std::array<double, 8> in_matrix_units(const PlanarFlowCoefficients& c, double f) {
  return {c.tx / f, c.ty / f, c.j11, c.j12, c.j21, c.j22, f * c.px, f * c.py};
}

// Largest coefficient difference over the largest coefficient, both in matrix units.
double relative_difference(const PlanarFlowCoefficients& got, const PlanarFlowCoefficients& want,
                           double f) {
  const auto g = in_matrix_units(got, f);
  const auto w = in_matrix_units(want, f);
  double diff = 0.0, size = 0.0;
  for (int i = 0; i < 8; ++i) {
    diff = std::max(diff, std::abs(g[i] - w[i]));
    size = std::max(size, std::abs(w[i]));
  }
  return size == 0.0 ? diff : diff / size;
}

// The coefficients a solution makes, through core's forward formulas, with the plane placed
// where `pixel` sees it.
PlanarFlowCoefficients forward(const PlanarMotionSolution& s, const Camera& camera,
                               const Vec2& pixel, MotionModel model) {
  const SolutionScene scene = solution_scene(s, camera.focal_px, pixel, model, 2.5);
  EXPECT_TRUE(plane_pose_problem(scene.pose).field.empty());
  return planar_flow_coefficients(camera, scene.pose, scene.motion);
}

// The solution that made the flow of `c`: unit N with N.P > 0, V/d, Omega.
PlanarMotionSolution truth(const FlowCase& c) {
  PlanarMotionSolution s;
  s.normal = glm::normalize(c.pose.normal);
  if (glm::dot(s.normal, c.pose.point) < 0.0) s.normal = -s.normal;
  const double d = glm::dot(s.normal, c.pose.point);
  s.v_over_d = eye_velocity(c.motion, c.pose) / d;
  s.omega = c.motion.omega;
  return s;
}

double solution_distance(const PlanarMotionSolution& a, const PlanarMotionSolution& b) {
  return std::max({glm::length(a.normal - b.normal), glm::length(a.v_over_d - b.v_over_d),
                   glm::length(a.omega - b.omega)});
}

Vec2 centre_pixel(const FlowCase& c) { return project_centred(c.camera, c.pose.point); }

TEST(InverseFlow, EverySolutionMapsForwardToTheCoefficientsAndOneIsTheTruth) {
  std::mt19937 rng(3131);
  int general = 0, rotations = 0, edge_on = 0;
  double worst_forward = 0.0, worst_truth = 0.0;
  for (int i = 0; i < 1800; ++i) {
    const FlowCase c = testing::random_flow_case(rng, i);
    ASSERT_TRUE(plane_pose_problem(c.pose).field.empty());
    const PlanarFlowCoefficients k = planar_flow_coefficients(c.camera, c.pose, c.motion);
    const Vec2 at = centre_pixel(c);
    const InverseFlowSolutions r = solve_inverse_flow(k, c.camera.focal_px, at);
    if (eye_velocity(c.motion, c.pose) == Vec3(0.0)) {  // not for a spin about the centre
      ++rotations;
      ASSERT_EQ(r.kind, InverseFlowCase::kPureRotation) << "case " << i;
    } else if (c.motion.model == MotionModel::kSpinAboutCentre && c.motion.velocity == Vec3(0.0)) {
      // A spin about the plane's centre P: V = -Omega x P is across the line of sight to P,
      // and the other solution's normal is along V, so its plane is seen exactly edge-on at
      // P's pixel, the check pixel: counted as edge-on, neither in front nor behind.
      ++edge_on;
      ASSERT_EQ(r.kind, InverseFlowCase::kGeneral) << "case " << i;
      ASSERT_EQ(r.solutions.size(), 1u) << "case " << i;
      EXPECT_EQ(r.dropped_behind, 1);
      EXPECT_EQ(r.edge_on, 1);
    } else {
      ++general;
      ASSERT_EQ(r.kind, InverseFlowCase::kGeneral) << "case " << i;
      ASSERT_EQ(r.solutions.size(), 2u) << "case " << i;
      EXPECT_EQ(r.dropped_behind, 2);
      EXPECT_EQ(r.edge_on, 0);
    }
    const PlanarMotionSolution want = truth(c);
    double nearest = 1e300;
    for (const PlanarMotionSolution& s : r.solutions) {
      for (MotionModel model : {MotionModel::kScrew, MotionModel::kSpinAboutCentre}) {
        const double e = relative_difference(forward(s, c.camera, at, model), k, c.camera.focal_px);
        worst_forward = std::max(worst_forward, e);
        EXPECT_LT(e, 1e-12) << "case " << i;
      }
      if (!s.normal_known) continue;
      EXPECT_NEAR(glm::length(s.normal), 1.0, 1e-14);
      EXPECT_GT(glm::dot(s.normal, Vec3(at / c.camera.focal_px, 1.0)), 0.0);  // in front
      EXPECT_GT(s.depth_over_d, 0.0);
      nearest = std::min(nearest, solution_distance(s, want));
    }
    if (r.kind == InverseFlowCase::kPureRotation) {
      EXPECT_LT(glm::length(r.solutions[0].omega - c.motion.omega), 1e-14);
      EXPECT_EQ(r.solutions[0].v_over_d, Vec3(0.0));
    } else {
      worst_truth = std::max(worst_truth, nearest);
      EXPECT_LT(nearest, 1e-9) << "case " << i;
    }
  }
  EXPECT_GE(general, 1000);
  EXPECT_GE(rotations, 300);
  EXPECT_GE(edge_on, 100);
  std::ostringstream worst;
  worst << "forward " << worst_forward << ", truth " << worst_truth;
  RecordProperty("worst", worst.str());
}

TEST(InverseFlow, AnExpansionPointOtherThanThePrincipalPointGivesTheSameSolutions) {
  const FlowCase c = testing::default_case();
  const PlanarFlowCoefficients k = planar_flow_coefficients(c.camera, c.pose, c.motion);
  const InverseFlowSolutions at_origin = solve_inverse_flow(k, c.camera.focal_px);
  const InverseFlowSolutions moved =
      solve_inverse_flow(reexpand(k, Vec2(120.0, -75.0)), c.camera.focal_px);
  ASSERT_EQ(moved.solutions.size(), 2u);
  for (int i = 0; i < 2; ++i) {
    EXPECT_LT(solution_distance(moved.solutions[i], at_origin.solutions[i]), 1e-12);
  }
}

TEST(InverseFlow, TheMirrorImageThroughTheEyeMakesTheSameFlowButLiesBehind) {
  const FlowCase c = testing::default_case();
  const PlanarFlowCoefficients k = planar_flow_coefficients(c.camera, c.pose, c.motion);
  const InverseFlowSolutions r = solve_inverse_flow(k, c.camera.focal_px);
  ASSERT_EQ(r.solutions.size(), 2u);
  EXPECT_EQ(r.dropped_behind, 2);
  for (const PlanarMotionSolution& s : r.solutions) {
    // B = [Omega]x + (V/d) N^T is unchanged by (N, V/d) -> (-N, -V/d) ...
    const Mat3 b = cross_matrix(s.omega) + glm::outerProduct(s.v_over_d, s.normal);
    const Mat3 mirror = cross_matrix(s.omega) + glm::outerProduct(-s.v_over_d, -s.normal);
    EXPECT_EQ(b, mirror);
    // ... but the mirrored plane -N.R = d meets the optical axis at negative depth.
    EXPECT_GT(s.normal.z, 0.0);
    EXPECT_NEAR(s.depth_over_d, 1.0 / s.normal.z, 1e-12);
  }
  // The roles of N and the direction of V/d swap between the two, |V/d| is shared, and so is
  // the diagonal of B: V1 N1/d, V2 N2/d and V3 N3/d = V3/Z0 (manual/theory.md section 10.3).
  const PlanarMotionSolution& one = r.solutions[0];
  const PlanarMotionSolution& two = r.solutions[1];
  EXPECT_NEAR(glm::length(one.v_over_d), glm::length(two.v_over_d), 1e-15);
  EXPECT_NEAR(std::abs(glm::dot(glm::normalize(one.v_over_d), two.normal)), 1.0, 1e-14);
  EXPECT_NEAR(std::abs(glm::dot(glm::normalize(two.v_over_d), one.normal)), 1.0, 1e-14);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(one.v_over_d[i] * one.normal[i], two.v_over_d[i] * two.normal[i], 1e-15);
  }
  // The two solutions are different worlds: different normals and different motions.
  EXPECT_GT(glm::length(r.solutions[0].normal - r.solutions[1].normal), 0.1);
  EXPECT_GT(glm::length(r.solutions[0].omega - r.solutions[1].omega), 0.01);
}

// The table of manual/theory.md section 10.1 (the dissertation's table of section 4.8.1,
// redone): each planar basis term from V/Z0, Omega and the slopes dZ/dX, dZ/dY.
TEST(InverseFlow, BasisTermsFromMotionAndSlopesAsInTheTheoryTable) {
  std::mt19937 rng(41);
  for (int i = 0; i < 200; ++i) {
    FlowCase c = testing::random_flow_case(rng, 3 * i);  // N3 != 0
    c.motion.model = MotionModel::kScrew;
    if (i % 4 == 1) c.motion.velocity = Vec3(0.0, 0.0, c.motion.velocity.z);  // along Z only
    const PlanarBasisTerms b =
        to_planar_basis(taylor_terms(planar_flow_coefficients(c.camera, c.pose, c.motion)));
    const double f = c.camera.focal_px;
    const Vec3 n = c.pose.normal;
    const double z0 = glm::dot(n, c.pose.point) / n.z;  // where the plane meets the Z axis
    const double sx = -n.x / n.z, sy = -n.y / n.z;      // dZ/dX, dZ/dY (eq. 38)
    const Vec3 v = c.motion.velocity / z0;
    const Vec3 w = c.motion.omega;
    EXPECT_NEAR(b.tx, f * (v.x + w.y), 1e-10);
    EXPECT_NEAR(b.ty, f * (v.y - w.x), 1e-10);
    EXPECT_NEAR(b.scale, -v.z - 0.5 * (sx * v.x + sy * v.y), 1e-13);
    EXPECT_NEAR(b.squash, 0.5 * (sx * v.x - sy * v.y), 1e-13);
    EXPECT_NEAR(b.shear, -0.5 * (sy * v.x + sx * v.y), 1e-13);
    EXPECT_NEAR(b.rotation, w.z + 0.5 * (sy * v.x - sx * v.y), 1e-13);
    EXPECT_NEAR(b.px, (w.y + sx * v.z) / f, 1e-15);
    EXPECT_NEAR(b.py, (-w.x + sy * v.z) / f, 1e-15);
    if (i % 4 == 1) {  // moving only along the line of sight: no squash, no shear
      EXPECT_NEAR(b.squash, 0.0, 1e-15);
      EXPECT_NEAR(b.shear, 0.0, 1e-15);
    }
  }
}

TEST(InverseFlow, PureRotationLeavesThePlaneUnobservable) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 50; ++i) {
    FlowCase c = testing::random_flow_case(rng, i);
    c.motion.velocity = Vec3(0.0);
    c.motion.model = MotionModel::kScrew;
    const PlanarFlowCoefficients k = planar_flow_coefficients(c.camera, c.pose, c.motion);
    const InverseFlowSolutions r = solve_inverse_flow(k, c.camera.focal_px);
    EXPECT_EQ(r.kind, InverseFlowCase::kPureRotation);
    ASSERT_EQ(r.solutions.size(), 1u);
    EXPECT_FALSE(r.solutions[0].normal_known);
    EXPECT_EQ(r.dropped_behind, 0);
    EXPECT_LT(glm::length(r.solutions[0].omega - c.motion.omega), 1e-14);
    // Any plane at all makes the same flow.
    PlanarMotionSolution other = r.solutions[0];
    other.normal = glm::normalize(Vec3(u(rng), u(rng), 2.0));
    other.normal_known = true;
    EXPECT_LT(relative_difference(forward(other, c.camera, Vec2(0.0), MotionModel::kScrew), k,
                                  c.camera.focal_px),
              1e-12);
  }
  // No motion at all is the pure rotation with Omega = 0.
  const InverseFlowSolutions still = solve_inverse_flow(PlanarFlowCoefficients{}, 500.0);
  EXPECT_EQ(still.kind, InverseFlowCase::kPureRotation);
  EXPECT_EQ(still.solutions.at(0).omega, Vec3(0.0));
  EXPECT_STREQ(inverse_flow_case_name(still.kind), "pure-rotation");
}

TEST(InverseFlow, TranslationAlongTheNormalHasOneSolution) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 200; ++i) {
    FlowCase c = testing::random_flow_case(rng, 3 * i);  // a tilted plane, N3 != 0
    c.motion.model = MotionModel::kScrew;
    const double speed = (i % 2 ? 1.0 : -1.0) * (0.1 + 0.4 * std::abs(u(rng)));  // both ways
    c.motion.velocity = speed * glm::normalize(c.pose.normal);
    const PlanarFlowCoefficients k = planar_flow_coefficients(c.camera, c.pose, c.motion);
    const Vec2 at = centre_pixel(c);
    const InverseFlowSolutions r = solve_inverse_flow(k, c.camera.focal_px, at);
    EXPECT_EQ(r.kind, InverseFlowCase::kTranslationAlongNormal) << "case " << i;
    ASSERT_EQ(r.solutions.size(), 1u) << "case " << i;
    EXPECT_EQ(r.dropped_behind, 1);
    // Near this case the solutions are sensitive: rounding of order 1e-16 in the coefficients
    // moves N and V/d by its square root, about 1e-8. The forward map stays exact.
    EXPECT_LT(solution_distance(r.solutions[0], truth(c)), 1e-7) << "case " << i;
    EXPECT_LT(relative_difference(forward(r.solutions[0], c.camera, at, MotionModel::kScrew), k,
                                  c.camera.focal_px),
              1e-12);
  }
  EXPECT_STREQ(inverse_flow_case_name(InverseFlowCase::kTranslationAlongNormal),
               "translation-along-normal");
}

TEST(InverseFlow, FrontoParallelPlaneMovingAlongItsNormalIsNamed) {
  for (double v3 : {-0.4, 0.25}) {
    FlowCase c = testing::default_case();
    c.pose.normal = Vec3(0.0, 0.0, 1.0);
    c.motion.velocity = Vec3(0.0, 0.0, v3);
    c.motion.omega = Vec3(0.1, -0.2, 0.3);  // rotation does not change the case
    const PlanarFlowCoefficients k = planar_flow_coefficients(c.camera, c.pose, c.motion);
    const InverseFlowSolutions r = solve_inverse_flow(k, c.camera.focal_px);
    EXPECT_EQ(r.kind, InverseFlowCase::kFrontoParallelAlongNormal);
    ASSERT_EQ(r.solutions.size(), 1u);
    EXPECT_LT(solution_distance(r.solutions[0], truth(c)), 1e-12);
    EXPECT_NEAR(r.solutions[0].depth_over_d, 1.0, 1e-15);
  }
  // Typed-in coefficients: a pure expansion at 0.1 per second.
  PlanarFlowCoefficients k;
  k.j11 = k.j22 = 0.1;
  const InverseFlowSolutions r = solve_inverse_flow(k, 600.0);
  EXPECT_EQ(r.kind, InverseFlowCase::kFrontoParallelAlongNormal);
  ASSERT_EQ(r.solutions.size(), 1u);
  EXPECT_EQ(r.solutions[0].normal, Vec3(0.0, 0.0, 1.0));
  EXPECT_NEAR(r.solutions[0].v_over_d.z, -0.1, 1e-15);  // approaching: V3/Z0 = -0.1
  EXPECT_STREQ(inverse_flow_case_name(r.kind), "fronto-parallel-along-normal");
}

TEST(InverseFlow, ASidewaysTranslationOfAFacingPlaneHasItsOtherSolutionEdgeOnAtTheAxis) {
  // The plane Z = 2 facing the eye, moving sideways at V = (0.064, 0, 0): tx = f V1 / Z =
  // 500 * 0.032 = 16 px, every other coefficient 0 (`explain --coefficients 16 0 0 0 0 0 0 0
  // --focal 500`).
  PlanarFlowCoefficients k;
  k.tx = 16.0;
  const InverseFlowSolutions r = solve_inverse_flow(k, 500.0);
  EXPECT_EQ(r.kind, InverseFlowCase::kGeneral);
  ASSERT_EQ(r.solutions.size(), 1u);
  EXPECT_EQ(r.dropped_behind, 1);  // the facing plane's mirror, Z = -d
  EXPECT_EQ(r.edge_on, 1);         // the other plane is parallel to the optical axis
  // Exact zeros, not rounding noise (3.5e-18 before).
  const PlanarMotionSolution& facing = r.solutions[0];
  EXPECT_EQ(facing.normal, Vec3(0.0, 0.0, 1.0));
  EXPECT_NEAR(facing.v_over_d.x, 0.032, 1e-16);
  EXPECT_EQ(facing.v_over_d.y, 0.0);
  EXPECT_EQ(facing.v_over_d.z, 0.0);
  EXPECT_EQ(facing.omega, Vec3(0.0));
  // Seen from a pixel off the axis, the other solution is there: the plane X = d (normal
  // along X), moving along the optical axis, with the rotation that keeps the same flow.
  const InverseFlowSolutions off_axis = solve_inverse_flow(k, 500.0, Vec2(100.0, 0.0));
  ASSERT_EQ(off_axis.solutions.size(), 2u);
  EXPECT_EQ(off_axis.edge_on, 0);
  bool found = false;
  for (const PlanarMotionSolution& s : off_axis.solutions) {
    if (std::abs(s.normal.x - 1.0) > 1e-15) continue;
    found = true;
    EXPECT_EQ(s.normal.y, 0.0);
    EXPECT_EQ(s.normal.z, 0.0);
    EXPECT_NEAR(s.v_over_d.z, 0.032, 1e-16);
    // By hand: B = [Omega]x + (V/d) N^T must be B13 = tx / f = 0.032 and zero elsewhere.
    // (V/d) N^T puts 0.032 at B31; [Omega]x has B13 = Omega2 and B31 = -Omega2, so
    // Omega = (0, 0.032, 0).
    EXPECT_EQ(s.omega.x, 0.0);
    EXPECT_NEAR(s.omega.y, 0.032, 1e-16);
    EXPECT_EQ(s.omega.z, 0.0);
  }
  EXPECT_TRUE(found);
}

TEST(InverseFlow, TranslationAlongTheNormalIsNamedWithin63MicroradiansOnly) {
  // V at angle phi from a tilted plane's normal, built from the angle (not from the solver's
  // eigenvalues): one solution up to kInverseFlowAngleTolerance = 2 sqrt(1e-9), two beyond.
  EXPECT_NEAR(kInverseFlowAngleTolerance, 2.0 * std::sqrt(kInverseFlowTolerance), 1e-18);
  FlowCase c = testing::default_case();
  c.motion.model = MotionModel::kScrew;
  c.motion.omega = Vec3(0.05, -0.02, 0.01);
  const Vec3 n = glm::normalize(c.pose.normal);
  const Vec3 across = glm::normalize(glm::cross(n, Vec3(0.0, 1.0, 0.0)));
  for (double phi : {0.0, 3e-5, 6.0e-5, 6.6e-5, 1e-4, 1e-3}) {
    c.motion.velocity = 0.3 * (std::cos(phi) * n + std::sin(phi) * across);
    const PlanarFlowCoefficients k = planar_flow_coefficients(c.camera, c.pose, c.motion);
    const InverseFlowSolutions r = solve_inverse_flow(k, c.camera.focal_px, centre_pixel(c));
    const bool named = phi <= kInverseFlowAngleTolerance;
    EXPECT_EQ(r.kind == InverseFlowCase::kTranslationAlongNormal, named) << "phi " << phi;
    EXPECT_EQ(r.solutions.size(), named ? 1u : 2u) << "phi " << phi;
  }
}

TEST(InverseFlow, RefusesNonFiniteInput) {
  PlanarFlowCoefficients k;
  EXPECT_THROW(solve_inverse_flow(k, 0.0), std::invalid_argument);
  EXPECT_THROW(solve_inverse_flow(k, std::nan("")), std::invalid_argument);
  k.py = std::numeric_limits<double>::infinity();
  EXPECT_THROW(solve_inverse_flow(k, 500.0), std::invalid_argument);
}

// The images of the plane's corners under both solutions, played forward frame by frame.
FutureSeparation default_case_futures(const FlowCase& c, double dt, int frames) {
  const PlanarFlowCoefficients k = planar_flow_coefficients(c.camera, c.pose, c.motion);
  const Vec2 at = centre_pixel(c);
  const InverseFlowSolutions r = solve_inverse_flow(k, c.camera.focal_px, at);
  EXPECT_EQ(r.solutions.size(), 2u);
  std::array<Vec2, 4> corners;
  const auto world = plane_corners(c.pose);
  for (int i = 0; i < 4; ++i) corners[i] = project_centred(c.camera, world[i]);
  return compare_futures(r.solutions[0], r.solutions[1], c.camera.focal_px, at, corners,
                         c.motion.model, dt, frames, 1.0);
}

TEST(InverseFlow, TheTwoSolutionsAgreeAtTheFirstFrameAndThenSeparate) {
  const FlowCase c = testing::default_case();
  const FutureSeparation s = default_case_futures(c, 1.0 / 30.0, 300);
  ASSERT_GE(s.corner_distance_px.size(), 2u);
  EXPECT_LT(s.corner_distance_px[0], 1e-9);
  EXPECT_LT(s.corner_distance_px[1], 0.01);  // the same flow: apart only at second order
  ASSERT_GT(s.first_frame_apart, 1);         // and yet the futures differ
  EXPECT_GT(s.corner_distance_px[s.first_frame_apart], 1.0);
  for (int f = 0; f < s.first_frame_apart; ++f) EXPECT_LE(s.corner_distance_px[f], 1.0);
  RecordProperty("first_frame_apart", s.first_frame_apart);
  // The recorded corner images give the recorded distances, frame by frame.
  ASSERT_EQ(s.corner_images_px.size(), s.corner_distance_px.size());
  for (size_t f = 0; f < s.corner_images_px.size(); ++f) {
    double worst = 0.0;
    for (int i = 0; i < 4; ++i) {
      worst =
          std::max(worst, glm::length(s.corner_images_px[f][0][i] - s.corner_images_px[f][1][i]));
    }
    EXPECT_DOUBLE_EQ(worst, s.corner_distance_px[f]) << f;
  }
  // Second order in dt: halving the step quarters the first frame's distance.
  const FutureSeparation half = default_case_futures(c, 1.0 / 60.0, 2);
  EXPECT_NEAR(half.corner_distance_px[1] / s.corner_distance_px[1], 0.25, 0.02);
}

TEST(InverseFlow, TheTrueSolutionPlayedForwardIsThePlaneItself) {
  // Independent of compare_futures' bookkeeping: one world played against itself never
  // separates, and the true solution's corner images follow the real plane's corners.
  const FlowCase c = testing::default_case();
  const PlanarFlowCoefficients k = planar_flow_coefficients(c.camera, c.pose, c.motion);
  const Vec2 at = centre_pixel(c);
  const InverseFlowSolutions r = solve_inverse_flow(k, c.camera.focal_px, at);
  std::array<Vec2, 4> corners;
  const auto world = plane_corners(c.pose);
  for (int i = 0; i < 4; ++i) corners[i] = project_centred(c.camera, world[i]);
  for (const PlanarMotionSolution& s : r.solutions) {
    const FutureSeparation same =
        compare_futures(s, s, c.camera.focal_px, at, corners, c.motion.model, 0.1, 20, 1e-9);
    EXPECT_EQ(same.first_frame_apart, -1);
    EXPECT_EQ(same.frames_played, 20);
  }
  const PlanarMotionSolution want = truth(c);
  const auto& real =
      solution_distance(r.solutions[0], want) < 1e-9 ? r.solutions[0] : r.solutions[1];
  // The real plane moved 30 frames, and the true solution's scene (scaled by the real d).
  const double d = glm::dot(want.normal, c.pose.point);
  SolutionScene scene = solution_scene(real, c.camera.focal_px, at, c.motion.model, d);
  PlanePose pose = c.pose;
  for (int f = 0; f < 30; ++f) {
    pose = advance_pose(pose, rigid_step(c.motion, pose, 1.0 / 30.0));
    scene.pose = advance_pose(scene.pose, rigid_step(scene.motion, scene.pose, 1.0 / 30.0));
  }
  EXPECT_LT(glm::length(scene.pose.point - pose.point), 1e-9);
  EXPECT_LT(glm::length(glm::normalize(scene.pose.normal) - glm::normalize(pose.normal)), 1e-9);
}

}  // namespace
}  // namespace oflab
