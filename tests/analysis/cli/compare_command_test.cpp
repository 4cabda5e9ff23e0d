// `oflab-cli compare` and the policy runs under it (analysis/runs/policy_runs.h): every policy
// plays identical frames, the rows agree with `animate` run alone, the outputs, and
// one-line errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <numeric>
#include <sstream>
#include <string>

#include "cli/commands.h"
#include "cli_capture.h"
#include "formats/datasets.h"
#include "formats/image_io.h"
#include "formats/scene_file.h"
#include "formats/script_file.h"
#include "formats/viewer_script_file.h"
#include "runs/policy_runs.h"
#include "scratch_dir.h"

namespace oflab {
namespace {

using testing::CliResult;

CliResult run(const std::vector<std::string>& args) { return testing::run_cli_captured(args); }

PlayOptions quick_options(int frames) {
  PlayOptions o;
  o.max_frames = frames;
  o.timing_repetitions = 1;
  return o;
}

void expect_same_views(const std::vector<PolicyRun>& runs, int frames) {
  for (const PolicyRun& r : runs) {
    ASSERT_EQ(static_cast<int>(r.run.frames.size()), frames) << r.policy->name;
    ASSERT_EQ(r.views.size(), runs.front().views.size()) << r.policy->name;
    for (size_t i = 0; i < r.views.size(); ++i) {
      EXPECT_EQ(r.views[i].rotation, runs.front().views[i].rotation) << r.policy->name << " " << i;
      EXPECT_EQ(r.views[i].translation, runs.front().views[i].translation)
          << r.policy->name << " " << i;
    }
  }
}

TEST(PolicyRuns, EveryPolicyPlaysTheSameFramesOfAPlane) {
  RunSource source;
  source.script = read_script_file(resolve_script_path("zoom-rotation"));
  source.texture = read_image(default_texture_path());
  std::vector<const ReusePolicy*> all;
  for (const ReusePolicy& p : reuse_policies()) {
    // The node-image cache and frame generation play scenes only, and say so.
    if (needs_scene(p)) {
      EXPECT_THROW(run_policies(source_kind("plane"), source, {&p}, quick_options(2)),
                   std::invalid_argument);
      continue;
    }
    all.push_back(&p);
  }
  const auto runs = run_policies(source_kind("plane"), source, all, quick_options(25));
  ASSERT_EQ(runs.size(), all.size());
  expect_same_views(runs, 25);
  // The poses really move: the views are not all the same.
  EXPECT_NE(runs.front().views.front().translation, runs.front().views.back().translation);
}

TEST(PolicyRuns, EveryPolicyPlaysTheSameFramesOfAScene) {
  RunSource source;
  source.scene = std::make_shared<const Scene>(read_scene_file(resolve_scene_path("two")));
  source.viewer = read_viewer_script_file(resolve_viewer_script_path("compound"));
  const auto runs = run_policies(
      source_kind("scene"), source,
      parse_policy_list("perspective,talisman,dissertation,hierarchical-cache,mv-extrapolation,"
                        "mv-no-inpaint,view-interpolation,depth-mesh"),
      quick_options(12));
  expect_same_views(runs, 12);
}

TEST(PolicyRuns, PolicyListsAreCheckedAgainstTheRegistry) {
  const auto list = parse_policy_list("talisman,rerender");
  ASSERT_EQ(list.size(), 2u);
  EXPECT_EQ(list[0], &reuse_policy("talisman"));
  EXPECT_EQ(list[1], &reuse_policy("rerender"));
  EXPECT_THROW(parse_policy_list("talisman,bogus"), std::invalid_argument);
  EXPECT_THROW(parse_policy_list("talisman,talisman"), std::invalid_argument);
  EXPECT_THROW(parse_policy_list(""), std::invalid_argument);
}

// The rows are the animate summaries of each policy run alone (levels, work, error).
TEST(CompareCommand, JsonRowsAgreeWithAnimateRunAlone) {
  const CliResult r = run({"compare", "--script", "rotation", "--policies", "talisman,perspective",
                           "--frames", "30", "--repeat-timing", "1", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j.at("policies").size(), 2u);
  EXPECT_EQ(j["policies"][0]["name"], "talisman");
  EXPECT_EQ(j["policies"][1]["name"], "perspective");
  for (const auto& row : j["policies"]) {
    const CliResult alone =
        run({"animate", "--script", "rotation", "--mode", row["name"].get<std::string>(),
             "--frames", "30", "--repeat-timing", "1", "--json"});
    ASSERT_EQ(alone.code, 0) << alone.err;
    const auto a = nlohmann::json::parse(alone.out);
    double sum = 0.0;
    for (const auto& [level, count] : a.at("levels").items()) {
      EXPECT_NEAR(row["levels"][level].get<double>(), 100.0 * count.get<double>() / 30.0, 1e-9)
          << row["name"] << " " << level;
      sum += row["levels"][level].get<double>();
    }
    EXPECT_NEAR(sum, 100.0, 1e-9);
    EXPECT_DOUBLE_EQ(row["work_saved"].get<double>(), a["work_saved"].get<double>());
    EXPECT_DOUBLE_EQ(row["max_measured_error_px"].get<double>(),
                     a["max_measured_error_px"].get<double>());
    EXPECT_EQ(row["frames"], 30);
  }
}

// One reading of a scene run (read_scene_source): the same options give compare and animate
// the same run, the scene's own content quality included (the street's is 3).
TEST(CompareCommand, SceneRowsAreAnimateRunAloneAtTheScenesContentQuality) {
  const std::vector<std::string> common = {
      "--scene", "street", "--script", "walk", "--frames", "2", "--repeat-timing", "1", "--json"};
  std::vector<std::string> compare = {"compare", "--policies", "perspective,hierarchical-cache"};
  compare.insert(compare.end(), common.begin(), common.end());
  const CliResult r = run(compare);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto rows = nlohmann::json::parse(r.out).at("policies");
  ASSERT_EQ(rows.size(), 2u);
  for (const auto& row : rows) {
    std::vector<std::string> animate = {"animate", "--mode", row["name"].get<std::string>()};
    animate.insert(animate.end(), common.begin(), common.end());
    const CliResult alone = run(animate);
    ASSERT_EQ(alone.code, 0) << alone.err;
    const auto a = nlohmann::json::parse(alone.out);
    EXPECT_DOUBLE_EQ(row["model_work_saved"].get<double>(), a["model_work_saved"].get<double>())
        << row["name"];
    EXPECT_DOUBLE_EQ(row["work_saved"].get<double>(), a["work_saved"].get<double>());
    EXPECT_DOUBLE_EQ(row["max_measured_error_px"].get<double>(),
                     a["max_measured_error_px"].get<double>());
  }
  // Control: at quality 1 the same run's work differs, so the check above can fail.
  compare.insert(compare.end(), {"--quality", "1"});
  const auto low = nlohmann::json::parse(run(compare).out).at("policies");
  EXPECT_NE(low[0]["model_work_saved"].get<double>(), rows[0]["model_work_saved"].get<double>());
}

// The seam with layer contents: compare takes --content and --quality as animate does, and
// its model_work_saved is animate's for the same policy and content.
TEST(CompareCommand, ContentAndQualityReachEveryPolicyAndModelWorkMatchesAnimate) {
  const std::vector<std::string> common = {"--script",        "rotation", "--content", "shaded",
                                           "--quality",       "2",        "--frames",  "12",
                                           "--repeat-timing", "1",        "--json"};
  std::vector<std::string> compare = {"compare", "--policies", "perspective,rerender"};
  compare.insert(compare.end(), common.begin(), common.end());
  const CliResult r = run(compare);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto rows = nlohmann::json::parse(r.out).at("policies");
  ASSERT_EQ(rows.size(), 2u);
  std::vector<std::string> texture = compare;
  texture[std::find(texture.begin(), texture.end(), "shaded") - texture.begin()] = "texture";
  const auto texture_rows = nlohmann::json::parse(run(texture).out).at("policies");
  for (std::size_t i = 0; i < rows.size(); ++i) {
    std::vector<std::string> animate = {"animate", "--mode", rows[i]["name"].get<std::string>()};
    animate.insert(animate.end(), common.begin(), common.end());
    const CliResult alone = run(animate);
    ASSERT_EQ(alone.code, 0) << alone.err;
    const auto a = nlohmann::json::parse(alone.out);
    EXPECT_DOUBLE_EQ(rows[i]["model_work_saved"].get<double>(), a["model_work_saved"].get<double>())
        << rows[i]["name"];
  }
  // The content reached the runs: a shaded re-render costs more than the texture's, so the
  // perspective policy saves more of the model's work with it.
  EXPECT_GT(rows[0]["model_work_saved"].get<double>(),
            texture_rows[0]["model_work_saved"].get<double>());
  EXPECT_DOUBLE_EQ(rows[1]["model_work_saved"].get<double>(), 0.0);  // re-render saves nothing
}

TEST(CompareCommand, TextTableHasARowPerPolicyAndOutWritesTheCsvs) {
  const std::filesystem::path dir = testing::fresh_test_dir("oflab-compare");
  std::filesystem::remove(dir);
  const CliResult r =
      run({"compare", "--script", "translation-1", "--policies", "dissertation,talisman,rerender",
           "--frames", "10", "--repeat-timing", "1", "--out", dir.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* name : {"dissertation", "talisman", "rerender"}) {
    EXPECT_NE(r.out.find(std::string("\n") + name + " "), std::string::npos) << r.out;
    EXPECT_TRUE(std::filesystem::exists(dir / (std::string(name) + ".csv"))) << name;
  }
  std::ifstream summary(dir / "summary.csv");
  std::string line;
  int lines = 0;
  while (std::getline(summary, line)) {
    if (lines == 0) {
      EXPECT_NE(line.find(",model_work_saved,"), std::string::npos) << line;
      EXPECT_NE(line.find(",frames_over_budget,starved_layer_frames,mean_optimality_gap"),
                std::string::npos)
          << line;
    }
    ++lines;
  }
  EXPECT_EQ(lines, 4);  // header and three policies
  std::filesystem::remove_all(dir);
}

// The column `name` of a per-frame CSV (`compare --out`'s POLICY.csv), as integers.
std::vector<std::int64_t> csv_column(const std::filesystem::path& file, const std::string& name) {
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  std::stringstream header(line);
  std::string cell;
  int column = 0;
  while (std::getline(header, cell, ',') && cell != name) ++column;
  std::vector<std::int64_t> values;
  while (std::getline(in, line)) {
    std::stringstream row(line);
    for (int c = 0; c <= column; ++c) std::getline(row, cell, ',');
    values.push_back(std::stoll(cell));
  }
  return values;
}

// The nearest-rank percentile by its definition: the smallest of the values that at least
// `percent` percent of them do not exceed.
std::int64_t smallest_covering(const std::vector<std::int64_t>& values, double percent) {
  std::int64_t best = std::numeric_limits<std::int64_t>::max();
  for (std::int64_t v : values) {
    const auto covered =
        std::count_if(values.begin(), values.end(), [v](std::int64_t x) { return x <= v; });
    if (100.0 * double(covered) >= percent * double(values.size())) best = std::min(best, v);
  }
  return best;
}

TEST(PolicyRuns, NearestRankPercentileIsTheTextbookOne) {
  const std::vector<std::int64_t> v = {15, 20, 35, 40, 50};  // the usual worked example
  EXPECT_EQ(nearest_rank_percentile(v, 5.0), 15);
  EXPECT_EQ(nearest_rank_percentile(v, 30.0), 20);
  EXPECT_EQ(nearest_rank_percentile(v, 40.0), 20);
  EXPECT_EQ(nearest_rank_percentile(v, 50.0), 35);
  EXPECT_EQ(nearest_rank_percentile(v, 100.0), 50);
  EXPECT_EQ(nearest_rank_percentile({}, 95.0), 0);
  std::vector<std::int64_t> twenty;  // 95 % of 20 is rank 19 exactly, not 20
  for (int i = 1; i <= 20; ++i) twenty.push_back(i);
  EXPECT_EQ(nearest_rank_percentile(twenty, 95.0), 19);
  EXPECT_EQ(smallest_covering(twenty, 95.0), 19);
}

// pixels_written_p95 and _max are the per-frame pixels of the run's CSV, frame 0 left out,
// computed here by the definition; pixels_written is the total over every frame.
TEST(CompareCommand, PixelPeaksAreThePerFramePixelsWithoutFrameZero) {
  const std::filesystem::path dir = testing::fresh_test_dir("oflab-compare-peaks");
  std::filesystem::remove(dir);
  const CliResult r =
      run({"compare", "--script", "zoom-rotation", "--policies", "perspective,rerender", "--frames",
           "24", "--repeat-timing", "1", "--json", "--out", dir.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto rows = nlohmann::json::parse(r.out).at("policies");
  for (const auto& row : rows) {
    const auto all = csv_column(dir / (row["name"].get<std::string>() + ".csv"), "pixels_written");
    ASSERT_EQ(all.size(), 24u);
    const std::vector<std::int64_t> later(all.begin() + 1, all.end());
    EXPECT_EQ(row["pixels_written"].get<std::int64_t>(),
              std::accumulate(all.begin(), all.end(), std::int64_t{0}));
    EXPECT_EQ(row["pixels_written_max"].get<std::int64_t>(),
              *std::max_element(later.begin(), later.end()));
    EXPECT_EQ(row["pixels_written_p95"].get<std::int64_t>(), smallest_covering(later, 95.0));
  }
  // Control: the 95th percentile is not the largest frame here (zoom-rotation's frames grow),
  // so the two fields are computed apart.
  EXPECT_LT(rows[0]["pixels_written_p95"].get<std::int64_t>(),
            rows[0]["pixels_written_max"].get<std::int64_t>());
  std::filesystem::remove_all(dir);
}

TEST(CompareCommand, BadInputIsOneLineWithExitCodeTwo) {
  const auto expect_error = [](const std::vector<std::string>& args, const std::string& text) {
    const CliResult r = run(args);
    EXPECT_EQ(r.code, 2) << r.out;
    EXPECT_NE(r.err.find(text), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  };
  expect_error({"compare", "--script", "rotation", "--policies", "bogus"},
               "--policies: unknown policy 'bogus'");
  expect_error({"compare", "--script", "rotation"}, "--policies");
  expect_error({"compare", "--policies", "talisman"}, "--script");
  expect_error({"compare", "--script", "nope", "--policies", "talisman"}, "--script");
  expect_error({"compare", "--script", "rotation", "--policies", "talisman", "--near", "1"},
               "--near: needs --scene");
  expect_error({"compare", "--script", "rotation", "--policies", "talisman", "--mode", "exact"},
               "--mode");
}

}  // namespace
}  // namespace oflab
