// The comparison's per-frame history: for each compared policy it equals, frame by frame,
// what the animation model records when it plays that policy alone on the same source; it
// restarts with the run; it keeps at most its limit of frames, the newest.
#include "player/policy_comparison.h"

#include <gtest/gtest.h>

#include "engine/reuse_policy.h"
#include "models/animation_model.h"
#include "models/scene_model.h"

namespace oflab::test {
namespace {

const SourceChoice kLoop{"script", "loop", ""};

// Frames 0 .. frames of `policy` played alone by an animation model on `choice`, one frame
// at a time as the window's clock does.
std::vector<AnimationFrame> single_run(const SourceChoice& choice, const ReusePolicy& policy,
                                       int frames) {
  SceneModel scene;
  AnimationModel model(&scene);
  EXPECT_TRUE(model.set_source(choice));
  EngineSettings settings = model.settings();
  settings.policy = &policy;
  EXPECT_TRUE(model.set_settings(settings));
  for (int f = 1; f <= frames; ++f) {
    scene.set_frame(f);
    model.history();
  }
  return model.history();
}

void expect_same_frame(const ComparedFrame& compared, const AnimationFrame& alone,
                       const std::string& what) {
  EXPECT_EQ(compared.frame, alone.frame) << what;
  EXPECT_EQ(compared.levels, alone.levels) << what;
  EXPECT_EQ(compared.max_measured_error_px, alone.max_measured_error_px) << what;
  EXPECT_EQ(compared.model_work, alone.model_work) << what;
  EXPECT_EQ(compared.pixels_written, alone.pixels_written) << what;
  EXPECT_GE(compared.time_ms, 0.0) << what;  // wall time: measured, never equal across runs
}

TEST(PolicyComparisonHistory, EqualsEachPolicyPlayedAlone) {
  constexpr int kFrames = 60;
  SceneModel scene;
  AnimationModel model(&scene);
  ASSERT_TRUE(model.set_source(kLoop));
  PolicyComparison comparison(&model.player());
  comparison.set_policies(
      {&reuse_policy("perspective"), &reuse_policy("affine"), &reuse_policy("talisman")});
  for (int f = 1; f <= kFrames; ++f) {
    scene.set_frame(f);
    comparison.runs();
  }
  for (const ComparedRun& run : comparison.runs()) {
    const std::vector<AnimationFrame> alone = single_run(kLoop, *run.policy, kFrames);
    ASSERT_EQ(run.history.size(), alone.size()) << run.policy->name;
    ASSERT_EQ(alone.size(), size_t(kFrames + 1));
    for (int f = 0; f <= kFrames; ++f) {
      ASSERT_NE(run.at(f), nullptr) << f;
      expect_same_frame(*run.at(f), alone[size_t(f)],
                        std::string(run.policy->name) + " frame " + std::to_string(f));
    }
    // The totals of the panels are the history's sums.
    std::int64_t pixels = 0;
    for (const ComparedFrame& c : run.history) pixels += c.pixels_written;
    EXPECT_EQ(run.pixels_written, pixels);
  }
}

TEST(PolicyComparisonHistory, LevelTotalsCountTheLayerFramesPerLevel) {
  SceneModel scene;
  AnimationModel model(&scene);
  ASSERT_TRUE(model.set_source({"scene", "four-cubes", "circle"}));
  PolicyComparison comparison(&model.player());
  comparison.set_policies({&reuse_policy("perspective"), &reuse_policy("rerender")});
  scene.set_frame(12);
  const std::vector<ComparedRun>& runs = comparison.runs();
  ASSERT_EQ(runs.size(), 2u);
  const std::vector<AnimationFrame> alone =
      single_run({"scene", "four-cubes", "circle"}, reuse_policy("perspective"), 12);
  std::array<std::int64_t, kLevelCount> expected{};
  for (int f = 3; f <= 9; ++f) {
    for (int level = 0; level < kLevelCount; ++level) {
      expected[size_t(level)] += alone[size_t(f)].levels[size_t(level)];
    }
  }
  EXPECT_EQ(runs[0].level_totals(3, 9), expected);
  // Re-rendering everything: every drawn layer-frame is a re-render.
  const auto rerender = runs[1].level_totals(0, 12);
  std::int64_t drawn = 0;
  for (const ComparedFrame& c : runs[1].history) drawn += c.drawn();
  EXPECT_GT(drawn, 0);
  EXPECT_EQ(rerender[size_t(Level::kRerender)], drawn);
  // Frames not played yet count nothing.
  EXPECT_EQ(runs[0].level_totals(13, 40), (std::array<std::int64_t, kLevelCount>{}));
}

TEST(PolicyComparisonHistory, RestartsWithTheRunAndKeepsAtMostItsLimit) {
  SceneModel scene;
  AnimationModel model(&scene);
  ASSERT_TRUE(model.set_source(kLoop));
  PolicyComparison comparison(&model.player(), 10);
  for (int f = 1; f <= 25; ++f) {
    scene.set_frame(f);
    comparison.runs();
  }
  for (const ComparedRun& run : comparison.runs()) {
    ASSERT_EQ(run.history.size(), 10u);
    EXPECT_EQ(run.history.front().frame, 16);
    EXPECT_EQ(run.history.back().frame, 25);
    EXPECT_EQ(run.at(15), nullptr);
    ASSERT_NE(run.at(20), nullptr);
    EXPECT_EQ(run.at(20)->frame, 20);
    EXPECT_EQ(run.at(26), nullptr);
  }
  scene.set_frame(4);  // back: the runs restart from frame 0
  for (const ComparedRun& run : comparison.runs()) {
    ASSERT_EQ(run.history.size(), 5u);
    EXPECT_EQ(run.history.front().frame, 0);
    EXPECT_EQ(run.at(4)->frame, 4);
  }
  comparison.reset();  // a new source or settings: nothing kept until read
  scene.set_frame(2);
  for (const ComparedRun& run : comparison.runs()) EXPECT_EQ(run.history.size(), 3u);
}

}  // namespace
}  // namespace oflab::test
