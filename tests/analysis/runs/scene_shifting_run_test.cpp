// `oflab-cli animate --mode scene-shifting` on the train-window scene, and the runs behind it.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli_capture.h"
#include "formats/scene_file.h"
#include "formats/viewer_script_file.h"
#include "runs/source_kinds.h"

namespace oflab {
namespace {

using testing::run_cli_captured;

nlohmann::json animate_json(const std::string& mode) {
  const auto r = run_cli_captured({"animate", "--scene", "train-window", "--script",
                                   "train-sideways", "--mode", mode, "--frames", "6", "--json"});
  EXPECT_EQ(r.code, 0) << r.err;
  return nlohmann::json::parse(r.out);
}

TEST(AnimateSceneShifting, JsonSummaryHasEveryFieldOfTheOtherModes) {
  const nlohmann::json shifting = animate_json("scene-shifting");
  const nlohmann::json engine = animate_json("perspective");
  for (const auto& [key, value] : engine.items()) {
    EXPECT_TRUE(shifting.contains(key)) << "missing field " << key;
  }
  EXPECT_EQ(shifting["mode"], "scene-shifting");
  EXPECT_EQ(shifting["frames"], 6);
  EXPECT_LE(shifting["max_measured_error_px"].get<double>(), 1.0 + 1e-9);
  EXPECT_GE(shifting["scene_shifting"]["slices"].size(), 2u);
}

TEST(AnimateSceneShifting, NeedsASceneAndRejectsEngineOptions) {
  auto r = run_cli_captured({"animate", "--script", "translate", "--mode", "scene-shifting"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--mode scene-shifting"), std::string::npos) << r.err;
  r = run_cli_captured({"animate", "--scene", "train-window", "--script", "train-sideways",
                        "--mode", "scene-shifting", "--epsilon", "0"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--epsilon"), std::string::npos) << r.err;
  r = run_cli_captured({"animate", "--scene", "two", "--script", "translate", "--mode",
                        "scene-shifting", "--frames", "2"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("not parallel to the image plane"), std::string::npos) << r.err;
}

TEST(SceneShiftingRun, TurningScriptRebuildsEveryOccupiedSliceEveryTurningFrame) {
  RunSource source;
  source.scene = std::make_shared<const Scene>(read_scene_file(resolve_scene_path("train-window")));
  source.viewer = read_viewer_script_file(resolve_viewer_script_path("train-turning"));
  PlayOptions options;
  options.max_frames = 8;
  const AnimationRun run = source_kind("scene-shifting").play(source, options);
  const nlohmann::json& facts = run.facts.at("scene_shifting");
  EXPECT_EQ(facts.at("turning_frames"), 7);
  EXPECT_EQ(facts.at("turning_frames_all_rebuilt"), facts.at("turning_frames"));
  EXPECT_EQ(facts.at("shifted_layers"), 0);
}

}  // namespace
}  // namespace oflab
