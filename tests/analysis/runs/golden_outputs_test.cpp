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

TEST_P(Golden, AnimateOutputsAreUnchanged) {
  const GoldenCase& c = GetParam();
  const fs::path fixtures = fs::path(OFLAB_GOLDEN_DIR) / c.name;
  // Per process, so parallel runs of the suite (several build trees) never share a folder.
  const fs::path out_dir =
      fs::temp_directory_path() / ("oflab-golden-" + std::to_string(getpid()) + "-" + c.name);
  fs::remove_all(out_dir);
  std::vector<std::string> args = {"animate"};
  args.insert(args.end(), c.args.begin(), c.args.end());
  args.insert(args.end(), {"--json", "--quiet", "--out", out_dir.string()});
  const testing::CliResult r = testing::run_cli_captured(args);
  ASSERT_EQ(r.code, 0) << r.err;

  nlohmann::json summary = nlohmann::json::parse(r.out);
  drop_times(summary);
  const std::string summary_text = summary.dump(2) + "\n";
  const std::string csv_text = csv_without_times(read_text(out_dir / "frames.csv"));
  fs::remove_all(out_dir);

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
