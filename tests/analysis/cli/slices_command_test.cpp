// `oflab-cli slices`: JSON shape, the infinite last slice as null, the epsilon condition
// checked from the printed depths, and one-line errors that name the option.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli/commands.h"
#include "cli_capture.h"

namespace oflab {
namespace {

using testing::CliResult;

CliResult run(const std::vector<std::string>& args) { return testing::run_cli_captured(args); }

TEST(SlicesCommand, JsonListsSlicesWithNullFarForTheBackground) {
  const CliResult r = run(
      {"slices", "--speed", "0.1", "--focal", "500", "--epsilon", "1", "--near", "2", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.contains("slices"));
  ASSERT_TRUE(j["slices"].is_array());
  EXPECT_DOUBLE_EQ(j["asymptote"].get<double>(), 50.0);  // k|V|/epsilon
  const auto& slices = j["slices"];
  // Edge speeds 25, 24, ..., 1 px/frame: 24 finite slices and the background.
  ASSERT_EQ(slices.size(), 25u);
  EXPECT_DOUBLE_EQ(slices[0]["near"].get<double>(), 2.0);
  EXPECT_TRUE(slices.back()["far"].is_null());
  EXPECT_NEAR(slices.back()["near"].get<double>(), 50.0, 1e-9);
  // Independent check of the epsilon condition from the printed numbers.
  for (size_t i = 0; i + 1 < slices.size(); ++i) {
    const double near = slices[i]["near"], far = slices[i]["far"];
    EXPECT_DOUBLE_EQ(far, slices[i + 1]["near"].get<double>());
    EXPECT_NEAR(50.0 / near - 50.0 / far, 1.0, 1e-9) << "slice " << i;
  }
}

TEST(SlicesCommand, DefaultNearIsOneAndStillViewerGivesOneSlice) {
  const auto j = nlohmann::json::parse(
      run({"slices", "--speed", "0.1", "--focal", "500", "--epsilon", "1", "--json"}).out);
  EXPECT_DOUBLE_EQ(j["slices"][0]["near"].get<double>(), 1.0);
  EXPECT_EQ(j["slices"].size(), 50u);
  const CliResult still =
      run({"slices", "--speed", "0", "--focal", "500", "--epsilon", "1", "--json"});
  ASSERT_EQ(still.code, 0) << still.err;
  const auto s = nlohmann::json::parse(still.out);
  ASSERT_EQ(s["slices"].size(), 1u);
  EXPECT_TRUE(s["slices"][0]["far"].is_null());
  EXPECT_DOUBLE_EQ(s["asymptote"].get<double>(), 0.0);
}

TEST(SlicesCommand, TextOutputIsATableWithTheAsymptote) {
  const CliResult r = run({"slices", "--speed", "0.1", "--focal", "500", "--epsilon", "5"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("Asymptote k|V|/epsilon = 10"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("(background)"), std::string::npos) << r.out;
  // Header lines plus one row per slice (edge speeds 50, 45, ..., 5: 10 slices).
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 3 + 10) << r.out;
}

TEST(SlicesCommand, BadInputGivesOneLineErrorNamingTheOption) {
  struct Bad {
    std::vector<std::string> args;
    std::string names;
  };
  const std::vector<std::string> ok = {"slices", "--speed",   "0.1", "--focal",
                                       "500",    "--epsilon", "1"};
  auto with = [&](size_t index, const std::string& value) {
    auto a = ok;
    a[index] = value;
    return a;
  };
  const Bad bad[] = {
      {with(2, "fast"), "--speed"},
      {with(2, "-0.1"), "--speed"},
      {with(2, "inf"), "--speed"},
      {with(4, "0"), "--focal"},
      {with(4, "-500"), "--focal"},
      {with(6, "0"), "--epsilon"},
      {with(6, "-1"), "--epsilon"},
      {with(6, "nan"), "--epsilon"},
      {{"slices", "--focal", "500", "--epsilon", "1"}, "--speed"},
      {{"slices", "--speed", "0.1", "--epsilon", "1"}, "--focal"},
      {{"slices", "--speed", "0.1", "--focal", "500"}, "--epsilon"},
      {{"slices", "--speed", "0.1", "--focal", "500", "--epsilon", "1", "--near", "0"}, "--near"},
      {{"slices", "--speed", "0.1", "--focal", "500", "--epsilon", "1", "--near", "-3"}, "--near"},
      {{"slices", "--speed", "0.1", "--focal", "500", "--epsilon", "1", "--near"}, "--near"},
      {{"slices", "--speed", "0.1", "--focal", "500", "--epsilon", "1", "--depth", "2"}, "--depth"},
      // More slices than the cap: the error suggests a larger epsilon.
      {{"slices", "--speed", "10", "--focal", "1000", "--epsilon", "0.001"}, "--epsilon"},
  };
  for (const Bad& b : bad) {
    const CliResult r = run(b.args);
    EXPECT_EQ(r.code, 2) << b.names << ": " << r.err;
    EXPECT_NE(r.err.find(b.names), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
}

TEST(SlicesCommand, HelpShowsTheUsage) {
  const CliResult r = run({"slices", "--help"});
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("--epsilon E"), std::string::npos);
}

}  // namespace
}  // namespace oflab
