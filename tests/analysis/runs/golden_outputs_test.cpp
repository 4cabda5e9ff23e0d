// Golden outputs: `oflab-cli animate --json --out DIR` of fixed runs, compared exactly with
// fixtures recorded from an earlier build (tests/analysis/golden/). Times are measured, so
// they are dropped before the comparison: JSON keys and CSV columns whose name holds
// "time", "_ms" or "fps". Everything else (level counts, pixels, errors, PSNR, notes) must
// be identical, digit for digit.
//
// A change of behaviour on purpose updates the fixtures in the same commit, saying why:
//   OFLAB_UPDATE_GOLDEN=1 build/tests/analysis/oflab_analysis_tests --gtest_filter='Golden*'
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli_capture.h"

namespace oflab {
namespace {

namespace fs = std::filesystem;

bool is_time_name(const std::string& name) {
  return name.find("time") != std::string::npos || name.find("_ms") != std::string::npos ||
         name.find("fps") != std::string::npos;
}

void drop_times(nlohmann::json& j) {
  if (j.is_object()) {
    for (auto it = j.begin(); it != j.end();) {
      if (is_time_name(it.key())) {
        it = j.erase(it);
      } else {
        drop_times(it.value());
        ++it;
      }
    }
  } else if (j.is_array()) {
    for (auto& e : j) drop_times(e);
  }
}

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, ',')) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.push_back("");
  return cells;
}

// The CSV without its time columns (the header names them).
std::string csv_without_times(const std::string& text) {
  std::istringstream in(text);
  std::string line;
  std::vector<bool> keep;
  std::ostringstream out;
  bool header = true;
  while (std::getline(in, line)) {
    const std::vector<std::string> cells = split_csv_line(line);
    if (header) {
      for (const std::string& c : cells) keep.push_back(!is_time_name(c));
      header = false;
    }
    std::string sep;
    for (size_t i = 0; i < cells.size(); ++i) {
      if (i < keep.size() && !keep[i]) continue;
      out << sep << cells[i];
      sep = ",";
    }
    out << "\n";
  }
  return out.str();
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_text(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

struct GoldenCase {
  std::string name;
  std::vector<std::string> args;
};

std::vector<GoldenCase> golden_cases() {
  std::vector<GoldenCase> cases;
  for (const char* script : {"loop", "rotation", "zoom"}) {
    for (const char* mode : {"perspective", "affine", "exact", "rerender"}) {
      cases.push_back({std::string(script) + "-" + mode, {"--script", script, "--mode", mode}});
    }
  }
  cases.push_back({"four-cubes-compound", {"--scene", "four-cubes", "--script", "compound"}});
  // The budget policy's allocation is deterministic with a pixel budget.
  cases.push_back({"four-cubes-budget",
                   {"--scene", "four-cubes", "--script", "compound", "--mode", "budget",
                    "--budget-pixels", "12000"}});
  cases.push_back(
      {"train-window-scene-shifting",
       {"--scene", "train-window", "--script", "train-sideways", "--mode", "scene-shifting"}});
  return cases;
}

class Golden : public ::testing::TestWithParam<GoldenCase> {};

// `oflab-cli animate ARGS --json --quiet --out DIR` without its times: the summary and the
// frames' CSV. `tag` names the scratch folder.
struct AnimateOutputs {
  std::string summary_text;
  std::string csv_text;
};

AnimateOutputs animate_outputs(const std::vector<std::string>& given, const std::string& tag) {
  // Per process, so parallel runs of the suite (several build trees) never share a folder.
  const fs::path out_dir =
      fs::temp_directory_path() / ("oflab-golden-" + std::to_string(getpid()) + "-" + tag);
  fs::remove_all(out_dir);
  std::vector<std::string> args = {"animate"};
  args.insert(args.end(), given.begin(), given.end());
  args.insert(args.end(), {"--json", "--quiet", "--out", out_dir.string()});
  const testing::CliResult r = testing::run_cli_captured(args);
  EXPECT_EQ(r.code, 0) << r.err;
  if (r.code != 0) return {};
  nlohmann::json summary = nlohmann::json::parse(r.out);
  drop_times(summary);
  AnimateOutputs outputs{summary.dump(2) + "\n",
                         csv_without_times(read_text(out_dir / "frames.csv"))};
  fs::remove_all(out_dir);
  return outputs;
}

TEST_P(Golden, AnimateOutputsAreUnchanged) {
  const GoldenCase& c = GetParam();
  const fs::path fixtures = fs::path(OFLAB_GOLDEN_DIR) / c.name;
  const AnimateOutputs outputs = animate_outputs(c.args, c.name);
  const std::string& summary_text = outputs.summary_text;
  const std::string& csv_text = outputs.csv_text;
  ASSERT_FALSE(summary_text.empty());

  if (std::getenv("OFLAB_UPDATE_GOLDEN")) {
    fs::create_directories(fixtures);
    write_text(fixtures / "summary.json", summary_text);
    write_text(fixtures / "frames.csv", csv_text);
    GTEST_SKIP() << "fixtures written to " << fixtures;
  }
  ASSERT_TRUE(fs::exists(fixtures / "summary.json")) << "missing fixture " << fixtures;
  ASSERT_TRUE(fs::exists(fixtures / "frames.csv")) << "missing fixture " << fixtures;
  EXPECT_EQ(summary_text, read_text(fixtures / "summary.json")) << c.name << ": summary";
  EXPECT_EQ(csv_text, read_text(fixtures / "frames.csv")) << c.name << ": frames.csv";
}

// The pixel loops' threads (core/image/thread_pool.h) change nothing but the times: four
// cubes as facade impostors (the lit content whose render is cut into bands of rows and of
// faces), with the exact re-render beside the engine, on 1 thread and on 2.
TEST(GoldenThreads, ImpostorCubesAreTheSameOnOneAndTwoThreads) {
  const auto run = [](const char* frames, const char* threads) {
    return animate_outputs({"--scene", "four-cubes", "--script", "compound", "--frames", frames,
                            "--content", "impostor", "--no-warm-up", "--threads", threads},
                           std::string("cubes-") + frames + "-" + threads);
  };
  const AnimateOutputs a = run("6", "1"), b = run("6", "2");
  ASSERT_FALSE(a.summary_text.empty());
  EXPECT_EQ(a.summary_text, b.summary_text);
  EXPECT_EQ(a.csv_text, b.csv_text);
  // Negative control: one frame more is a different run, and the comparison sees it.
  EXPECT_NE(run("7", "2").csv_text, a.csv_text);
}

INSTANTIATE_TEST_SUITE_P(Runs, Golden, ::testing::ValuesIn(golden_cases()),
                         [](const ::testing::TestParamInfo<GoldenCase>& info) {
                           std::string n = info.param.name;
                           for (char& ch : n) {
                             if (ch == '-') ch = '_';
                           }
                           return n;
                         });

}  // namespace
}  // namespace oflab
