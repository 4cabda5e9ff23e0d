// The decision procedure and the engine on synthetic scripts (no files): flow measures
// against independent computations, the level rule, and the engine's contracts.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <set>
#include <vector>

#include "image/composite.h"
#include "engine/decision.h"
#include "engine/engine.h"
#include "engine/reuse_policy.h"
#include "flow/homography.h"
#include "engine/script.h"

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
  PlaneAnimator a(cam, checker_texture(96, 64), spy), b(cam, checker_texture(96, 64), {});
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
// scratch swap; the cache is copied into its own memory), in every policy.
TEST(Engine, SteadyFramesReuseTheLayerBuffers) {
  const Camera cam = make_camera(256.0, 320, 240);
  const auto frames = expand_segments(facing_pose(2.0), MotionModel::kSpinAboutCentre,
                                      {{80, Vec3(0.0), Vec3(0.0, 0.0, 0.05)}});
  for (const ReusePolicy& policy : reuse_policies()) {
    EngineSettings settings;
    settings.policy = &policy;
    PlaneAnimator a(cam, checker_texture(96, 96), settings);
    a.start(frames[0].pose);
    std::set<const Pixel*> buffers;
    for (size_t i = 1; i < frames.size(); ++i) {
      a.advance(frames[i - 1].pose, frames[i - 1].motion, frames[i].pose);
      if (i >= 20) buffers.insert(a.displayed().layer.image.pixels().data());
    }
    EXPECT_LE(buffers.size(), 3u) << policy.name;
  }
}

TEST(Engine, RerenderModeEqualsADirectExactRenderPixelForPixel) {
  const Camera cam = make_camera(300.0, 320, 240);
  const Layer tex = checker_texture(96, 64);
  EngineSettings s;
  s.policy = &reuse_policy("rerender");
  const auto frames = expand_segments(facing_pose(2.0), MotionModel::kSpinAboutCentre,
                                      {{20, Vec3(0.01, 0.0, -0.02), Vec3(0.02, 0.03, 0.05)}});
  PlaneAnimator a(cam, tex, s);
  for (size_t i = 0; i < frames.size(); ++i) {
    const FrameReport r = i == 0 ? a.start(frames[0].pose)
                                 : a.advance(frames[i - 1].pose, frames[i - 1].motion,
                                             frames[i].pose);
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
  PlaneAnimator a(cam, checker_texture(96, 64), EngineSettings{});
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
  PlaneAnimator a(cam, checker_texture(96, 64), s);
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
  PlaneAnimator a(cam, checker_texture(96, 64), EngineSettings{});
  a.start(frames[0].pose);
  int hidden = 0;
  for (size_t i = 1; i < frames.size(); ++i) {
    const FrameReport r = a.advance(frames[i - 1].pose, frames[i - 1].motion, frames[i].pose);
    if (!r.visible) {
      ++hidden;
      EXPECT_NE(r.note.find("not visible"), std::string::npos);
      EXPECT_TRUE(std::isnan(r.measured_error_px));
    }
  }
  EXPECT_GT(hidden, 3);
  PlaneAnimator empty(cam, make_layer(Image()), EngineSettings{});
  const FrameReport r = empty.start(facing_pose(2.0));
  EXPECT_FALSE(r.visible);
  EXPECT_NE(r.note.find("texture is empty"), std::string::npos);
}

TEST(Engine, EdgeOnFrameIsReportedAndTheNextVisibleFrameRerenders) {
  const Camera cam = make_camera(256.0, 640, 480);
  PlanePose p = facing_pose(2.0);
  p.point = Vec3(-0.12, 0.0, 2.0);
  p.normal = Vec3(1.0, 0.0, 0.0);
  const auto frames = expand_segments(p, MotionModel::kScrew, {{9, Vec3(0.03, 0.0, 0.0), Vec3(0.0)}});
  PlaneAnimator a(cam, checker_texture(96, 64), EngineSettings{});
  a.start(frames[0].pose);
  bool saw_edge_on = false;
  for (size_t i = 1; i < frames.size(); ++i) {
    const FrameReport r = a.advance(frames[i - 1].pose, frames[i - 1].motion, frames[i].pose);
    if (r.note.find("edge-on") != std::string::npos) saw_edge_on = true;
  }
  EXPECT_TRUE(saw_edge_on);
}

}  // namespace
}  // namespace oflab
