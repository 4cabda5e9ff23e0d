// The plain-C++ side of the views: flow parts, basis catalogue, scene parameters, colours.
// Checked against independent computations (finite differences of core's exact
// projection, exact rotations), never against numbers copied from the code.
#include <gtest/gtest.h>

#include <cmath>

#include "basis/basis_catalog.h"
#include "display/flow_parts.h"
#include "display/palette.h"
#include "flow/homography.h"
#include "flow/plane_scene.h"
#include "models/scene_parameters.h"

namespace oflab {
namespace {

FlowContext demo_context() {
  const PlaneScene s = default_demo_scene();
  return make_flow_context(s.camera, s.pose, s.motion);
}

// Image position of the plane point seen at p after time t (exact rigid step).
Vec2 moved_image_point(const FlowContext& c, const Vec2& p, double t) {
  const Vec3 point = plane_point_at_pixel(c.pose, c.camera.focal_px, p);
  const RigidStep step = rigid_step(c.motion, c.pose, t);
  return project_centred(c.camera, step.rotation * point + step.translation);
}

TEST(FlowParts, FullFlowMatchesFiniteDifferencesOfTheExactMotion) {
  const FlowContext c = demo_context();
  const double h = 1e-5;
  for (const Vec2& p : {Vec2(30, -20), Vec2(-60, 10), Vec2(80, 40)}) {
    const Vec2 fd = (moved_image_point(c, p, h) - moved_image_point(c, p, -h)) / (2 * h);
    const Vec2 v = flow_part_at(c, FlowPart::kFull, p);
    EXPECT_NEAR(glm::length(v - fd), 0.0, 1e-5 * glm::length(fd)) << p.x << "," << p.y;
  }
}

TEST(FlowParts, TheThreeOrdersAddUpToTheFullFlowOfAPlane) {
  const FlowContext c = demo_context();
  for (const Vec2& p : {Vec2(30, -20), Vec2(-60, 10), Vec2(80, 40)}) {
    const Vec2 sum = flow_part_at(c, FlowPart::kTranslation, p) +
                     flow_part_at(c, FlowPart::kFirstOrder, p) +
                     flow_part_at(c, FlowPart::kSecondOrder, p);
    const Vec2 full = flow_part_at(c, FlowPart::kFull, p);
    EXPECT_NEAR(glm::length(sum - full), 0.0, 1e-9 * glm::length(full));
  }
}

TEST(FlowParts, ResidualAgainstTheHomographyFlowIsRoundingOnly) {
  const FlowContext c = demo_context();
  const auto full = sample_flow_grid(c, FlowPart::kFull, 10.0);
  const auto residual = sample_flow_grid(c, FlowPart::kExactMinusHomography, 10.0);
  ASSERT_FALSE(full.empty());
  EXPECT_LT(max_flow_magnitude(residual), 1e-9 * max_flow_magnitude(full));
}

TEST(FlowParts, HomographyFlowIsTheTimeDerivativeOfTheTaylorHomography) {
  // The residual's reference: d/dt of H1(t) p at t = 0, by central differences.
  const FlowContext c = demo_context();
  const double h = 1e-6;
  const Vec2 p(50, -30);
  const Vec2 fd = (apply_homography(taylor_homography(c.coefficients, h), p) -
                   apply_homography(taylor_homography(c.coefficients, -h), p)) /
                  (2 * h);
  const Vec2 residual = flow_part_at(c, FlowPart::kExactMinusHomography, p);
  const Vec2 exact = flow_part_at(c, FlowPart::kFull, p);
  EXPECT_NEAR(glm::length(exact - fd - residual), 0.0, 1e-5 * glm::length(exact));
}

TEST(FlowParts, ResidualAgainstTheAffineFlowIsTheSecondOrderPart) {
  const FlowContext c = demo_context();
  const Vec2 p(-70, 45);
  const Vec2 residual = flow_part_at(c, FlowPart::kExactMinusAffine, p);
  const Vec2 second = flow_part_at(c, FlowPart::kSecondOrder, p);
  EXPECT_NEAR(glm::length(residual - second), 0.0, 1e-9 * glm::length(second));
  EXPECT_GT(glm::length(second), 0.1);  // the demo plane is not fronto-parallel
}

TEST(FlowParts, SeesPlaneInsideItsImageOnly) {
  const FlowContext c = demo_context();
  const auto corners = projected_corners(c.camera, c.pose);
  const Vec2 centre = 0.25 * (corners[0] + corners[1] + corners[2] + corners[3]);
  EXPECT_TRUE(sees_plane(c, centre));
  EXPECT_FALSE(sees_plane(c, corners[0] + 1.2 * (corners[0] - centre)));
  EXPECT_FALSE(sees_plane(c, Vec2(390, 290)));
}

TEST(FlowParts, StreamlineOfATranslationIsAStraightSegment) {
  const FlowContext c = demo_context();
  const Vec2 seed(20, 0);
  const double t = 0.05;
  const auto path = trace_streamline(c, FlowPart::kTranslation, seed, t, 10);
  ASSERT_EQ(path.size(), 11u);
  const Vec2 expected = seed + t * Vec2(c.coefficients.tx, c.coefficients.ty);
  EXPECT_NEAR(glm::length(path.back() - expected), 0.0, 1e-9);
}

TEST(FlowParts, StreamlineArrowHeadPointsAlongTheLastStep) {
  const FlowContext c = demo_context();
  const auto path = trace_streamline(c, FlowPart::kFull, Vec2(10, -5), 0.2, 16);
  ASSERT_GE(path.size(), 3u);
  const auto head = streamline_arrow_head(path, 12.0);
  ASSERT_EQ(head.size(), 3u);
  EXPECT_EQ(head[1], path.back());
  const Vec2 forward = glm::normalize(path.back() - path[path.size() - 2]);
  for (const Vec2& wing : {head[0], head[2]}) {
    EXPECT_NEAR(glm::length(wing - head[1]), 12.0, 1e-9);
    // Behind the tip, at 25 degrees from the line: cos 25 = 0.9063.
    EXPECT_NEAR(glm::dot(head[1] - wing, forward) / 12.0, std::cos(25.0 * M_PI / 180.0), 1e-9);
  }
  // The wings lie on opposite sides of the line.
  const auto side = [&](const Vec2& w) {
    const Vec2 d = w - head[1];
    return forward.x * d.y - forward.y * d.x;
  };
  EXPECT_LT(side(head[0]) * side(head[2]), 0.0);
  EXPECT_TRUE(streamline_arrow_head({Vec2(1, 1)}, 5.0).empty());
  EXPECT_TRUE(streamline_arrow_head({Vec2(1, 1), Vec2(1, 1)}, 5.0).empty());
}

TEST(FlowParts, StreamlineStopsAtThePlaneOutline) {
  const FlowContext c = demo_context();
  // Long enough to travel 2000 px at the translation's speed: far beyond the plane.
  const double speed = glm::length(Vec2(c.coefficients.tx, c.coefficients.ty));
  const auto path = trace_streamline(c, FlowPart::kTranslation, Vec2(20, 0), 2000.0 / speed, 100);
  ASSERT_GE(path.size(), 2u);
  EXPECT_LT(path.size(), 101u);
  for (const Vec2& p : path) EXPECT_TRUE(sees_plane(c, p));
}

TEST(FlowParts, PartKeysRoundTrip) {
  for (int k = 0; k < kFlowPartCount; ++k) {
    FlowPart part = FlowPart::kFull;
    ASSERT_TRUE(parse_flow_part(flow_part_key(FlowPart(k)), &part));
    EXPECT_EQ(part, FlowPart(k));
  }
  FlowPart part = FlowPart::kSecondOrder;
  EXPECT_FALSE(parse_flow_part("affine", &part));
  EXPECT_EQ(part, FlowPart::kSecondOrder);
}

TEST(BasisCatalog, EachUnitTermReadsBackAsOneAndTheOthersAsZero) {
  for (int k = 0; k < kBasisKindCount; ++k) {
    const auto terms = basis_terms(BasisKind(k));
    ASSERT_EQ(terms.size(), 12u);
    for (size_t i = 0; i < terms.size(); ++i) {
      for (size_t j = 0; j < terms.size(); ++j) {
        EXPECT_NEAR(terms[j].coefficient(terms[i].unit), i == j ? 1.0 : 0.0, 1e-12)
            << basis_key(BasisKind(k)) << " " << terms[i].symbol << " -> " << terms[j].symbol;
      }
    }
  }
}

TEST(BasisCatalog, UnitTermFlowHasTheTermsOrder) {
  // Doubling the distance scales a term's flow by 2^order.
  for (int k = 0; k < kBasisKindCount; ++k) {
    for (const BasisTerm& term : basis_terms(BasisKind(k))) {
      const Vec2 near = taylor_flow_at(term.unit, Vec2(0.3, -0.2));
      const Vec2 far = taylor_flow_at(term.unit, Vec2(0.6, -0.4));
      EXPECT_NEAR(glm::length(far), std::pow(2.0, term.order) * glm::length(near), 1e-12)
          << term.symbol;
    }
  }
}

int active_second_order(BasisKind kind, const TaylorTerms& flow) {
  int count = 0;
  for (const BasisTerm& term : basis_terms(kind)) {
    if (term.order == 2 && !is_negligible(2, term.coefficient(flow), 500.0)) ++count;
  }
  return count;
}

TEST(BasisCatalog, APlaneExcitesTwoPlanarFourTaylorAndSixWaxmanUllmanSecondOrderTerms) {
  const TaylorTerms flow = demo_context().terms;
  EXPECT_EQ(active_second_order(BasisKind::kPlanar, flow), 2);
  EXPECT_EQ(active_second_order(BasisKind::kTaylor, flow), 4);
  EXPECT_EQ(active_second_order(BasisKind::kWaxmanUllman, flow), 6);
}

TEST(SceneParameters, OrientationRoundTripsTheNormal) {
  for (const Vec3& n : {Vec3(0.25, -0.15, 1.0), Vec3(0, 0, 1), Vec3(-0.7, 0.3, 0.2)}) {
    const Vec3 back = normal_of(orientation_of(n));
    EXPECT_NEAR(glm::length(back - glm::normalize(n)), 0.0, 1e-12);
  }
  const PlaneOrientation facing = orientation_of(Vec3(0, 0, 2));
  EXPECT_DOUBLE_EQ(facing.turn_deg, 0.0);
  EXPECT_DOUBLE_EQ(facing.tilt_deg, 0.0);
}

TEST(SceneParameters, ChangingDistanceKeepsTheCentresImage) {
  const PlaneScene s = default_demo_scene();
  const PlanePose moved = with_centre_depth(s.pose, 5.0);
  EXPECT_DOUBLE_EQ(moved.point.z, 5.0);
  const Vec2 before = project_centred(s.camera, s.pose.point);
  const Vec2 after = project_centred(s.camera, moved.point);
  EXPECT_NEAR(glm::length(after - before), 0.0, 1e-12);
}

TEST(Palette, WheelHueFollowsDirectionAndWhiteMeansNoFlow) {
  const Rgb8 right = flow_wheel_colour(Vec2(1, 0), 1.0);
  EXPECT_EQ(right.r, 255);
  EXPECT_LT(right.g, 10);
  const Rgb8 still = flow_wheel_colour(Vec2(0, 0), 1.0);
  EXPECT_EQ(still.r, 255);
  EXPECT_EQ(still.g, 255);
  EXPECT_EQ(still.b, 255);
  const Rgb8 left = flow_wheel_colour(Vec2(-1, 0), 1.0);  // cyan
  EXPECT_LT(left.r, 10);
  EXPECT_EQ(left.b, 255);
}

TEST(Palette, LevelColoursAreDistinct) {
  for (int a = 0; a < kLevelCount; ++a) {
    for (int b = a + 1; b < kLevelCount; ++b) {
      const Rgb8 x = level_colour(Level(a)), y = level_colour(Level(b));
      EXPECT_FALSE(x.r == y.r && x.g == y.g && x.b == y.b);
    }
  }
}

}  // namespace
}  // namespace oflab
