// The registry of reuse policies: its entries, lookups, the levels each policy allows, and
// the threshold choice against an independent computation of the rule.
#include "engine/reuse_policy.h"

#include <gtest/gtest.h>

#include <random>
#include <set>
#include <stdexcept>
#include <string>

#include "engine/engine.h"

namespace oflab {
namespace {

// The threshold rule written out from its statement (manual/animation.md): level L is
// acceptable when the errors of terms L..3, accumulated plus this frame's, sum to at most
// thresholds[L]; the lowest acceptable allowed level wins, else re-render. The sums are
// built from the top term down, unlike choose_level.
Level reference_choice(const FrameInputs& in, const LevelSet& allowed) {
  double neglected[kTermCount];
  double sum = 0.0;
  for (int k = kTermCount - 1; k >= 0; --k) {
    sum += in.carried[k] + in.flow[k];
    neglected[k] = sum;
  }
  for (int l = 0; l < kTermCount; ++l) {
    if (allowed[l] && neglected[l] <= in.thresholds[l]) return static_cast<Level>(l);
  }
  return Level::kRerender;
}

TEST(ReusePolicies, RegistryListsTheDissertationModesFirstInOrder) {
  const std::vector<ReusePolicy>& all = reuse_policies();
  ASSERT_GE(all.size(), 4u);
  EXPECT_STREQ(all[0].name, "perspective");
  EXPECT_STREQ(all[1].name, "affine");
  EXPECT_STREQ(all[2].name, "exact");
  EXPECT_STREQ(all[3].name, "rerender");
  EXPECT_EQ(&default_reuse_policy(), &all[0]);
  EXPECT_EQ(EngineSettings{}.policy, &all[0]);
}

TEST(ReusePolicies, NamesAreUniqueAndEveryEntryHasASummaryAndAChoice) {
  std::set<std::string> names;
  for (const ReusePolicy& p : reuse_policies()) {
    EXPECT_TRUE(names.insert(p.name).second) << "duplicate policy " << p.name;
    EXPECT_NE(std::string(p.summary), "") << p.name;
    EXPECT_EQ(std::string(p.summary).find('\n'), std::string::npos) << p.name;
    EXPECT_NE(p.choose, nullptr) << p.name;
    EXPECT_TRUE(p.allows(Level::kRerender)) << p.name;
  }
}

TEST(ReusePolicies, LookupFindsEachEntryAndRejectsUnknownNames) {
  for (const ReusePolicy& p : reuse_policies()) {
    EXPECT_EQ(find_reuse_policy(p.name), &p);
    EXPECT_EQ(&reuse_policy(p.name), &p);
  }
  EXPECT_EQ(find_reuse_policy("scene-shifting"), nullptr);
  EXPECT_EQ(find_reuse_policy("Perspective"), nullptr);
  EXPECT_EQ(find_reuse_policy(""), nullptr);
  try {
    reuse_policy("bogus");
    FAIL() << "no exception for an unknown policy";
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("'bogus'"), std::string::npos) << message;
    EXPECT_NE(message.find("perspective, affine, exact, rerender"), std::string::npos) << message;
  }
}

TEST(ReusePolicies, NameListJoinsTheRegistryInOrder) {
  EXPECT_EQ(reuse_policy_names().rfind("perspective, affine, exact, rerender", 0), 0u);
  EXPECT_EQ(reuse_policy_names("|").rfind("perspective|affine|exact|rerender", 0), 0u);
}

TEST(ReusePolicies, EachModeAllowsItsLevels) {
  const auto allowed = [](const char* name) { return reuse_policy(name).allowed; };
  EXPECT_EQ(allowed("perspective"), (LevelSet{true, true, true, true, true}));
  EXPECT_EQ(allowed("affine"), (LevelSet{true, true, true, false, true}));
  EXPECT_EQ(allowed("exact"), (LevelSet{true, true, true, true, true}));
  EXPECT_EQ(allowed("rerender"), (LevelSet{false, false, false, false, true}));
  EXPECT_TRUE(reuse_policy("affine").allows_reuse());
  EXPECT_FALSE(reuse_policy("rerender").allows_reuse());
  EXPECT_EQ(reuse_policy("affine").initial_view, InitialView::kAffinePart);
  EXPECT_EQ(reuse_policy("perspective").initial_view, InitialView::kExact);
  EXPECT_EQ(reuse_policy("affine").model, ModelUpdate::kAffineTaylor);
  EXPECT_EQ(reuse_policy("perspective").model, ModelUpdate::kTaylor);
  EXPECT_EQ(reuse_policy("exact").model, ModelUpdate::kExact);
  EXPECT_EQ(allowed("dissertation"), (LevelSet{true, true, true, true, true}));
  EXPECT_EQ(allowed("talisman"), (LevelSet{false, false, true, false, true}));
  EXPECT_EQ(reuse_policy("dissertation").books, FlowBooks::kPrinted);
  EXPECT_FALSE(reuse_policy("dissertation").bounded);
  EXPECT_EQ(reuse_policy("talisman").model, ModelUpdate::kAffineFit);
  EXPECT_TRUE(reuse_policy("talisman").bounded);
}

TEST(ReusePolicies, ChoicesFollowAnIndependentThresholdRule) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> term(0.0, 0.8), budget(0.2, 2.0);
  std::set<Level> seen;
  for (int trial = 0; trial < 2000; ++trial) {
    FrameInputs in;
    for (int k = 0; k < kTermCount; ++k) {
      in.flow[k] = term(rng);
      in.carried[k] = 0.5 * term(rng);
      in.thresholds[k] = budget(rng);
    }
    in.pixels = estimate_level_pixels(1000, 600);
    for (const ReusePolicy& p : reuse_policies()) {
      const Level chosen = p.choose(p, in);
      EXPECT_TRUE(p.allows(chosen)) << p.name;
      if (p.choose != threshold_choice) continue;  // the rivals: reuse_rivals_test.cpp
      if (p.allows_reuse()) {
        EXPECT_EQ(chosen, reference_choice(in, p.allowed)) << p.name << " trial " << trial;
      } else {
        EXPECT_EQ(chosen, Level::kRerender) << p.name;
      }
      seen.insert(chosen);
    }
  }
  EXPECT_EQ(seen.size(), static_cast<size_t>(kLevelCount));  // every level was exercised
}

TEST(ReusePolicies, TodaysReprojectionRendersOnAFixedCadence) {
  // Frame k after a render at frame 0 is rendered exactly when k is a multiple of N.
  for (const char* name :
       {"timewarp", "stabilized-plane", "depth-reprojection", "cadence", "mv-extrapolation",
        "mv-no-inpaint", "view-interpolation", "depth-mesh"}) {
    const ReusePolicy& p = reuse_policy(name);
    EXPECT_EQ(p.schedule, Schedule::kCadence) << name;
    if (p.pixel_motion != PixelMotion::kBetweenRenders) {
      EXPECT_EQ(latency_frames(p, 2), 0) << name;
    }
    EXPECT_TRUE(reports_holes(p)) << name;
    EXPECT_NE(std::string(p.models), "") << name;
    EXPECT_NE(std::string(p.breaks), "") << name;
    for (int cadence = 1; cadence <= 8; ++cadence) {
      int last_render = 0;
      for (int frame = 1; frame <= 24; ++frame) {
        FrameInputs in;
        in.cadence = cadence;
        in.since_render = frame - last_render;
        const Level chosen = p.choose(p, in);
        const bool render = frame % cadence == 0;
        EXPECT_EQ(chosen, render ? Level::kRerender : Level::kPerspective)
            << name << " cadence " << cadence << " frame " << frame;
        if (chosen == Level::kRerender) last_render = frame;
      }
    }
  }
  EXPECT_EQ(reuse_policy("timewarp").frame_plane, FramePlane::kInfinity);
  EXPECT_EQ(reuse_policy("stabilized-plane").frame_plane, FramePlane::kStabilization);
  EXPECT_EQ(reuse_policy("depth-reprojection").frame_warp, FrameWarp::kPerPixelDepth);
  EXPECT_EQ(reuse_policy("cadence").model, ModelUpdate::kExact);
  // Frame generation: per-pixel, along motion vectors, with and without inpainting, scenes only.
  for (const char* name : {"mv-extrapolation", "mv-no-inpaint"}) {
    const ReusePolicy& p = reuse_policy(name);
    EXPECT_EQ(p.frame_warp, FrameWarp::kPerPixelDepth) << name;
    EXPECT_EQ(p.pixel_motion, PixelMotion::kMotionVectors) << name;
    std::string why;
    EXPECT_TRUE(needs_scene(p, &why)) << name;
    EXPECT_NE(why, "") << name;
  }
  EXPECT_TRUE(reuse_policy("mv-extrapolation").inpaint);
  EXPECT_FALSE(reuse_policy("mv-no-inpaint").inpaint);
  EXPECT_EQ(reuse_policy("depth-reprojection").pixel_motion, PixelMotion::kViewerStep);
  // View interpolation: per-pixel, between two renders, scenes only, shown late: the frame
  // after a render waits for the next render, cadence frames after it.
  const ReusePolicy& between = reuse_policy("view-interpolation");
  EXPECT_EQ(between.frame_warp, FrameWarp::kPerPixelDepth);
  EXPECT_EQ(between.pixel_motion, PixelMotion::kBetweenRenders);
  EXPECT_TRUE(needs_scene(between));
  for (int cadence = 1; cadence <= 8; ++cadence) {
    const int first_between = 1, next_render = cadence;
    EXPECT_EQ(latency_frames(between, cadence), next_render - first_between) << cadence;
    EXPECT_EQ(latency_frames(reuse_policy("depth-reprojection"), cadence), 0) << cadence;
  }
  // The depth mesh: per-pixel (its far part), scenes only, shown at once.
  const ReusePolicy& mesh = reuse_policy("depth-mesh");
  EXPECT_EQ(mesh.frame_warp, FrameWarp::kPerPixelDepth);
  EXPECT_EQ(mesh.pixel_motion, PixelMotion::kFarMesh);
  EXPECT_TRUE(needs_scene(mesh));
  for (int cadence = 1; cadence <= 8; ++cadence) EXPECT_EQ(latency_frames(mesh, cadence), 0);
  EXPECT_FALSE(needs_scene(reuse_policy("depth-reprojection")));
  EXPECT_TRUE(needs_scene(reuse_policy("hierarchical-cache")));
  EXPECT_FALSE(reports_holes(reuse_policy("perspective")));
}

TEST(ReusePolicies, LevelCostsCountTheWarpsEachLevelRuns) {
  const LevelPixels p = estimate_level_pixels(5000, 3000);
  EXPECT_EQ(p[static_cast<int>(Level::kNone)], 0);
  EXPECT_EQ(p[static_cast<int>(Level::kTranslate)], 0);
  EXPECT_EQ(p[static_cast<int>(Level::kAffine)], 5000);       // cache -> display
  EXPECT_EQ(p[static_cast<int>(Level::kPerspective)], 8000);  // texture -> cache -> display
  EXPECT_EQ(p[static_cast<int>(Level::kRerender)], 5000);     // texture -> display
}

TEST(ReusePolicies, EachPolicyNamesWhatItDidInItsOwnWords) {
  for (const ReusePolicy& p : reuse_policies()) {
    for (int k = 0; k < kLevelCount; ++k) {
      const Level level = Level(k);
      const std::string word = level_word(p, level);
      if (p.frame_warp == FrameWarp::kNodeImages) {
        EXPECT_EQ(word, level == Level::kRerender ? "rendered" : "cached") << p.name;
      } else if (p.pixel_motion == PixelMotion::kMotionVectors) {
        EXPECT_EQ(word, level == Level::kRerender ? "rendered" : "generated") << p.name;
      } else if (p.pixel_motion == PixelMotion::kBetweenRenders) {
        EXPECT_EQ(word, level == Level::kRerender ? "rendered" : "interpolated") << p.name;
      } else if (p.pixel_motion == PixelMotion::kFarMesh) {
        EXPECT_EQ(word, level == Level::kRerender ? "rendered" : "meshed") << p.name;
      } else if (p.schedule == Schedule::kCadence) {
        EXPECT_EQ(word, level == Level::kRerender ? "rendered" : "reprojected") << p.name;
      } else {
        EXPECT_EQ(word, level_name(level)) << p.name;
      }
    }
  }
  // The four policies of today's reprojection and the cache never borrow a Taylor level name.
  for (const char* name : {"timewarp", "stabilized-plane", "depth-reprojection", "cadence",
                           "hierarchical-cache", "mv-extrapolation"}) {
    EXPECT_STRNE(level_word(reuse_policy(name), Level::kPerspective), "perspective") << name;
    EXPECT_STRNE(level_word(reuse_policy(name), Level::kRerender), "rerender") << name;
  }
}

}  // namespace
}  // namespace oflab
