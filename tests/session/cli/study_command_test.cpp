// `oflab-cli study` (session/cli/study_command.h), run in process through oflab-cli's command
// table: the list, `simulate --json` against its golden output for a fixed seed, a simulated
// session's CSV written (never over a file without --force) and analysed alone and as a class,
// and bad input refused with exit code 2.
#include "cli/study_command.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli/cli_run.h"

namespace oflab {
namespace {

namespace fs = std::filesystem;

using testing::CliRun;

CliRun study(const CommandArgs& args) {
  return testing::run_session_command(study_command(), args);
}

std::string golden_text(const std::string& name) {
  std::ifstream in(std::string(OFLAB_SOURCE_DIR) + "/tests/session/golden/" + name);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(StudyCommand, ListsTheShippedStudies) {
  const CliRun r = study({"list"});
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("reuse-threshold"), std::string::npos);
  EXPECT_NE(r.out.find("class"), std::string::npos);
}

// The golden output changes only on purpose (a change of a method, the fit or the draws).
TEST(StudyCommand, SimulateJsonMatchesItsGoldenOutputForAFixedSeed) {
  const CliRun r = study({"simulate", "--study", "class", "--observer-threshold", "0.8",
                          "--sessions", "12", "--seed", "5", "--replicates", "40", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string golden = golden_text("study-simulate-class.json");
  ASSERT_FALSE(golden.empty()) << "missing golden file; the output was:\n" << r.out;
  EXPECT_EQ(nlohmann::json::parse(r.out), nlohmann::json::parse(golden)) << r.out;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["results"].size(), 4u);  // two conditions, two methods
  for (const auto& row : j["results"]) {
    EXPECT_GE(row["recovered_within_10pct"].get<double>(), 0.0);
    EXPECT_LE(row["ci_coverage"].get<double>(), 1.0);
    EXPECT_EQ(row["median_trials"].get<double>(), 30.0);
  }
}

TEST(StudyCommand, ASessionCsvIsWrittenOnceAndAnalysedAloneAndAsAClass) {
  const fs::path dir = fs::temp_directory_path() / ("oflab-study-cli-" + std::to_string(getpid()));
  fs::create_directories(dir);
  const std::string ann = (dir / "ann.csv").string(), bob = (dir / "bob.csv").string();
  const CommandArgs base = {"session", "--study", "class", "--observer-threshold", "1"};
  CommandArgs a = base, b = base;
  a.insert(a.end(), {"--csv", ann, "--observer", "ann", "--seed", "1", "--ppi", "110"});
  b.insert(b.end(), {"--csv", bob, "--observer", "bob", "--seed", "2", "--ppi", "110"});
  ASSERT_EQ(study(a).code, 0);
  ASSERT_EQ(study(b).code, 0);
  const CliRun again = study(a);
  EXPECT_EQ(again.code, 2);
  EXPECT_NE(again.err.find("--force"), std::string::npos) << again.err;
  a.push_back("--force");
  EXPECT_EQ(study(a).code, 0);

  const CliRun one = study({"analyse", ann, "--json", "--replicates", "40"});
  ASSERT_EQ(one.code, 0) << one.err;
  const nlohmann::json j1 = nlohmann::json::parse(one.out);
  ASSERT_EQ(j1["results"].size(), 2u);  // near and far, no class rows for one observer
  for (const auto& row : j1["results"]) {
    EXPECT_EQ(row["trials"], 30);
    const double t = row["threshold_px"], lo = row["ci95_px"][0], hi = row["ci95_px"][1];
    EXPECT_LT(lo, t);
    EXPECT_GT(hi, t);
    EXPECT_GT(row["threshold_arcmin"].get<double>(), 0.0);
  }
  const CliRun both = study({"analyse", ann, bob, "--json", "--replicates", "40"});
  ASSERT_EQ(both.code, 0) << both.err;
  const nlohmann::json j2 = nlohmann::json::parse(both.out);
  ASSERT_EQ(j2["results"].size(), 6u);  // two observers and the class, two conditions each
  EXPECT_TRUE(j2["results"][4]["observer"].is_null());
  EXPECT_EQ(j2["results"][4]["trials"], 60);
  fs::remove_all(dir);
}

TEST(StudyCommand, BadInputIsRefusedWithExitCodeTwo) {
  EXPECT_EQ(study({"simulate", "--study", "nonesuch", "--observer-threshold", "1"}).code, 2);
  EXPECT_EQ(study({"simulate", "--study", "class", "--observer-threshold", "50"}).code, 2);
  EXPECT_EQ(
      study({"simulate", "--study", "class", "--observer-threshold", "1", "--method", "x"}).code,
      2);
  EXPECT_EQ(study({"analyse", "--json"}).code, 2);
  const CliRun missing = study({"analyse", "/nonexistent/a.csv"});
  EXPECT_EQ(missing.code, 2);
  EXPECT_NE(missing.err.find("/nonexistent/a.csv: cannot open the file"), std::string::npos)
      << missing.err;
  EXPECT_EQ(study({"frobnicate"}).code, 2);
}

}  // namespace
}  // namespace oflab
