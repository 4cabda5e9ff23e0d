// `oflab-cli policies`: the JSON shape, the text listing, that both follow the registry, that
// every listed name is accepted by `animate --mode`, and one-line errors.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>

#include "cli/commands.h"
#include "cli_capture.h"
#include "engine/reuse_policy.h"

namespace oflab {
namespace {

using testing::CliResult;

CliResult run(const std::vector<std::string>& args) { return testing::run_cli_captured(args); }

TEST(PoliciesCommand, JsonListsEveryPolicyWithWhatItModelsInRegistryOrder) {
  const CliResult r = run({"policies", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.is_object());
  ASSERT_EQ(j.size(), 2u);
  EXPECT_EQ(j.at("interpolation_latency_frames"), 1);  // frame generation, for comparison
  const auto& list = j.at("policies");
  ASSERT_TRUE(list.is_array());
  ASSERT_EQ(list.size(), reuse_policies().size());
  EXPECT_EQ(list[0]["name"], "perspective");
  EXPECT_EQ(list[1]["name"], "affine");
  EXPECT_EQ(list[2]["name"], "exact");
  EXPECT_EQ(list[3]["name"], "rerender");
  for (size_t i = 0; i < list.size(); ++i) {
    const ReusePolicy& p = reuse_policies()[i];
    ASSERT_EQ(list[i].size(), 8u) << list[i];
    EXPECT_EQ(list[i]["scenes_only"], needs_scene(p)) << p.name;
    EXPECT_EQ(list[i]["name"], p.name);
    EXPECT_EQ(list[i]["summary"], p.summary);
    EXPECT_EQ(list[i]["models"], p.models);
    EXPECT_EQ(list[i]["breaks"], p.breaks);
    EXPECT_NE(list[i]["models"], "");
    EXPECT_NE(list[i]["breaks"], "");
    // At the default cadence 2: view interpolation waits one frame for the next render.
    EXPECT_EQ(list[i]["latency_frames"], p.pixel_motion == PixelMotion::kBetweenRenders ? 1 : 0)
        << p.name;
    EXPECT_EQ(list[i]["schedule"], p.schedule == Schedule::kCadence ? "cadence" : "threshold");
  }
  std::set<std::string> names;
  for (const auto& e : list) names.insert(e["name"].get<std::string>());
  for (const char* name :
       {"timewarp", "stabilized-plane", "depth-reprojection", "cadence", "mv-extrapolation",
        "mv-no-inpaint", "view-interpolation", "depth-mesh"}) {
    EXPECT_EQ(names.count(name), 1u) << name;
  }
}

TEST(PoliciesCommand, CadenceIsAcceptedByTheCadencePoliciesOnly) {
  for (const char* name : {"timewarp", "stabilized-plane", "depth-reprojection", "cadence"}) {
    const CliResult r = run({"animate", "--script", "rotation", "--frames", "7", "--mode", name,
                             "--cadence", "3", "--json", "--repeat-timing", "1", "--no-warm-up"});
    ASSERT_EQ(r.code, 0) << name << ": " << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["cadence"], 3) << name;
    EXPECT_EQ(j["latency_frames"], 0) << name;
    EXPECT_EQ(j["hole_pixels"], 0) << name;  // one plane: nothing to disocclude
    // Frames 0, 3 and 6 rendered, the four others warped.
    EXPECT_EQ(j["levels"]["rerender"], 3) << name;
    EXPECT_EQ(j["levels"]["perspective"], 4) << name;
  }
  for (const char* bad : {"0", "9", "2.5"}) {
    const CliResult r =
        run({"animate", "--script", "rotation", "--mode", "cadence", "--cadence", bad});
    EXPECT_EQ(r.code, 2) << bad;
    EXPECT_NE(r.err.find("--cadence"), std::string::npos) << r.err;
  }
  const CliResult r = run({"animate", "--script", "rotation", "--cadence", "2"});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--cadence: needs a policy on a fixed cadence"), std::string::npos) << r.err;
}

TEST(PoliciesCommand, TextHasOneLinePerPolicyStartingWithItsName) {
  const CliResult r = run({"policies"});
  ASSERT_EQ(r.code, 0) << r.err;
  std::istringstream lines(r.out);
  std::string line;
  size_t i = 0;
  // Per policy: its name and summary, then indented "models:" and "breaks:" lines; then the
  // latency note.
  while (std::getline(lines, line) && i < reuse_policies().size()) {
    const ReusePolicy& p = reuse_policies()[i++];
    EXPECT_EQ(line.rfind(std::string(p.name) + " ", 0), 0u) << line;
    EXPECT_NE(line.find(p.summary), std::string::npos) << line;
    ASSERT_TRUE(std::getline(lines, line));
    EXPECT_NE(line.find(std::string("models: ") + p.models), std::string::npos) << line;
    ASSERT_TRUE(std::getline(lines, line));
    EXPECT_NE(line.find(std::string("breaks: ") + p.breaks), std::string::npos) << line;
  }
  EXPECT_EQ(i, reuse_policies().size());
  EXPECT_EQ(line.rfind("Latency: ", 0), 0u) << line;
}

TEST(PoliciesCommand, EveryListedNameIsAnAnimateMode) {
  const auto j = nlohmann::json::parse(run({"policies", "--json"}).out);
  for (const auto& p : j["policies"]) {
    // The node-image cache and frame generation play scenes only.
    const bool scene_only = p["scenes_only"].get<bool>();
    const CliResult r = scene_only
                            ? run({"animate", "--scene", "two", "--script", "translate", "--frames",
                                   "2", "--mode", p["name"].get<std::string>(), "--json"})
                            : run({"animate", "--script", "stationary", "--frames", "2", "--mode",
                                   p["name"].get<std::string>(), "--json"});
    ASSERT_EQ(r.code, 0) << p["name"] << ": " << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out)["mode"], p["name"]);
  }
}

TEST(PoliciesCommand, TheHierarchicalCacheIsListedAndRefusesASinglePlane) {
  const auto j = nlohmann::json::parse(run({"policies", "--json"}).out);
  bool listed = false;
  for (const auto& p : j["policies"]) listed = listed || p["name"] == "hierarchical-cache";
  EXPECT_TRUE(listed);
  const CliResult r =
      run({"animate", "--script", "stationary", "--frames", "2", "--mode", "hierarchical-cache"});
  const CliResult c = run({"compare", "--script", "zoom", "--policies", "hierarchical-cache"});
  EXPECT_EQ(c.code, 2);
  EXPECT_NE(c.err.find("needs --scene"), std::string::npos) << c.err;
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("needs --scene"), std::string::npos) << r.err;
  // Frame generation reads a rendered scene frame's motion vectors and depth: scenes only too.
  const CliResult mv = run({"animate", "--script", "stationary", "--mode", "mv-extrapolation"});
  EXPECT_EQ(mv.code, 2);
  EXPECT_NE(mv.err.find("--mode mv-extrapolation: needs --scene NAME|FILE (its motion vectors"),
            std::string::npos)
      << mv.err;
  EXPECT_EQ(mv.err.find('\n'), mv.err.size() - 1) << mv.err;
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
