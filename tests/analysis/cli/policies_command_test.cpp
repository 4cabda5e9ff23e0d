// `oflab-cli policies`: the JSON shape, the text listing, that both follow the registry, that
// every listed name is accepted by `animate --mode`, and one-line errors.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "cli/commands.h"
#include "cli_capture.h"
#include "engine/reuse_policy.h"

namespace oflab {
namespace {

using testing::CliResult;

CliResult run(const std::vector<std::string>& args) { return testing::run_cli_captured(args); }

TEST(PoliciesCommand, JsonListsEveryPolicyWithNameAndSummaryInRegistryOrder) {
  const CliResult r = run({"policies", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.is_object());
  ASSERT_EQ(j.size(), 1u);
  const auto& list = j.at("policies");
  ASSERT_TRUE(list.is_array());
  ASSERT_EQ(list.size(), reuse_policies().size());
  EXPECT_EQ(list[0]["name"], "perspective");
  EXPECT_EQ(list[1]["name"], "affine");
  EXPECT_EQ(list[2]["name"], "exact");
  EXPECT_EQ(list[3]["name"], "rerender");
  for (size_t i = 0; i < list.size(); ++i) {
    ASSERT_EQ(list[i].size(), 2u) << list[i];
    EXPECT_EQ(list[i]["name"], reuse_policies()[i].name);
    EXPECT_EQ(list[i]["summary"], reuse_policies()[i].summary);
  }
}

TEST(PoliciesCommand, TextHasOneLinePerPolicyStartingWithItsName) {
  const CliResult r = run({"policies"});
  ASSERT_EQ(r.code, 0) << r.err;
  std::istringstream lines(r.out);
  std::string line;
  size_t i = 0;
  while (std::getline(lines, line)) {
    ASSERT_LT(i, reuse_policies().size()) << r.out;
    const ReusePolicy& p = reuse_policies()[i++];
    EXPECT_EQ(line.rfind(std::string(p.name) + " ", 0), 0u) << line;
    EXPECT_NE(line.find(p.summary), std::string::npos) << line;
  }
  EXPECT_EQ(i, reuse_policies().size());
}

TEST(PoliciesCommand, EveryListedNameIsAnAnimateMode) {
  const auto j = nlohmann::json::parse(run({"policies", "--json"}).out);
  for (const auto& p : j["policies"]) {
    const CliResult r = run({"animate", "--script", "stationary", "--frames", "2", "--mode",
                             p["name"].get<std::string>(), "--json"});
    ASSERT_EQ(r.code, 0) << p["name"] << ": " << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out)["mode"], p["name"]);
  }
}

TEST(PoliciesCommand, UnknownModeErrorNamesTheOptionAndThePolicies) {
  const CliResult r = run({"animate", "--script", "stationary", "--mode", "bogus"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--mode: 'bogus'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(reuse_policy_names()), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  const CliResult help = run({"animate", "--help"});
  EXPECT_NE(help.out.find("--mode " + reuse_policy_names("|")), std::string::npos) << help.out;
}

TEST(PoliciesCommand, UnknownOptionIsAOneLineError) {
  const CliResult r = run({"policies", "--bogus"});
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err.rfind("oflab-cli policies: ", 0), 0u) << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  EXPECT_TRUE(r.out.empty());
}

}  // namespace
}  // namespace oflab
