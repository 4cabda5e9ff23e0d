// The budget policy from the command line and on the shipped scenes: no frame after the
// first writes more than the budget (four cubes, the street), the summaries report it, and
// bad budget options are one-line errors with exit code 2.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "cli_capture.h"
#include "formats/datasets.h"
#include "formats/scene_file.h"
#include "formats/viewer_script_file.h"
#include "runs/policy_runs.h"

namespace oflab {
namespace {

using testing::CliResult;

CliResult run(const std::vector<std::string>& args) { return testing::run_cli_captured(args); }

// Plays a shipped scene under `budget` and checks every frame after the first against it.
void expect_shipped_scene_within_budget(const std::string& scene, const std::string& script,
                                        double budget_pixels, int frames) {
  RunSource source;
  source.scene = std::make_shared<const Scene>(read_scene_file(resolve_scene_path(scene)));
  source.viewer = read_viewer_script_file(resolve_viewer_script_path(script));
  source.settings.engine.budget = {FrameBudget::Unit::kPixels, budget_pixels};
  PlayOptions options;
  options.max_frames = frames;
  options.baseline = false;
  const auto runs = run_policies(source_kind("scene"), source, {&reuse_policy("budget")}, options);
  const AnimationRun& r = runs.at(0).run;
  ASSERT_EQ(static_cast<int>(r.frames.size()), frames);
  long drawn = 0;
  for (std::size_t i = 1; i < r.frames.size(); ++i) {
    const AnimationFrame& f = r.frames[i];
    EXPECT_LE(f.pixels_written, static_cast<std::int64_t>(budget_pixels)) << scene << " " << i;
    EXPECT_TRUE(f.budget.active);
    drawn += f.drawn();
  }
  EXPECT_GT(drawn, 0) << scene;
  EXPECT_EQ(r.summary.frames_over_budget, 0) << scene;
  EXPECT_EQ(r.summary.budget_frames, frames - 1) << scene;
}

TEST(BudgetPolicy, FourCubesNeverExceedsTheBudgetAfterTheFirstFrame) {
  for (double budget : {0.0, 5000.0, 40000.0}) {
    expect_shipped_scene_within_budget("four-cubes", "compound", budget, 60);
  }
}

TEST(BudgetPolicy, TheStreetNeverExceedsTheBudgetAfterTheFirstFrame) {
  expect_shipped_scene_within_budget("street", "walk", 60000.0, 12);
}

TEST(BudgetCommand, AnimateAndCompareReportTheBudgetFigures) {
  const CliResult a =
      run({"animate", "--scene", "four-cubes", "--script", "compound", "--mode", "budget",
           "--budget-pixels", "8000", "--frames", "30", "--repeat-timing", "1", "--json"});
  ASSERT_EQ(a.code, 0) << a.err;
  const auto j = nlohmann::json::parse(a.out);
  ASSERT_TRUE(j.contains("budget")) << a.out;
  EXPECT_EQ(j["budget"]["frames"], 29);
  EXPECT_EQ(j["budget"]["frames_over_budget"], 0);
  const CliResult c = run({"compare", "--scene", "four-cubes", "--script", "compound", "--policies",
                           "perspective,budget", "--budget-pixels", "8000", "--frames", "30",
                           "--repeat-timing", "1", "--json"});
  ASSERT_EQ(c.code, 0) << c.err;
  const auto rows = nlohmann::json::parse(c.out).at("policies");
  EXPECT_FALSE(rows[0].contains("budget"));
  ASSERT_TRUE(rows[1].contains("budget"));
  EXPECT_EQ(rows[1]["budget"]["frames_over_budget"], 0);
  EXPECT_EQ(rows[1]["budget"]["starved_layer_frames"], j["budget"]["starved_layer_frames"]);
  EXPECT_EQ(rows[1]["budget"]["gap_frames"], j["budget"]["gap_frames"]);
  const CliResult text = run({"animate", "--script", "rotation", "--mode", "budget",
                              "--budget-pixels", "3000", "--frames", "20", "--repeat-timing", "1"});
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_NE(text.out.find("0 frames over budget (of 19)"), std::string::npos) << text.out;
}

TEST(BudgetCommand, BadBudgetOptionsAreOneLineErrorsWithExitCodeTwo) {
  const auto expect_error = [](const std::vector<std::string>& args, const std::string& text) {
    const CliResult r = run(args);
    EXPECT_EQ(r.code, 2) << r.out;
    EXPECT_NE(r.err.find(text), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  };
  const std::vector<std::string> animate = {"animate", "--script", "rotation", "--frames", "3"};
  const auto with = [&](std::vector<std::string> more) {
    std::vector<std::string> args = animate;
    args.insert(args.end(), more.begin(), more.end());
    return args;
  };
  expect_error(with({"--mode", "budget", "--budget-pixels"}), "--budget-pixels");
  expect_error(with({"--mode", "budget", "--budget-pixels", "-5"}),
               "--budget-pixels: -5 is outside 0..1e+09 px");
  expect_error(with({"--mode", "budget", "--budget-ms", "-0.5"}),
               "--budget-ms: -0.5 is outside 0..1e+09 ms");
  expect_error(with({"--mode", "budget", "--budget-ms", "x"}), "--budget-ms: 'x' is not");
  expect_error(with({"--mode", "budget", "--budget-pixels", "10", "--budget-ms", "2"}), "not both");
  expect_error(with({"--budget-pixels", "1000"}), "--budget-pixels: needs --mode budget");
  expect_error(with({"--mode", "affine", "--budget-ms", "3"}), "--budget-ms: needs --mode budget");
  expect_error({"compare", "--script", "rotation", "--policies", "perspective,talisman",
                "--budget-pixels", "1000"},
               "--budget-pixels: needs budget in --policies");
  expect_error({"animate", "--scene", "four-cubes", "--script", "compound", "--mode",
                "scene-shifting", "--budget-pixels", "10"},
               "--budget-pixels: not used by --mode scene-shifting");
}

}  // namespace
}  // namespace oflab
