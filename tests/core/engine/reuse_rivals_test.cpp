// The rival policies of the registry (manual/policies.md): Talisman's least-squares affine
// fit and fiducials against independent computations, and the dissertation's printed rule,
// one test per rule it keeps.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "engine/affine_fit.h"
#include "engine/decision.h"
#include "engine/engine.h"
#include "engine/reuse_policy.h"
#include "engine/script.h"
#include "flow/flow_field.h"

namespace oflab {
namespace {

// Solves the 3x3 system m x = b by Gaussian elimination with partial pivoting.
Vec3 solve3(double m[3][3], double b[3]) {
  for (int c = 0; c < 3; ++c) {
    int pivot = c;
    for (int r = c + 1; r < 3; ++r) {
      if (std::abs(m[r][c]) > std::abs(m[pivot][c])) pivot = r;
    }
    std::swap(m[c], m[pivot]);
    std::swap(b[c], b[pivot]);
    for (int r = c + 1; r < 3; ++r) {
      const double f = m[r][c] / m[c][c];
      for (int k = c; k < 3; ++k) m[r][k] -= f * m[c][k];
      b[r] -= f * b[c];
    }
  }
  double x[3];
  for (int r = 2; r >= 0; --r) {
    double s = b[r];
    for (int k = r + 1; k < 3; ++k) s -= m[r][k] * x[k];
    x[r] = s / m[r][r];
  }
  return Vec3(x[0], x[1], x[2]);
}

// The least-squares affine map from its normal equations: each output row (a, b, c)
// solves (M^T M)(a, b, c) = M^T u, M the rows (x, y, 1) of `from`, u one coordinate of `to`.
Mat3 normal_equations_fit(const std::vector<Vec2>& from, const std::vector<Vec2>& to) {
  Vec3 rows[2];
  for (int out = 0; out < 2; ++out) {
    double m[3][3] = {}, b[3] = {};
    for (size_t i = 0; i < from.size(); ++i) {
      const double v[3] = {from[i].x, from[i].y, 1.0};
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) m[r][c] += v[r] * v[c];
        b[r] += v[r] * (out == 0 ? to[i].x : to[i].y);
      }
    }
    rows[out] = solve3(m, b);
  }
  return mat3_from_rows(rows[0], rows[1], {0.0, 0.0, 1.0});
}

Vec2 apply(const Mat3& a, const Vec2& p) { return apply_homography(a, p); }

TEST(TalismanFit, EqualsTheNormalEquationsOnRandomPolygons) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-200.0, 200.0), noise(-6.0, 6.0);
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 3 + trial % 6;
    std::vector<Vec2> from, to;
    for (int i = 0; i < n; ++i) from.push_back(Vec2(u(rng), u(rng)));
    for (const Vec2& p : from) {
      to.push_back(Vec2(0.9 * p.x - 0.2 * p.y + 13.0 + noise(rng),
                        0.15 * p.x + 1.1 * p.y - 7.0 + noise(rng)));
    }
    const Mat3 fit = least_squares_affine(from, to);
    const Mat3 reference = normal_equations_fit(from, to);
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(entry(fit, r, c), entry(reference, r, c), 1e-7 * (c == 2 ? 100.0 : 1.0))
            << "trial " << trial << " entry " << r << "," << c;
      }
    }
    // Its geometric fiducial is the largest distance of a fitted vertex from its target.
    double worst = 0.0;
    for (int i = 0; i < n; ++i)
      worst = std::max(worst, glm::length(apply(reference, from[i]) - to[i]));
    EXPECT_NEAR(fit_rendered_polygon(from, to).fiducials.geometric_px, worst, 1e-7);
  }
}

TEST(TalismanFit, RefusesCollinearOrTooFewVertices) {
  EXPECT_THROW(least_squares_affine({Vec2(0, 0), Vec2(1, 1), Vec2(2, 2)},
                                    {Vec2(0, 0), Vec2(1, 0), Vec2(0, 1)}),
               std::invalid_argument);
  EXPECT_THROW(least_squares_affine({Vec2(0, 0), Vec2(1, 0)}, {Vec2(0, 0), Vec2(1, 0)}),
               std::invalid_argument);
}

TEST(TalismanFit, SamplingFiducialsAreTheSingularValuesOfAKnownWarp) {
  // A = R(a) diag(s1, s2) R(b): singular values s1, s2 whatever the rotations.
  const auto rot = [](double t) {
    return glm::dmat2(std::cos(t), std::sin(t), -std::sin(t), std::cos(t));
  };
  const std::vector<Vec2> square = {Vec2(0, 0), Vec2(100, 0), Vec2(100, 80), Vec2(0, 80)};
  const double cases[][4] = {{1.7, 0.6, 0.3, -1.1}, {0.4, 0.4, 2.0, 0.5}, {2.5, 1.0, 0.0, 0.0}};
  for (const auto& c : cases) {
    const glm::dmat2 a = rot(c[2]) * glm::dmat2(c[0], 0.0, 0.0, c[1]) * rot(c[3]);
    std::vector<Vec2> to;
    for (const Vec2& p : square) to.push_back(a * p + Vec2(5.0, -3.0));
    const FitFiducials f = fit_rendered_polygon(square, to).fiducials;
    EXPECT_NEAR(f.sigma_max, std::max(c[0], c[1]), 1e-9);
    EXPECT_NEAR(f.sigma_min, std::min(c[0], c[1]), 1e-9);
    EXPECT_NEAR(f.geometric_px, 0.0, 1e-9);
    EXPECT_FALSE(f.facing_changed);
  }
}

TEST(TalismanFit, VisibilityFiducialSeesAPolygonTurnOver) {
  const std::vector<Vec2> square = {Vec2(0, 0), Vec2(100, 0), Vec2(100, 80), Vec2(0, 80)};
  std::vector<Vec2> mirrored, turned;
  for (const Vec2& p : square) {
    mirrored.push_back(Vec2(200.0 - p.x, p.y));  // seen from behind
    turned.push_back(Vec2(-p.y, p.x));           // rotated a quarter turn, same side
  }
  EXPECT_TRUE(fit_rendered_polygon(square, mirrored).fiducials.facing_changed);
  EXPECT_FALSE(fit_rendered_polygon(square, turned).fiducials.facing_changed);
}

TEST(TalismanChoice, AnyFiducialOverItsLimitReRenders) {
  const ReusePolicy& p = reuse_policy("talisman");
  FrameInputs in;
  in.thresholds = {1.0, 1.0, 0.75, 1.0};
  in.fit = FitFiducials{0.7, 1.2, 0.9, false};
  EXPECT_EQ(p.choose(p, in), Level::kAffine);
  const auto with = [&](auto change) {
    FrameInputs changed = in;
    change(changed.fit);
    return p.choose(p, changed);
  };
  EXPECT_EQ(with([](FitFiducials& f) { f.geometric_px = 0.76; }), Level::kRerender);
  EXPECT_EQ(with([](FitFiducials& f) { f.sigma_max = 2.01; }), Level::kRerender);
  EXPECT_EQ(with([](FitFiducials& f) { f.sigma_min = 0.49; }), Level::kRerender);
  EXPECT_EQ(with([](FitFiducials& f) { f.sigma_max = 1.9, f.sigma_min = 0.9; }),
            Level::kRerender);  // anisotropy 2.1
  EXPECT_EQ(with([](FitFiducials& f) { f.facing_changed = true; }), Level::kRerender);
}

Layer checker_texture(int w, int h) {
  Image img(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      img.at(x, y) = ((x / 8) + (y / 8)) % 2 ? Pixel{40, 40, 160, 255} : Pixel{230, 200, 60, 255};
    }
  }
  return make_layer(std::move(img));
}

PlanePose facing_pose(double depth) {
  PlanePose p;
  p.point = Vec3(0.1, -0.05, depth);
  p.normal = Vec3(0.0, 0.0, 1.0);
  p.up = Vec3(0.0, -1.0, 0.0);
  p.size = Vec2(0.96, 0.64);
  p.texture_size = glm::ivec2(96, 64);
  return p;
}

std::vector<Vec2> corners_through(const Mat3& warp) {
  return {apply(warp, Vec2(0, 0)), apply(warp, Vec2(96, 0)), apply(warp, Vec2(96, 64)),
          apply(warp, Vec2(0, 64))};
}

// In the engine, every reused frame shows the fit of the corners as last rendered onto their
// exact projections: its measured error (from where the pixels are) is the fit's corner
// error, computed here from the normal equations.
TEST(TalismanEngine, ShownErrorIsTheFitsCornerErrorAndStaysWithinTheThreshold) {
  const Camera cam = make_camera(300.0, 320, 240);
  const auto frames = expand_segments(facing_pose(2.0), MotionModel::kScrew,
                                      {{60, Vec3(0.004, 0.002, -0.01), Vec3(0.004, 0.006, 0.01)}});
  EngineSettings s;
  s.policy = &reuse_policy("talisman");
  PlaneEngine a(cam, checker_texture(96, 64), s);
  Mat3 rendered(1.0);
  int reused = 0, rerendered = 0;
  for (size_t i = 0; i < frames.size(); ++i) {
    const FrameReport r = i == 0
                              ? a.start(frames[0].pose)
                              : a.advance(frames[i - 1].pose, frames[i - 1].motion, frames[i].pose);
    const Mat3 exact = exact_texture_warp(cam, frames[i].pose);
    if (r.level == Level::kRerender) {
      rendered = exact;
      ++rerendered;
      continue;
    }
    ASSERT_EQ(r.level, Level::kAffine) << "frame " << i;
    ++reused;
    const std::vector<Vec2> from = corners_through(rendered), to = corners_through(exact);
    const Mat3 fit = normal_equations_fit(from, to);
    double worst = 0.0;
    for (size_t c = 0; c < from.size(); ++c)
      worst = std::max(worst, glm::length(apply(fit, from[c]) - to[c]));
    EXPECT_NEAR(r.measured_error_px, worst, 1e-6) << "frame " << i;
    EXPECT_NEAR(r.estimated_error_px, worst, 1e-6) << "frame " << i;
    EXPECT_LE(r.measured_error_px, s.thresholds[2] + 1e-9) << "frame " << i;
  }
  EXPECT_GT(reused, 10);
  EXPECT_GT(rerendered, 1);
}

// Printed rule 1: each term against its own threshold; the highest term over its threshold
// picks the level (k + 1), even when a lower term is over its own too.
TEST(DissertationRule, CascadeTestsEachTermAgainstItsOwnThreshold) {
  const TermArray thresholds{1.0, 1.0, 1.0, 1.0};
  // Each term within its own threshold: none, although the neglected terms sum to 3.2 (the
  // corrected rule, which sums them, keeps only term 3 out: perspective).
  EXPECT_EQ(printed_cascade({0.3, 0.3, 0.3, 0.3}, {0.5, 0.5, 0.5, 0.5}, thresholds), Level::kNone);
  EXPECT_EQ(choose_level({0.3, 0.3, 0.3, 0.3}, {0.5, 0.5, 0.5, 0.5}, thresholds, kAllLevels),
            Level::kPerspective);
  EXPECT_EQ(printed_cascade({0, 0, 0, 0}, {1.2, 0, 0, 0}, thresholds), Level::kTranslate);
  EXPECT_EQ(printed_cascade({0, 0.6, 0, 0}, {5.0, 0.5, 0, 0}, thresholds), Level::kAffine);
  EXPECT_EQ(printed_cascade({0, 0, 0, 0}, {5.0, 5.0, 1.01, 0}, thresholds), Level::kPerspective);
  EXPECT_EQ(printed_cascade({0, 0, 0, 0.5}, {0, 0, 0, 0.51}, thresholds), Level::kRerender);
  // "exceeds": a term exactly at its threshold may still be neglected.
  EXPECT_EQ(printed_cascade({0, 0, 0, 0}, {1.0, 1.0, 1.0, 1.0}, thresholds), Level::kNone);
  const ReusePolicy& p = reuse_policy("dissertation");
  FrameInputs in;
  in.thresholds = thresholds;
  in.flow = {5.0, 0.2, 0.0, 0.0};
  in.pending = {9.0, 9.0, 9.0, 9.0};  // the exact pending errors play no part
  EXPECT_EQ(p.choose(p, in), Level::kTranslate);
}

// Printed rules 2-4: size = max(width, height) of the corners' bounding box; flow_1 and
// flow_2 scale the largest |J_ij| and |p| by size and size^2 (t = 1 frame); flow_0 the
// larger |t| at the principal point; flow_3 = |Omega|^2 size^2.
TEST(DissertationRule, PrintedMeasuresUseTheBoundingBoxSizeAndOmegaSquared) {
  const Camera cam = make_camera(300.0, 320, 240);
  PlanePose pose = facing_pose(2.0);
  pose.normal = glm::normalize(Vec3(0.3, -0.2, 1.0));
  RigidMotion m;
  m.velocity = Vec3(0.01, -0.02, 0.015);
  m.omega = Vec3(0.01, 0.02, 0.02);
  const std::vector<Vec2> corners = {Vec2(-50, -20), Vec2(70, -25), Vec2(65, 30), Vec2(-40, 28)};
  const double size = 120.0;  // width 70 - (-50); height 30 - (-25) = 55
  const PlanarFlowCoefficients k = planar_flow_coefficients(cam, pose, m);
  const TermArray f = measure_printed_flow(cam, pose, m, corners);
  EXPECT_DOUBLE_EQ(f[0], std::max(std::abs(k.tx), std::abs(k.ty)));
  const double j = std::max({std::abs(k.j11), std::abs(k.j12), std::abs(k.j21), std::abs(k.j22)});
  EXPECT_NEAR(f[1], j * size, 1e-12);
  EXPECT_NEAR(f[2], std::max(std::abs(k.px), std::abs(k.py)) * size * size, 1e-12);
  EXPECT_NEAR(f[3], (0.01 * 0.01 + 0.02 * 0.02 + 0.02 * 0.02) * size * size, 1e-12);
}

// In the engine, the dissertation policy's books are the printed measures and its levels
// are the printed cascade over them.
TEST(DissertationEngine, BooksAreThePrintedMeasuresAndLevelsTheCascade) {
  const Camera cam = make_camera(300.0, 320, 240);
  const auto frames = expand_segments(facing_pose(2.0), MotionModel::kScrew,
                                      {{40, Vec3(0.003, 0.001, -0.004), Vec3(0.0, 0.0, 0.0015)}});
  EngineSettings s;
  s.policy = &reuse_policy("dissertation");
  PlaneEngine a(cam, checker_texture(96, 64), s);
  a.start(frames[0].pose);
  int reused = 0;
  for (size_t i = 1; i < frames.size(); ++i) {
    std::vector<Vec2> corners;
    for (const Vec2& c : a.displayed_outline()) corners.push_back(pixel_to_centred(cam, c));
    const TermArray printed =
        measure_printed_flow(cam, frames[i - 1].pose, frames[i - 1].motion, corners);
    const FrameReport r = a.advance(frames[i - 1].pose, frames[i - 1].motion, frames[i].pose);
    for (int t = 0; t < kTermCount; ++t) EXPECT_NEAR(r.flow[t], printed[t], 1e-9) << i;
    EXPECT_EQ(r.level, printed_cascade(r.carried, r.flow, s.thresholds)) << "frame " << i;
    reused += r.level != Level::kRerender;
  }
  EXPECT_GT(reused, 5);
}

}  // namespace
}  // namespace oflab
