// Today's reprojection from the command line (manual/policies.md "Today's reprojection"): the
// claims of issue 27's "done when", each measured on the shipped scenes and viewer scripts.
#include <gtest/gtest.h>

#include <algorithm>
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

// The index of the column named `name` in a CSV header (header.size() when absent).
std::size_t column(const std::vector<std::string>& header, const std::string& name) {
  return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
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
  const std::size_t hole_column = column(rows[0], "hole_pixels");
  ASSERT_LT(hole_column, rows[0].size());
  long total = 0;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    ASSERT_EQ(rows[i].size(), rows[0].size());
    const long holes = std::stol(rows[i][hole_column]);
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

// A policy on a fixed cadence keeps it, or every frame says why not: per row of the CSV the
// causes add up to the re-rendered polygons; with Delta 1 the cadence is kept exactly (every
// drawn polygon on even frames, none on odd ones); with the default Delta the re-renders
// beyond it are the sampling limit's, named frame by frame.
TEST(Reprojection, EveryReRenderOffTheCadenceIsNamedPerFrame) {
  const std::filesystem::path dir = testing::fresh_test_dir("oflab-cadence-causes");
  const std::vector<std::string> causes = {"rerender_schedule", "rerender_sampling_limit",
                                           "rerender_refused", "rerender_no_image",
                                           "rerender_clipped"};
  for (const std::string delta : {"1", "dissertation"}) {
    const std::string out = (dir / delta).string();
    const CliResult r = testing::run_cli_captured(
        {"animate",  "--scene",     "four-cubes", "--script", "rotate",  "--mode",
         "timewarp", "--cadence",   "2",          "--delta",  delta,     "--frames",
         "40",       "--out",       out,          "--json",   "--quiet", "--repeat-timing",
         "1",        "--no-warm-up"});
    ASSERT_EQ(r.code, 0) << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out);
    const auto rows = read_csv(out + "/frames.csv");
    ASSERT_EQ(rows.size(), 41u);
    const std::size_t rerender = column(rows[0], "rerender"), drawn = column(rows[0], "drawn");
    long sampling_limit = 0;
    for (std::size_t i = 1; i < rows.size(); ++i) {
      long sum = 0;
      for (const std::string& cause : causes) sum += std::stol(rows[i].at(column(rows[0], cause)));
      EXPECT_EQ(sum, std::stol(rows[i].at(rerender))) << "delta " << delta << ", row " << i;
      sampling_limit += std::stol(rows[i].at(column(rows[0], "rerender_sampling_limit")));
      if (delta == "1") {
        const long expected = (i - 1) % 2 == 0 ? std::stol(rows[i].at(drawn)) : 0;
        EXPECT_EQ(std::stol(rows[i].at(rerender)), expected) << "row " << i;
      }
    }
    const nlohmann::json& c = j.at("rerender_causes");
    EXPECT_EQ(c["sampling_limit"].get<long>(), sampling_limit);
    if (delta == "1") {
      EXPECT_EQ(c["sampling_limit"].get<long>() + c["refused"].get<long>() +
                    c["no_image"].get<long>() + c["clipped"].get<long>(),
                0);
    } else {
      EXPECT_GT(sampling_limit, 0);  // the default Delta's cache is magnified past the limit
    }
  }
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

// compare checks --cadence by the one rule of limits::kCadence (1..8), and refuses it, as it
// refuses --stabilization-plane and --hole-fill, when no compared policy reads it: one line
// naming the option, the value or the policies that read it.
TEST(Reprojection, CompareRefusesACadenceOutOfRangeOrWithoutACadencePolicy) {
  const std::vector<std::string> base = {"compare",   "--scene",  "four-cubes", "--script",
                                         "translate", "--frames", "2",          "--quiet"};
  const auto compare = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = base;
    args.insert(args.end(), extra.begin(), extra.end());
    return testing::run_cli_captured(args);
  };
  for (const char* bad : {"0", "9", "2.5"}) {
    const CliResult r = compare({"--policies", "timewarp,perspective", "--cadence", bad});
    EXPECT_EQ(r.code, 2) << bad;
    EXPECT_NE(r.err.find("--cadence"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(bad), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("1..8"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  const CliResult none = compare({"--policies", "perspective,talisman", "--cadence", "3"});
  EXPECT_EQ(none.code, 2);
  EXPECT_NE(none.err.find("--cadence: needs one of timewarp, stabilized-plane, "
                          "depth-reprojection, cadence, mv-extrapolation, "
                          "mv-no-inpaint, view-interpolation, depth-mesh in --policies, not "
                          "'perspective,talisman'"),
            std::string::npos)
      << none.err;
  const CliResult plane =
      compare({"--policies", "timewarp", "--stabilization-plane", "0", "0", "1", "0", "0", "1"});
  EXPECT_EQ(plane.code, 2);
  EXPECT_NE(plane.err.find("--stabilization-plane: needs one of stabilized-plane"),
            std::string::npos)
      << plane.err;
  const CliResult fill = compare({"--policies", "cadence", "--hole-fill", "stretch"});
  EXPECT_EQ(fill.code, 2);
  EXPECT_NE(fill.err.find("--hole-fill: needs one of depth-reprojection"), std::string::npos)
      << fill.err;
  // The control: a cadence in range with a cadence policy compared plays.
  const CliResult good = compare({"--policies", "perspective,cadence", "--cadence", "8"});
  EXPECT_EQ(good.code, 0) << good.err;
}

}  // namespace
}  // namespace oflab
