// The `lookahead` policy's prediction and schedule (core/engine/lookahead.h), against
// independent computations: the slack of a quadratic evaluated directly, and schedules
// worked by hand.
#include "engine/lookahead.h"

#include <gtest/gtest.h>

#include "engine/reuse_policy.h"

namespace oflab {
namespace {

// The first t > t0 at which s(t) = a + b t + c t^2 is negative, by evaluating it.
int first_negative(double a, double b, double c, int t0) {
  for (int t = t0 + 1; t < t0 + 1000; ++t) {
    if (a + b * t + c * t * t < 0.0) return t;
  }
  return -1;
}

TEST(Lookahead, PredictionIsExactForAQuadraticSlack) {
  const struct {
    double a, b, c;
  } cases[] = {{1.01, -0.01, -0.002}, {1.0, -0.13, 0.0}, {0.81, 0.02, -0.003}, {1.0, -0.2, 0.004}};
  for (const auto& q : cases) {
    for (int t0 = 2; t0 < 12; ++t0) {
      SlackSeries s;
      for (int t = t0 - 2; t <= t0; ++t) s.push(q.a + q.b * t + q.c * t * t);
      const int expected = first_negative(q.a, q.b, q.c, t0);
      const int ahead = s.frames_to_expiry();
      EXPECT_EQ(ahead < 0 ? -1 : t0 + ahead, expected)
          << q.a << " " << q.b << " " << q.c << " " << t0;
    }
  }
}

TEST(Lookahead, TwoSamplesExtrapolateLinearlyAndOneSampleNothing) {
  SlackSeries s;
  s.push(1.0);
  EXPECT_EQ(s.frames_to_expiry(), -1);
  EXPECT_EQ(s.frames_to_expiry_with(0.75), 4);  // 0.5, 0.25, 0.0 (not negative), then -0.25
  s.push(0.75);
  EXPECT_EQ(s.frames_to_expiry(), 4);
  // A slack that grows never expires.
  SlackSeries growing;
  growing.push(0.5);
  growing.push(0.6);
  EXPECT_EQ(growing.frames_to_expiry(), -1);
}

TEST(Lookahead, LevelSlackIsTheBestAcceptedLevelsMargin) {
  const TermArray error{3.0, 0.9, 0.4, 0.1}, thresholds{1.0, 1.0, 0.5, 1.0};
  EXPECT_DOUBLE_EQ(level_slack(error, thresholds, {true, true, false, false, false}), 0.1);
  EXPECT_DOUBLE_EQ(level_slack(error, thresholds, {false, false, true, true, false}), 0.9);
  EXPECT_LT(level_slack(error, thresholds, {false, false, false, false, true}), -1e300);
}

LayerCandidates choice(Level level, int write_expiry, std::int64_t pixels) {
  LayerCandidates c;
  c.kind = LayerCandidates::Kind::kChoice;
  c.choice = level;
  c.write_expiry = write_expiry;
  c.early_write = Level::kAffine;
  c.pixels = estimate_level_pixels(pixels, pixels);
  return c;
}

FrameAllocation own_choices(const std::vector<LayerCandidates>& layers) {
  FrameAllocation a;
  for (const LayerCandidates& c : layers) a.levels.push_back(c.choice);
  return a;
}

// An empty frame before a peak: the layers due next frame are moved into it, nearest first,
// while the frame stays below the mean of the warped layers' pixels over the frame and its
// horizon and each move lowers the peak of this frame and the due one; a layer due beyond the
// horizon, or with no prediction, stays.
TEST(Lookahead, ALightFrameTakesTheNearestPredictedWritesUpToTheMean) {
  const std::vector<LayerCandidates> layers = {choice(Level::kTranslate, 1, 100),
                                               choice(Level::kTranslate, 1, 100),
                                               choice(Level::kTranslate, 1, 100),
                                               choice(Level::kTranslate, 2, 100),
                                               choice(Level::kNone, kLookaheadHorizon + 1, 100),
                                               choice(Level::kTranslate, -1, 100)};
  FrameAllocation a = own_choices(layers);
  spread_updates(layers, {}, a);
  // Planned 0, predicted 400 over the horizon: the mean of 4 frames is 100, one layer.
  EXPECT_EQ(a.levels[0], Level::kAffine);
  EXPECT_EQ(a.early[0], 1);
  for (std::size_t i = 1; i < layers.size(); ++i) {
    EXPECT_EQ(a.levels[i], layers[i].choice) << i;
    EXPECT_EQ(a.early[i], 0) << i;
  }
  EXPECT_DOUBLE_EQ(a.planned, 100.0);
  EXPECT_DOUBLE_EQ(a.movable, 100.0);
  // Control: five layers due next frame raise the mean to 150, and two move (the frame then
  // holds 200 against 300 next); after light frames the mean falls, and one moves.
  const std::vector<LayerCandidates> five(5, choice(Level::kTranslate, 1, 100));
  FrameAllocation b = own_choices(five);
  spread_updates(five, {}, b);
  for (int i = 0; i < 5; ++i) EXPECT_EQ(b.early[i], i < 2 ? 1 : 0) << i;
  FrameAllocation c = own_choices(five);
  spread_updates(five, {0.0, 0.0, 0.0}, c);
  for (int i = 0; i < 5; ++i) EXPECT_EQ(c.early[i], i < 1 ? 1 : 0) << i;
}

// A fresh or clipped render is fixed: it is planned but no schedule moves it, so it changes
// neither the mean nor the comparisons (the street's clipped layers, manual/policies.md).
TEST(Lookahead, FixedRendersTakeNoPartInTheSchedule) {
  std::vector<LayerCandidates> layers(5, choice(Level::kTranslate, 1, 100));
  LayerCandidates fresh;
  fresh.kind = LayerCandidates::Kind::kFresh;
  fresh.choice = Level::kRerender;
  fresh.pixels = estimate_level_pixels(50000, 50000);
  layers.push_back(fresh);
  FrameAllocation a = own_choices(layers);
  spread_updates(layers, {}, a);
  for (int i = 0; i < 5; ++i) EXPECT_EQ(a.early[i], i < 2 ? 1 : 0) << i;
  EXPECT_EQ(a.levels[5], Level::kRerender);
  EXPECT_DOUBLE_EQ(a.movable, 200.0);
  EXPECT_DOUBLE_EQ(a.planned - a.movable,
                   static_cast<double>(fresh.pixels[static_cast<int>(Level::kRerender)]));
  // A move that would not lower the pair's peak is not made, whatever the mean: a frame of 250
  // own pixels before a frame due 300 keeps its layers (one moved: 350 now, above the 300).
  std::vector<LayerCandidates> busy(3, choice(Level::kTranslate, 1, 100));
  LayerCandidates own = choice(Level::kAffine, -1, 250);
  busy.push_back(own);
  FrameAllocation b = own_choices(busy);
  spread_updates(busy, {1000.0, 1000.0, 1000.0}, b);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(b.early[i], 0) << i;
}

// An affine layer whose levels up to affine are predicted to expire next frame writes a
// perspective warp there (two passes, twice the pixels); a render now writes no more than its
// affine warp now, so it is made early even in a frame above the mean (it adds nothing to the
// frame), and the next frame's peak falls. Controls: without that prediction, or when the render
// costs more than the affine warp (it would add to a frame above the mean), the layer keeps
// its own choice.
TEST(Lookahead, AnAffineLayerAboutToNeedAPerspectiveWarpIsRenderedNowWhenThatAddsNothing) {
  LayerCandidates about = choice(Level::kAffine, -1, 0);
  about.pixels = {0, 0, 100, 200, 100};
  about.upgrade_expiry = 1;
  const auto allocate = [](const LayerCandidates& c) {
    const std::vector<LayerCandidates> layers = {c, choice(Level::kAffine, -1, 50)};
    FrameAllocation a = own_choices(layers);
    spread_updates(layers, {}, a);  // own 150 now, 200 due next frame: the mean is 87.5
    return a;
  };
  const FrameAllocation a = allocate(about);
  EXPECT_EQ(a.levels[0], Level::kRerender);
  EXPECT_EQ(a.early[0], 1);
  EXPECT_EQ(a.levels[1], Level::kAffine);
  EXPECT_DOUBLE_EQ(a.movable, 150.0);
  LayerCandidates unpredicted = about;
  unpredicted.upgrade_expiry = -1;
  EXPECT_EQ(allocate(unpredicted).early[0], 0);
  LayerCandidates dearer = about;
  dearer.pixels[static_cast<int>(Level::kRerender)] = 150;
  EXPECT_EQ(allocate(dearer).early[0], 0);
  EXPECT_EQ(allocate(dearer).levels[0], Level::kAffine);
}

// A frame already over the mean moves nothing; and only `lookahead` schedules ahead.
TEST(Lookahead, AHeavyFrameMovesNothingAndOnlyLookaheadSpreads) {
  const std::vector<LayerCandidates> layers = {choice(Level::kAffine, -1, 1000),
                                               choice(Level::kTranslate, 1, 100)};
  FrameAllocation a = own_choices(layers);
  spread_updates(layers, {}, a);
  EXPECT_EQ(a.levels[1], Level::kTranslate);
  for (const ReusePolicy& p : reuse_policies()) {
    EXPECT_EQ(p.spreads_updates, std::string(p.name) == "lookahead") << p.name;
  }
  const std::vector<LayerCandidates> light(4, choice(Level::kTranslate, 1, 100));
  EXPECT_EQ(allocate_frame(reuse_policy("perspective"), {}, {}, light).levels[0],
            Level::kTranslate);
  EXPECT_EQ(allocate_frame(reuse_policy("lookahead"), {}, {}, light).levels[0], Level::kAffine);
}

}  // namespace
}  // namespace oflab
