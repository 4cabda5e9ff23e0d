// The decision procedure and the engine on synthetic scripts (no files): flow measures
// against independent computations, the level rule, and the engine's contracts.
#include "engine/engine.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "engine/decision.h"
#include "engine/reuse_policy.h"
#include "engine/script.h"
#include "flow/decomposition.h"
#include "flow/homography.h"
#include "image/composite.h"

namespace oflab {
namespace {

Layer checker_texture(int w, int h) {
  Image img(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const bool dark = ((x / 8) + (y / 8)) % 2;
      img.at(x, y) = dark ? Pixel{40, 40, 160, 255} : Pixel{230, 200, 60, 255};
    }
  return make_layer(std::move(img));
}

PlanePose facing_pose(double depth) {
  PlanePose p;
  p.point = Vec3(0.0, 0.0, depth);
  p.normal = Vec3(0.0, 0.0, 1.0);
  p.up = Vec3(0.0, -1.0, 0.0);
  p.size = Vec2(0.96, 0.64);
  p.texture_size = glm::ivec2(96, 64);
  return p;
}

Image frame_of(const Camera& c, const PlacedLayer& l) {
  Image f(c.width, c.height);
  if (!l.layer.empty()) composite_over(f, l.layer, l.offset_x, l.offset_y);
  return f;
}

TEST(Decision, HigherOrderMeasurePredictsTheTaylorHomographyResidual) {
  const Camera cam = make_camera(400.0, 640, 480);
  PlanePose pose = facing_pose(2.0);
  pose.normal = Vec3(0.3, -0.2, 1.0);
  RigidMotion m;
  m.velocity = Vec3(0.01, -0.005, -0.02);
  m.omega = Vec3(0.01, 0.02, 0.03);
  const std::array<Vec2, 4> corners = projected_corners(cam, pose);
  const FlowMeasures fm = measure_flow(cam, pose, m, {corners.begin(), corners.end()});
  const PlanarFlowCoefficients k =
      reexpand(planar_flow_coefficients(cam, pose, m), fm.expansion_point);
  const std::array<Vec2, 4> later =
      projected_corners(cam, advance_pose(pose, rigid_step(m, pose, 1.0)));
  const double actual = max_corner_distance(taylor_homography(k, 1.0), corners, later);
  EXPECT_NEAR(fm.flow[3], actual, 0.1 * actual);
  // Translation measure: the flow at the expansion point, from the exact flow.
  EXPECT_NEAR(fm.flow[0], glm::length(exact_flow_at(cam, pose, m, fm.expansion_point)), 1e-9);
}

TEST(Decision, LowestLevelWithinItsBudgetWins) {
  const TermArray thresholds{1.0, 1.0, 1.0, 1.0};
  const LevelSet all = kAllLevels, no_perspective{true, true, true, false, true};
  EXPECT_EQ(choose_level({0, 0, 0, 0}, {0.5, 0, 0, 0}, thresholds, all), Level::kNone);
  EXPECT_EQ(choose_level({0.6, 0, 0, 0}, {0.5, 0, 0, 0}, thresholds, all), Level::kTranslate);
  EXPECT_EQ(choose_level({0, 0.6, 0, 0}, {0, 0.5, 0, 0}, thresholds, all), Level::kAffine);
  EXPECT_EQ(choose_level({0, 0, 0.6, 0}, {0, 0, 0.5, 0}, thresholds, all), Level::kPerspective);
  EXPECT_EQ(choose_level({0, 0, 0.6, 0}, {0, 0, 0.5, 0}, thresholds, no_perspective),
            Level::kRerender);
  EXPECT_EQ(choose_level({0, 0, 0, 0.6}, {0, 0, 0, 0.5}, thresholds, all), Level::kRerender);
  // Budgets hold the sum of what a level neglects, not each term alone.
  EXPECT_EQ(choose_level({0, 0, 0, 0}, {0.6, 0.6, 0, 0}, thresholds, all), Level::kTranslate);
}

TEST(Decision, LevelNamesRoundTripAndTitlesSpellReRender) {
  for (int l = 0; l < kLevelCount; ++l) {
    Level parsed = Level::kNone;
    ASSERT_TRUE(parse_level(level_name(Level(l)), &parsed)) << level_name(Level(l));
    EXPECT_EQ(parsed, Level(l));
  }
  EXPECT_STREQ(level_name(Level::kRerender), "rerender");
  EXPECT_STREQ(level_title(Level::kRerender), "re-render");
  EXPECT_STREQ(level_title(Level::kAffine), "affine");
  Level untouched = Level::kAffine;
  EXPECT_FALSE(parse_level("re-render", &untouched));
  EXPECT_FALSE(parse_level("", &untouched));
  EXPECT_EQ(untouched, Level::kAffine);
}

// What a policy outside the registry saw, frame by frame (see the test below).
std::vector<FrameInputs> g_seen_inputs;
Level recording_choice(const ReusePolicy& policy, const FrameInputs& inputs) {
  g_seen_inputs.push_back(inputs);
  return threshold_choice(policy, inputs);
}

TEST(Engine, APolicyOutsideTheRegistryDrivesTheEngineAndSeesLevelCosts) {
  const Camera cam = make_camera(300.0, 320, 240);
  const auto frames = expand_segments(facing_pose(2.0), MotionModel::kSpinAboutCentre,
                                      {{30, Vec3(0.004, 0.0, -0.01), Vec3(0.01, 0.02, 0.03)}});
  ReusePolicy recording = default_reuse_policy();
  recording.choose = recording_choice;
  EngineSettings spy;
  spy.policy = &recording;
  PlaneEngine a(cam, checker_texture(96, 64), spy), b(cam, checker_texture(96, 64), {});
  a.start(frames[0].pose);
  b.start(frames[0].pose);
  g_seen_inputs.clear();
  for (size_t i = 1; i < frames.size(); ++i) {
    const Image& shown = a.displayed().layer.image;
    const std::int64_t area = std::int64_t(shown.width()) * shown.height();
    const FrameReport r = a.advance(frames[i - 1].pose, frames[i - 1].motion, frames[i].pose);
    ASSERT_EQ(g_seen_inputs.size(), i);
    const FrameInputs& in = g_seen_inputs.back();
    EXPECT_EQ(in.flow, r.flow);
    EXPECT_EQ(in.carried, r.carried);
    EXPECT_EQ(in.pixels[int(Level::kTranslate)], 0);
    EXPECT_EQ(in.pixels[int(Level::kAffine)], area);
    EXPECT_EQ(in.pixels[int(Level::kRerender)], area);
    EXPECT_GE(in.pixels[int(Level::kPerspective)], area);
    EXPECT_EQ(r.level, b.advance(frames[i - 1].pose, frames[i - 1].motion, frames[i].pose).level)
        << "frame " << i;
  }
}

// Steady state: a plane spinning in its own plane keeps its layer size, so after the first
// frames every warp reuses the same few layer buffers (the displayed layer and the warp
// scratch swap; the cache is copied into its own memory), in every policy. A fixed cadence
// alternates re-renders and perspective updates, which rotate the cache's buffer through the
// swap too: one buffer more, still a fixed set.
TEST(Engine, SteadyFramesReuseTheLayerBuffers) {
  const Camera cam = make_camera(256.0, 320, 240);
  const auto frames = expand_segments(facing_pose(2.0), MotionModel::kSpinAboutCentre,
                                      {{80, Vec3(0.0), Vec3(0.0, 0.0, 0.05)}});
  for (const ReusePolicy& policy : reuse_policies()) {
    EngineSettings settings;
    settings.policy = &policy;
    PlaneEngine a(cam, checker_texture(96, 96), settings);
    a.start(frames[0].pose);
    std::set<const Pixel*> buffers;
    for (size_t i = 1; i < frames.size(); ++i) {
      a.advance(frames[i - 1].pose, frames[i - 1].motion, frames[i].pose);
      if (i >= 20) buffers.insert(a.displayed().layer.image.pixels().data());
    }
    EXPECT_LE(buffers.size(), policy.schedule == Schedule::kCadence ? 4u : 3u) << policy.name;
  }
}

TEST(Engine, RerenderModeEqualsADirectExactRenderPixelForPixel) {
  const Camera cam = make_camera(300.0, 320, 240);
  const Layer tex = checker_texture(96, 64);
  EngineSettings s;
  s.policy = &reuse_policy("rerender");
  const auto frames = expand_segments(facing_pose(2.0), MotionModel::kSpinAboutCentre,
                                      {{20, Vec3(0.01, 0.0, -0.02), Vec3(0.02, 0.03, 0.05)}});
  PlaneEngine a(cam, tex, s);
  for (size_t i = 0; i < frames.size(); ++i) {
    const FrameReport r = i == 0
                              ? a.start(frames[0].pose)
                              : a.advance(frames[i - 1].pose, frames[i - 1].motion, frames[i].pose);
    EXPECT_EQ(r.level, Level::kRerender);
    const Image shown = frame_of(cam, a.displayed());
    const Image exact = frame_of(cam, render_exact(cam, tex, frames[i].pose, s.sampling));
    ASSERT_EQ(shown.pixels(), exact.pixels()) << "frame " << i;
  }
}

TEST(Engine, PureSidewaysTranslationOnlyTranslatesAndKeepsTheErrorBudget) {
  const Camera cam = make_camera(256.0, 320, 240);
  const auto frames = expand_segments(facing_pose(1.0), MotionModel::kScrew,
                                      {{60, Vec3(0.003, 0.0, 0.0), Vec3(0.0)}});
  PlaneEngine a(cam, checker_texture(96, 64), EngineSettings{});
  a.start(frames[0].pose);
  int translates = 0;
  for (size_t i = 1; i < frames.size(); ++i) {
    const FrameReport r = a.advance(frames[i - 1].pose, frames[i - 1].motion, frames[i].pose);
    EXPECT_TRUE(r.level == Level::kNone || r.level == Level::kTranslate) << i;
    translates += r.level == Level::kTranslate;
    EXPECT_LE(r.measured_error_px, 1.0 + 1e-9);
    EXPECT_EQ(r.pixels_written, 0);  // neither level warps anything
  }
  EXPECT_NEAR(translates, 30, 2);  // 0.77 px per frame: every second frame
}

TEST(Engine, ExactModeHasNoModelErrorAndRerendersOnlyForSampling) {
  const Camera cam = make_camera(300.0, 320, 240);
  PlanePose start = facing_pose(2.0);
  start.normal = Vec3(0.4, 0.1, 1.0);
  const auto frames = expand_segments(start, MotionModel::kSpinAboutCentre,
                                      {{80, Vec3(0.005, 0.0, -0.01), Vec3(0.01, 0.03, 0.02)}});
  EngineSettings s;
  s.policy = &reuse_policy("exact");
  PlaneEngine a(cam, checker_texture(96, 64), s);
  a.start(frames[0].pose);
  for (size_t i = 1; i < frames.size(); ++i) {
    const FrameReport r = a.advance(frames[i - 1].pose, frames[i - 1].motion, frames[i].pose);
    EXPECT_EQ(r.accumulated[3], 0.0);
    if (r.level == Level::kRerender) {
      EXPECT_FALSE(r.note.empty()) << i;
    }
    if (r.level == Level::kPerspective) {
      EXPECT_LT(r.measured_error_px, 1e-6) << i;
    }
  }
}

TEST(Engine, PlaneBehindTheCameraAndEmptyTextureAreReportedNotFatal) {
  const Camera cam = make_camera(300.0, 320, 240);
  // Approaches and passes through the eye plane.
  const auto frames = expand_segments(facing_pose(0.5), MotionModel::kScrew,
                                      {{12, Vec3(0.0, 0.0, -0.1), Vec3(0.0)}});
  PlaneEngine a(cam, checker_texture(96, 64), EngineSettings{});
  a.start(frames[0].pose);
  int hidden = 0;
  for (size_t i = 1; i < frames.size(); ++i) {
    const FrameReport r = a.advance(frames[i - 1].pose, frames[i - 1].motion, frames[i].pose);
    if (!r.visible) {
      ++hidden;
      EXPECT_TRUE(r.note.find("not visible") != std::string::npos || r.note == "outside the image")
          << r.note;
      EXPECT_TRUE(std::isnan(r.measured_error_px));
    }
  }
  EXPECT_GT(hidden, 3);
  PlaneEngine empty(cam, make_layer(Image()), EngineSettings{});
  const FrameReport r = empty.start(facing_pose(2.0));
  EXPECT_FALSE(r.visible);
  EXPECT_NE(r.note.find("texture is empty"), std::string::npos);
}

TEST(Engine, EdgeOnFrameIsReportedAndTheNextVisibleFrameRerenders) {
  const Camera cam = make_camera(256.0, 640, 480);
  PlanePose p = facing_pose(2.0);
  p.point = Vec3(-0.12, 0.0, 2.0);
  p.normal = Vec3(1.0, 0.0, 0.0);
  const auto frames =
      expand_segments(p, MotionModel::kScrew, {{9, Vec3(0.03, 0.0, 0.0), Vec3(0.0)}});
  PlaneEngine a(cam, checker_texture(96, 64), EngineSettings{});
  a.start(frames[0].pose);
  bool saw_edge_on = false;
  for (size_t i = 1; i < frames.size(); ++i) {
    const FrameReport r = a.advance(frames[i - 1].pose, frames[i - 1].motion, frames[i].pose);
    if (r.note.find("edge-on") != std::string::npos) saw_edge_on = true;
  }
  EXPECT_TRUE(saw_edge_on);
}

// Plays `frames` through one engine; every report comes back (start() then advance()).
std::vector<FrameReport> play(const Camera& cam, const std::vector<ScriptFrame>& frames,
                              const EngineSettings& settings = {}) {
  PlaneEngine a(cam, checker_texture(96, 64), settings);
  std::vector<FrameReport> out{a.start(frames[0].pose)};
  for (size_t i = 1; i < frames.size(); ++i) {
    out.push_back(a.advance(frames[i - 1].pose, frames[i - 1].motion, frames[i].pose));
    const FrameReport& r = out.back();
    // Contracts of every frame, whatever the pose.
    EXPECT_FALSE(r.visible && r.clipped == false && a.displayed().layer.empty() &&
                 r.level != Level::kNone)
        << "frame " << i;
    if (!r.visible) {
      EXPECT_FALSE(r.note.empty()) << "frame " << i;
      EXPECT_TRUE(std::isnan(r.measured_error_px)) << "frame " << i;
      EXPECT_TRUE(a.displayed_outline().empty()) << "frame " << i;
    } else {
      EXPECT_TRUE(std::isfinite(r.measured_error_px)) << "frame " << i;
    }
  }
  return out;
}

int count_if_note(const std::vector<FrameReport>& reports, const std::string& words) {
  int n = 0;
  for (const FrameReport& r : reports) n += r.note.find(words) != std::string::npos;
  return n;
}

TEST(EngineFraming, FrontalPlaneFlyingIntoTheEyeIsClippedThenHiddenWithoutAborting) {
  // The case that once aborted: f = 256, from Z = 0.5 towards the eye at 0.049 per frame,
  // through the near plane (frame 10), the eye and behind the camera.
  const Camera cam = make_camera(256.0, 640, 480);
  PlanePose p = facing_pose(0.5);
  p.size = Vec2(0.949, 0.773);
  const auto frames =
      expand_segments(p, MotionModel::kScrew, {{16, Vec3(0.0, 0.0, -0.049), Vec3(0.0)}});
  const std::vector<FrameReport> r = play(cam, frames);
  int clipped = 0, hidden = 0;
  for (const FrameReport& f : r) {
    clipped += f.clipped;
    hidden += !f.visible;
    if (f.clipped) {
      EXPECT_EQ(f.level, Level::kRerender);
      EXPECT_EQ(f.measured_error_px, 0.0);
    }
  }
  EXPECT_GT(clipped, 3);  // the plane outgrows the guard band long before the near plane
  EXPECT_GE(hidden, 5);   // at or behind the eye
  EXPECT_FALSE(r.back().visible);
}

TEST(EngineFraming, PlanePassingBesideAndBehindTheCameraNeverAborts) {
  const Camera cam = make_camera(256.0, 640, 480);
  PlanePose p = facing_pose(0.6);
  p.point = Vec3(0.25, 0.1, 0.6);
  p.normal = Vec3(0.3, 0.0, 1.0);
  const auto frames =
      expand_segments(p, MotionModel::kScrew, {{14, Vec3(0.0, 0.0, -0.08), Vec3(0.0)}});
  const std::vector<FrameReport> r = play(cam, frames);
  EXPECT_TRUE(r.front().visible);
  EXPECT_FALSE(r.back().visible);
}

TEST(EngineFraming, PlaneSweepingThroughTheEyeIsEdgeOnThereAndNeverAborts) {
  // A plane containing the Y axis direction sweeps sideways through the eye: at one frame
  // the eye lies in it (seen edge-on as a line), on either side it is seen from a side.
  const Camera cam = make_camera(256.0, 640, 480);
  PlanePose p = facing_pose(1.0);
  p.point = Vec3(-0.2, 0.0, 1.0);
  p.normal = Vec3(1.0, 0.0, 0.2);
  const auto frames =
      expand_segments(p, MotionModel::kScrew, {{9, Vec3(0.05, 0.0, 0.0), Vec3(0.0)}});
  const std::vector<FrameReport> r = play(cam, frames);
  EXPECT_GE(count_if_note(r, "edge-on"), 1);
}

TEST(EngineFraming, PlaneAMillionthFromEdgeOnIsReportedNotDrawn) {
  const Camera cam = make_camera(256.0, 640, 480);
  PlanePose p = facing_pose(2.0);
  p.normal = Vec3(1.0, 0.0, 1e-6);  // the line of sight is 1e-6 rad from the plane
  const auto frames =
      expand_segments(p, MotionModel::kSpinAboutCentre, {{4, Vec3(0.0), Vec3(0.0, 1e-7, 0.0)}});
  const std::vector<FrameReport> r = play(cam, frames);
  for (const FrameReport& f : r) {
    EXPECT_FALSE(f.visible);
    EXPECT_NE(f.note.find("edge-on"), std::string::npos) << f.note;
  }
}

TEST(EngineFraming, PlaneLeavingTheImageIsNotVisibleAndComesBackRerendered) {
  // Sideways at 40 px per frame: the plane leaves the image, then returns.
  const Camera cam = make_camera(256.0, 320, 240);
  const auto frames = expand_segments(
      facing_pose(2.0), MotionModel::kScrew,
      {{12, Vec3(0.3, 0.0, 0.0), Vec3(0.0)}, {12, Vec3(-0.3, 0.0, 0.0), Vec3(0.0)}});
  const std::vector<FrameReport> r = play(cam, frames);
  bool was_outside = false, came_back = false;
  for (const FrameReport& f : r) {
    const bool meets = plane_meets_image(cam, frames[f.frame].pose, EngineSettings{}.near);
    EXPECT_EQ(f.visible, meets) << "frame " << f.frame;
    if (!meets) {
      EXPECT_EQ(f.note, "outside the image");
      EXPECT_EQ(f.pixels_written, 0);
      EXPECT_EQ(f.estimated_error_px, 0.0);
    }
    if (meets && was_outside && !came_back) {
      EXPECT_EQ(f.level, Level::kRerender) << "frame " << f.frame;
      came_back = true;
    }
    was_outside = was_outside || !meets;
  }
  EXPECT_TRUE(was_outside);
  EXPECT_TRUE(came_back);
}

TEST(EngineBooks, EstimateBoundsTheShownErrorAndTheThresholdHoldsOnATiltedSpin) {
  // The estimate (books or exact pending, whichever is larger) bounds the measured error,
  // which is found independently from where the shown layer's pixels are.
  const Camera cam = make_camera(300.0, 320, 240);
  PlanePose start = facing_pose(1.5);
  start.normal = Vec3(0.5, 0.2, 1.0);
  const auto frames = expand_segments(start, MotionModel::kSpinAboutCentre,
                                      {{80, Vec3(0.006, -0.002, -0.006), Vec3(0.01, 0.03, 0.02)}});
  const std::vector<FrameReport> r = play(cam, frames);
  for (const FrameReport& f : r) {
    ASSERT_TRUE(f.visible);
    EXPECT_LE(f.measured_error_px, f.estimated_error_px + 1e-6) << "frame " << f.frame;
    EXPECT_LE(f.measured_error_px, 1.0 + 1e-6) << "frame " << f.frame;
  }
}

// Largest singular value of the linear part of an affine map, from the eigenvalues of
// A^T A found by iterating (independent of the engine's closed form).
double stretch_of(const Mat3& m) {
  const glm::dmat2 a(entry(m, 0, 0), entry(m, 1, 0), entry(m, 0, 1), entry(m, 1, 1));
  const glm::dmat2 ata = glm::transpose(a) * a;
  glm::dvec2 v(1.0, 0.3);
  for (int k = 0; k < 200; ++k) v = glm::normalize(ata * v);
  return std::sqrt(glm::length(ata * v));
}

TEST(EngineBooks, PerspectiveUpdatesRespectTheSamplingLimitAlongEveryAxis) {
  // A plane turning towards edge-on: a sqrt|det A| cache keeps the output's area, so the
  // affine rest W_aff (det 1) stretches it along one axis; beyond the limit the engine must
  // re-render instead of showing the stretched cache.
  const Camera cam = make_camera(300.0, 320, 240);
  EngineSettings s;
  s.delta = DeltaPolicy::kSqrtAbsDet;
  s.thresholds = {0.2, 0.2, 0.2, 50.0};  // perspective whenever it is within the limit
  const auto frames = expand_segments(facing_pose(1.5), MotionModel::kSpinAboutCentre,
                                      {{70, Vec3(0.0), Vec3(0.0, 0.022, 0.0)}});
  PlaneEngine a(cam, checker_texture(96, 64), s);
  a.start(frames[0].pose);
  int limited = 0, perspective = 0;
  const Mat3 to_centre = translation_matrix(48.0, 32.0);
  for (size_t i = 1; i < frames.size(); ++i) {
    const FrameReport r = a.advance(frames[i - 1].pose, frames[i - 1].motion, frames[i].pose);
    limited += r.note.find("sampling limit") != std::string::npos;
    if (r.level != Level::kPerspective) continue;
    ++perspective;
    const AffinePerspectiveSplit split =
        split_affine_perspective(a.displayed_warp() * to_centre, s.delta);
    EXPECT_LE(stretch_of(split.affine), s.max_magnification + 1e-9) << "frame " << i;
  }
  EXPECT_GT(perspective, 0);
  EXPECT_GT(limited, 0);
}

// Erratum 23: the second-order measure. Planar flow is exactly quadratic, so what its
// affine Taylor part about the expansion point misses at a corner is the second-order
// term itself; it is found here from the exact flow alone (finite differences of
// exact_flow_at, exact for a quadratic up to rounding), never from px, py.
TEST(Errata, Erratum23SecondOrderMeasureIsTheQuadraticFlowAtTheCorners) {
  const Camera cam = make_camera(400.0, 640, 480);
  PlanePose pose = facing_pose(1.2);
  pose.point = Vec3(0.15, -0.1, 1.2);
  pose.normal = Vec3(-0.5, 0.4, 1.0);
  RigidMotion m;
  m.velocity = Vec3(0.01, -0.004, -0.03);
  m.omega = Vec3(-0.02, -0.015, 0.01);
  const std::array<Vec2, 4> corners = projected_corners(cam, pose);
  const FlowMeasures fm = measure_flow(cam, pose, m, {corners.begin(), corners.end()});
  const Vec2 e = fm.expansion_point;
  const auto v = [&](const Vec2& p) { return exact_flow_at(cam, pose, m, p); };
  const double h = 4.0;
  const Vec2 dx = (v(e + Vec2(h, 0.0)) - v(e - Vec2(h, 0.0))) / (2.0 * h);
  const Vec2 dy = (v(e + Vec2(0.0, h)) - v(e - Vec2(0.0, h))) / (2.0 * h);
  double second = 0.0, size = 0.0;
  for (const Vec2& c : corners) {
    const Vec2 d = c - e;
    second = std::max(second, glm::length(v(c) - v(e) - (dx * d.x + dy * d.y)));
    size = std::max(size, glm::length(d));
  }
  ASSERT_GT(second, 0.5);  // a case with a real second-order term
  EXPECT_NEAR(fm.flow[2], second, 1e-6 * second);
  // The corrected closed-form bound holds; the printed max{px, py} size^2 does not.
  const PlanarFlowCoefficients k = reexpand(planar_flow_coefficients(cam, pose, m), e);
  EXPECT_GE((std::abs(k.px) + std::abs(k.py)) * size * size, second);
  EXPECT_LT(std::max(k.px, k.py) * size * size, second);
}

// Erratum 25: the update rule of the error books, replayed from the reports (neglected
// terms accumulate, handled ones are caught up with, re-render clears all) and checked
// against the truth. On a frontal plane sliding exactly 0.5 px per frame, translated every
// second frame by exactly one pixel (no rounding, no higher orders) the corrected books equal the
// measured error of every frame, found from where the shown pixels are; the printed rule, which
// accumulates only the terms below the level, would book nothing while the image drifts.
TEST(Errata, Erratum25NeglectedTermsAccumulateHandledOnesResetAndTheBooksMatchTheTruth) {
  const Camera cam = make_camera(256.0, 320, 240);
  const auto frames = expand_segments(facing_pose(1.0), MotionModel::kScrew,
                                      {{40, Vec3(0.5 / 256.0, 0.0, 0.0), Vec3(0.0)}});
  EngineSettings s;
  s.thresholds.fill(0.9);  // translates after two frames, by exactly one pixel
  const std::vector<FrameReport> r = play(cam, frames, s);
  TermArray printed{};
  int drifting = 0;
  for (size_t i = 1; i < r.size(); ++i) {
    const FrameReport& f = r[i];
    const int level = static_cast<int>(f.level);
    for (int t = 0; t < kTermCount; ++t) {
      EXPECT_NEAR(f.carried[t], r[i - 1].accumulated[t], 1e-12) << i;  // no stretch here
      const double corrected = f.level == Level::kRerender ? 0.0
                               : t >= level                ? f.carried[t] + f.flow[t]
                                                           : 0.0;
      EXPECT_NEAR(f.accumulated[t], corrected, 1e-12) << "frame " << i << " term " << t;
      if (t < level) printed[t] += f.flow[t];
      if (t >= level) printed[t] = std::max(0.0, printed[t] - f.flow[t]);
    }
    double books = 0.0, printed_books = 0.0;
    for (int t = 0; t < kTermCount; ++t) books += f.accumulated[t], printed_books += printed[t];
    EXPECT_NEAR(books, f.measured_error_px, 1e-6) << "frame " << i;
    if (f.level == Level::kNone && f.measured_error_px > 0.4) {
      ++drifting;
      EXPECT_LT(printed_books, f.measured_error_px) << "frame " << i;
    }
  }
  EXPECT_GT(drifting, 5);
}

}  // namespace
}  // namespace oflab
