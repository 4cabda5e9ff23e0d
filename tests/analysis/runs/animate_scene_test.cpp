// `oflab-cli animate --scene`: the contracted summary, the CSV, the four-cube compound run
// in every mode, hidden-polygon and near-plane reports, and argument errors.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli/commands.h"
#include "cli_capture.h"
#include "scratch_dir.h"

namespace oflab {
namespace {

namespace fs = std::filesystem;

using Cli = testing::CliResult;

Cli cli(const std::vector<std::string>& args) { return testing::run_cli_captured(args); }

nlohmann::json run_json(const std::vector<std::string>& args) {
  std::vector<std::string> all = {"animate"};
  all.insert(all.end(), args.begin(), args.end());
  // These tests read levels and counts, not times: one timed pass (after the warm-up).
  all.insert(all.end(), {"--json", "--quiet", "--repeat-timing", "1"});
  const Cli c = cli(all);
  EXPECT_EQ(c.code, 0) << c.err;
  return c.code == 0 ? nlohmann::json::parse(c.out) : nlohmann::json::object();
}

long level_sum(const nlohmann::json& j) {
  long n = 0;
  for (const char* k : {"none", "translate", "affine", "perspective", "rerender"}) {
    n += j["polygon_levels"][k].get<long>();
  }
  return n;
}

TEST(AnimateScene, FourCubesCompoundRunsInEveryModeWithTheContractedSummary) {
  for (const char* mode : {"perspective", "affine", "exact", "rerender"}) {
    const nlohmann::json j =
        run_json({"--scene", "four-cubes", "--script", "compound", "--mode", mode});
    ASSERT_TRUE(j.contains("polygon_levels")) << mode;
    EXPECT_EQ(j["frames"], 401);
    EXPECT_EQ(j["polygons"], 20);
    for (const char* k : {"none", "translate", "affine", "perspective", "rerender"}) {
      EXPECT_TRUE(j["polygon_levels"].contains(k)) << k;
    }
    // Every polygon of every frame is drawn at some level, culled or hidden.
    EXPECT_EQ(level_sum(j) + j["culled"].get<long>() + j["hidden"].get<long>(), 20L * 401);
    EXPECT_GT(j["culled"].get<long>(), 0);  // the cubes' far faces
    for (const char* k : {"engine", "rerender"}) {
      EXPECT_GT(j["median_frame_ms"][k].get<double>(), 0.0) << k;
    }
    EXPECT_TRUE(j["median_frame_ms"].contains("conventional"));
    if (std::string(mode) == "rerender") {
      EXPECT_EQ(j["polygon_levels"]["rerender"].get<long>(), level_sum(j));
    } else {
      EXPECT_GT(
          j["polygon_levels"]["none"].get<long>() + j["polygon_levels"]["translate"].get<long>(),
          j["polygon_levels"]["rerender"].get<long>())
          << mode;
    }
    if (std::string(mode) != "affine") {
      EXPECT_LE(j["max_measured_error_px"].get<double>(), 1.25) << mode;
    }
  }
}

TEST(AnimateScene, TextSummaryShowsLevelsCullingHiddenAndFrameTimes) {
  const Cli c =
      cli({"animate", "--scene", "five-parallel", "--script", "translate", "--frames", "30"});
  ASSERT_EQ(c.code, 0) << c.err;
  for (const char* s : {"polygons per level", "perspective", "culled", "hidden",
                        "median frame time", "exact re-render"}) {
    EXPECT_NE(c.out.find(s), std::string::npos) << s << "\n" << c.out;
  }
}

TEST(AnimateScene, HiddenPolygonsAreReportedWithTheWorkSaved) {
  const nlohmann::json skip = run_json({"--scene", "five-parallel", "--script", "stationary"});
  EXPECT_EQ(skip["hidden"].get<long>(), 4L * skip["frames"].get<long>());
  EXPECT_GT(skip["hidden_area_px"].get<double>(), 0.0);
  const nlohmann::json all =
      run_json({"--scene", "five-parallel", "--script", "stationary", "--no-skip-hidden"});
  EXPECT_EQ(all["hidden"], 0);
  EXPECT_GT(all["pixels_written"].get<long>(), skip["pixels_written"].get<long>());
}

TEST(AnimateScene, FlyingThroughPolygonsClipsThemInEveryMode) {
  for (const char* mode : {"perspective", "affine", "exact", "rerender"}) {
    const nlohmann::json j =
        run_json({"--scene", "five-parallel", "--script", "fly-through", "--mode", mode});
    EXPECT_GT(j["clipped"].get<long>(), 10) << mode;
    EXPECT_GT(j["mean_psnr_db"].get<double>(), 30.0) << mode;
  }
}

TEST(AnimateScene, EveryShippedSceneRunsWithEveryShippedViewerScript) {
  for (const char* scene : {"single-0.1", "single-1", "single-3", "two", "five-collinear",
                            "five-semi-occluded", "five-parallel", "cube", "two-cubes"}) {
    for (const char* script :
         {"translate", "zoom", "rotate", "stationary", "circle", "fly-through"}) {
      const Cli c =
          cli({"animate", "--scene", scene, "--script", script, "--frames", "15", "--json"});
      EXPECT_EQ(c.code, 0) << scene << " " << script << ": " << c.err;
    }
  }
}

TEST(AnimateScene, WritesOneCsvRowPerFrame) {
  const fs::path scratch = testing::fresh_test_dir("oflab-animate-scene");
  const fs::path dir = scratch / "out";
  const Cli c = cli({"animate", "--scene", "two-cubes", "--script", "zoom", "--frames", "12",
                     "--out", dir.string(), "--frames-png", "--quiet"});
  ASSERT_EQ(c.code, 0) << c.err;
  std::ifstream csv(dir / "frames.csv");
  std::string header, line;
  std::getline(csv, header);
  for (const char* col :
       {"none", "rerender", "back_facing", "outside_frustum", "hidden", "clipped", "time_ms",
        "pixels_written", "rerender_time_ms", "conventional_time_ms"}) {
    EXPECT_NE(header.find(col), std::string::npos) << col;
  }
  int rows = 0;
  while (std::getline(csv, line)) ++rows;
  EXPECT_EQ(rows, 12);
  EXPECT_TRUE(fs::exists(dir / "frame_00011.png"));
  EXPECT_TRUE(fs::exists(dir / "summary.json"));
  fs::remove_all(scratch);
}

TEST(AnimateScene, BadOptionsNameTheOption) {
  EXPECT_NE(cli({"animate", "--scene", "no-such-scene", "--script", "zoom"}).err.find("--scene"),
            std::string::npos);
  EXPECT_NE(cli({"animate", "--scene", "cube", "--script", "no-such-script"}).err.find("--script"),
            std::string::npos);
  EXPECT_NE(cli({"animate", "--scene", "cube"}).err.find("--script"), std::string::npos);
  EXPECT_NE(cli({"animate", "--script", "zoom", "--compare-conventional"}).err.find("--scene"),
            std::string::npos);
  EXPECT_NE(
      cli({"animate", "--scene", "cube", "--script", "zoom", "--near", "0"}).err.find("--near"),
      std::string::npos);
  EXPECT_NE(cli({"animate", "--scene", "cube", "--script", "zoom", "--guard-band", "-1"})
                .err.find("--guard-band"),
            std::string::npos);
  EXPECT_NE(cli({"animate", "--scene", "cube", "--script", "zoom", "--texture", "/nonexistent.png"})
                .err.find("--texture"),
            std::string::npos);
  EXPECT_EQ(cli({"animate", "--scene", "cube", "--script", "zoom", "--mode", "fast"}).code, 2);
}

}  // namespace
}  // namespace oflab
