// Today's reprojection from the command line (manual/policies.md "Today's reprojection"): the
// claims of issue 27's "done when", each measured on the shipped scenes and viewer scripts.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli_capture.h"
#include "scratch_dir.h"

namespace oflab {
namespace {

using testing::CliResult;

// `animate --json` of a scene, one timed pass (the figures checked are deterministic).
nlohmann::json animate_scene(const std::string& scene, const std::string& script,
                             const std::string& mode, std::vector<std::string> extra = {}) {
  std::vector<std::string> args = {"animate", "--scene",         scene, "--script",
                                   script,    "--mode",          mode,  "--json",
                                   "--quiet", "--repeat-timing", "1",   "--no-warm-up"};
  args.insert(args.end(), extra.begin(), extra.end());
  const CliResult r = testing::run_cli_captured(args);
  EXPECT_EQ(r.code, 0) << r.err;
  return r.code == 0 ? nlohmann::json::parse(r.out) : nlohmann::json::object();
}

std::vector<std::vector<std::string>> read_csv(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::vector<std::string>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream cells_in(line);
    std::string cell;
    while (std::getline(cells_in, cell, ',')) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

TEST(Reprojection, TimewarpIsExactWhenTheViewerRolls) {
  const nlohmann::json j = animate_scene("four-cubes", "rotate", "timewarp");
  EXPECT_LE(j["max_measured_error_px"].get<double>(), 0.5);
}

TEST(Reprojection, TimewarpIsBlindToTranslationWherePerspectiveIsNot) {
  EXPECT_GT(
      animate_scene("four-cubes", "translate", "timewarp")["max_measured_error_px"].get<double>(),
      2.0);
  EXPECT_LE(animate_scene("four-cubes", "translate", "perspective")["max_measured_error_px"]
                .get<double>(),
            1.0);
}

TEST(Reprojection, DepthReprojectionHasHolesWhereCubesDisoccludeAndNoneOnAZoom) {
  // The first 60 frames of compound translate past the cubes: the near ones uncover the far.
  const nlohmann::json cubes =
      animate_scene("four-cubes", "compound", "depth-reprojection", {"--frames", "60"});
  EXPECT_GT(cubes["hole_pixels"].get<long>(), 0);
  // Zooming in magnifies the plane: splatting closes the cracks; zooming out reveals only
  // the empty background, which is no hole.
  const nlohmann::json zoom = animate_scene("single-1", "zoom", "depth-reprojection");
  EXPECT_EQ(zoom["hole_pixels"].get<long>(), 0);
  EXPECT_EQ(zoom["frames"], 100);
}

TEST(Reprojection, SummariesAndThePerFrameCsvCarryHolePixels) {
  const std::filesystem::path dir = testing::fresh_test_dir("oflab-reprojection");
  const std::string out = (dir / "run").string();
  const CliResult r = testing::run_cli_captured(
      {"animate", "--scene", "four-cubes", "--script", "translate", "--mode", "depth-reprojection",
       "--frames", "30", "--cadence", "4", "--out", out, "--json", "--quiet", "--repeat-timing",
       "1", "--no-warm-up"});
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  const auto rows = read_csv(out + "/frames.csv");
  ASSERT_EQ(rows.size(), 31u);
  ASSERT_EQ(rows[0].back(), "hole_pixels");
  long total = 0;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    ASSERT_EQ(rows[i].size(), rows[0].size());
    const long holes = std::stol(rows[i].back());
    if ((i - 1) % 4 == 0) EXPECT_EQ(holes, 0) << "a rendered frame, row " << i;
    total += holes;
  }
  EXPECT_GT(total, 0);
  EXPECT_EQ(j["hole_pixels"].get<long>(), total);
  std::ifstream summary(out + "/summary.json");
  EXPECT_EQ(nlohmann::json::parse(summary)["hole_pixels"].get<long>(), total);

  const CliResult c =
      testing::run_cli_captured({"compare", "--scene", "four-cubes", "--script", "translate",
                                 "--policies", "perspective,depth-reprojection", "--frames", "30",
                                 "--cadence", "4", "--json", "--quiet", "--repeat-timing", "1"});
  ASSERT_EQ(c.code, 0) << c.err;
  const nlohmann::json rows_json = nlohmann::json::parse(c.out)["policies"];
  EXPECT_EQ(rows_json[0]["hole_pixels"], 0);
  EXPECT_EQ(rows_json[1]["hole_pixels"].get<long>(), total);
  EXPECT_EQ(rows_json[1]["latency_frames"], 0);
  std::filesystem::remove_all(dir);
}

TEST(Reprojection, AutomaticStabilizationPlaneOfOnePlaneMatchesCadenceFrameForFrame) {
  const std::filesystem::path dir = testing::fresh_test_dir("oflab-stabilized");
  const std::string out = (dir / "cmp").string();
  const CliResult r =
      testing::run_cli_captured({"compare", "--scene", "single-1", "--script", "circle",
                                 "--policies", "stabilized-plane,cadence", "--cadence", "3",
                                 "--out", out, "--quiet", "--repeat-timing", "1"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto a = read_csv(out + "/stabilized-plane.csv");
  const auto b = read_csv(out + "/cadence.csv");
  ASSERT_EQ(a.size(), b.size());
  ASSERT_GT(a.size(), 300u);
  for (std::size_t i = 1; i < a.size(); ++i) {
    for (std::size_t k = 0; k < a[0].size(); ++k) {
      const std::string& column = a[0][k];
      if (column.find("time") != std::string::npos || column.find("_ms") != std::string::npos) {
        continue;
      }
      // The two homographies agree to rounding: errors differ by ~1e-12 px at most.
      if (column == "max_measured_error_px") {
        EXPECT_NEAR(std::stod(a[i][k]), std::stod(b[i][k]), 1e-9) << "frame " << i - 1;
      } else {
        EXPECT_EQ(a[i][k], b[i][k]) << column << ", frame " << i - 1;
      }
    }
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace oflab
