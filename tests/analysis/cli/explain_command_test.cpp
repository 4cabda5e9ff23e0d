// `oflab-cli explain` and `oflab-cli flow --explain`: the solutions they print map forward,
// through core's planar flow coefficients, to the coefficients given; the degenerate cases
// are named; bad input is refused in one line naming the option; `flow` without --explain
// prints exactly what it printed before.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli/commands.h"
#include "cli_capture.h"
#include "flow/flow_field.h"

namespace oflab {
namespace {

using testing::CliResult;
using testing::exact_text;

CliResult run(const std::vector<std::string>& args) { return testing::run_cli_captured(args); }

Vec3 vec(const nlohmann::json& j) {
  return Vec3(j[0].get<double>(), j[1].get<double>(), j[2].get<double>());
}

// The worked default case of manual/theory.md section 9.
const std::vector<std::string> kDefaultFlow = {"flow",
                                               "--focal",
                                               "600",
                                               "--image",
                                               "800",
                                               "600",
                                               "--plane-point",
                                               "0.15",
                                               "-0.1",
                                               "3",
                                               "--plane-normal",
                                               "0.25",
                                               "-0.15",
                                               "1",
                                               "--velocity",
                                               "0.3",
                                               "-0.2",
                                               "0.5",
                                               "--omega",
                                               "0.4",
                                               "-0.3",
                                               "0.6",
                                               "--plane-up",
                                               "0",
                                               "-1",
                                               "0",
                                               "--plane-size",
                                               "1",
                                               "0.8",
                                               "--dt",
                                               "0.0333333333333"};

std::vector<std::string> with(std::vector<std::string> args, const std::string& extra) {
  args.push_back(extra);
  return args;
}

std::vector<std::string> explain_args(const PlanarFlowCoefficients& c, double f) {
  return {"explain",         "--coefficients",  exact_text(c.tx),  exact_text(c.ty),
          exact_text(c.j11), exact_text(c.j12), exact_text(c.j21), exact_text(c.j22),
          exact_text(c.px),  exact_text(c.py),  "--focal",         exact_text(f),
          "--json"};
}

// The coefficients the printed solution makes, through core's forward formulas.
PlanarFlowCoefficients forward(const nlohmann::json& s, const Camera& camera) {
  PlanePose pose;
  pose.normal = s["normal"].is_null() ? Vec3(0, 0, 1) : vec(s["normal"]);
  pose.point = Vec3(0.0, 0.0, 1.0 / pose.normal.z);  // d = 1 (the tests' planes meet the axis)
  pose.up = std::abs(pose.normal.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
  RigidMotion motion;
  motion.velocity = vec(s["v_over_d"]);
  motion.omega = vec(s["omega"]);
  return planar_flow_coefficients(camera, pose, motion);
}

TEST(ExplainCommand, SolutionsMapForwardToTheGivenCoefficients) {
  const CliResult flow = run(with(kDefaultFlow, "--json"));
  ASSERT_EQ(flow.code, 0) << flow.err;
  const auto k = nlohmann::json::parse(flow.out)["coefficients"];
  PlanarFlowCoefficients c;
  c.tx = k["tx"];
  c.ty = k["ty"];
  c.j11 = k["j11"];
  c.j12 = k["j12"];
  c.j21 = k["j21"];
  c.j22 = k["j22"];
  c.px = k["px"];
  c.py = k["py"];
  const CliResult r = run(explain_args(c, 600.0));
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["degenerate"].is_null());
  ASSERT_EQ(j["solutions"].size(), 2u);
  Camera camera = make_camera(600.0, 800, 600);
  for (const auto& s : j["solutions"]) {
    EXPECT_NEAR(glm::length(vec(s["normal"])), 1.0, 1e-12);
    const PlanarFlowCoefficients back = forward(s, camera);
    for (const auto& [got, want] : {std::pair{back.tx / 600, c.tx / 600},
                                    {back.ty / 600, c.ty / 600},
                                    {back.j11, c.j11},
                                    {back.j12, c.j12},
                                    {back.j21, c.j21},
                                    {back.j22, c.j22},
                                    {back.px * 600, c.px * 600},
                                    {back.py * 600, c.py * 600}}) {
      EXPECT_NEAR(got, want, 1e-12);
    }
  }
  // One of them is the given plane: N along (0.25, -0.15, 1), V/d = V/(N.P), Omega.
  const Vec3 n = glm::normalize(Vec3(0.25, -0.15, 1.0));
  const Vec3 v_over_d = Vec3(0.3, -0.2, 0.5) / glm::dot(n, Vec3(0.15, -0.1, 3.0));
  int matches = 0;
  for (const auto& s : j["solutions"]) {
    matches += glm::length(vec(s["normal"]) - n) < 1e-9 &&
               glm::length(vec(s["v_over_d"]) - v_over_d) < 1e-9 &&
               glm::length(vec(s["omega"]) - Vec3(0.4, -0.3, 0.6)) < 1e-9;
  }
  EXPECT_EQ(matches, 1);
}

TEST(ExplainCommand, NamesTheDegenerateCases) {
  PlanarFlowCoefficients rotation;  // Omega = (0.1, 0.2, 0.3), V = 0, f = 500
  rotation.tx = 500 * 0.2;
  rotation.ty = -500 * 0.1;
  rotation.j12 = -0.3;
  rotation.j21 = 0.3;
  rotation.px = 0.2 / 500;
  rotation.py = -0.1 / 500;
  auto j = nlohmann::json::parse(run(explain_args(rotation, 500.0)).out);
  EXPECT_EQ(j["degenerate"], "pure-rotation");
  ASSERT_EQ(j["solutions"].size(), 1u);
  EXPECT_TRUE(j["solutions"][0]["normal"].is_null());
  EXPECT_LT(glm::length(vec(j["solutions"][0]["omega"]) - Vec3(0.1, 0.2, 0.3)), 1e-15);

  PlanarFlowCoefficients approach;  // a fronto-parallel plane coming nearer: V3/Z0 = -0.2
  approach.j11 = approach.j22 = 0.2;
  j = nlohmann::json::parse(run(explain_args(approach, 500.0)).out);
  EXPECT_EQ(j["degenerate"], "fronto-parallel-along-normal");
  ASSERT_EQ(j["solutions"].size(), 1u);
  EXPECT_EQ(vec(j["solutions"][0]["normal"]), Vec3(0, 0, 1));

  // A tilted plane translating along its normal.
  PlanePose pose;
  pose.point = Vec3(0.1, 0.0, 2.0);
  pose.normal = Vec3(0.3, 0.2, 1.0);
  RigidMotion motion;
  motion.velocity = 0.4 * glm::normalize(pose.normal);
  motion.omega = Vec3(0.05, 0.0, -0.1);
  const PlanarFlowCoefficients along =
      planar_flow_coefficients(make_camera(500.0, 640, 480), pose, motion);
  j = nlohmann::json::parse(run(explain_args(along, 500.0)).out);
  EXPECT_EQ(j["degenerate"], "translation-along-normal");
  EXPECT_EQ(j["solutions"].size(), 1u);

  // The text names the count and the case.
  auto text = explain_args(approach, 500.0);
  text.pop_back();
  const CliResult t = run(text);
  EXPECT_EQ(t.code, 0);
  EXPECT_NE(t.out.find("1 solution (degenerate: fronto-parallel-along-normal"), std::string::npos)
      << t.out;
}

// Issue 39, point 10: at a check pixel where one plane of the general case is seen edge-on,
// the count, the words and the left-out candidates are true. A sideways translation of the
// plane Z = d facing the eye (tx = 16 px/s alone, f = 500 px): the facing plane is the one
// solution seen at the principal point, its mirror Z = -d is the one candidate behind the
// eye, and the other solution, the plane X = d, is parallel to the optical axis there
// (solved by hand: tests/core/flow/inverse_flow_test.cpp). Printed without rounding noise.
TEST(ExplainCommand, AnEdgeOnPlaneAtTheCheckPixelIsCountedAsEdgeOnNotBehindTheEye) {
  const std::vector<std::string> args = {
      "explain", "--coefficients", "16", "0", "0", "0", "0", "0", "0", "0", "--focal", "500"};
  const CliResult t = run(args);
  ASSERT_EQ(t.code, 0) << t.err;
  EXPECT_EQ(t.out.rfind("1 solution seen at centred pixel (0, 0) (general case: two planes with "
                        "two motions make this same instantaneous flow; the other is seen "
                        "edge-on at this pixel)\n",
                        0),
            0u)
      << t.out;
  EXPECT_NE(t.out.find("Left out: 1 mirror candidate(s)"), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("Left out: 1 plane(s) parallel to the line of sight"), std::string::npos)
      << t.out;
  EXPECT_NE(t.out.find("normal N = (0, 0, 1), 0 deg from the optical axis"), std::string::npos)
      << t.out;
  EXPECT_NE(t.out.find("V/d = (0.032, 0, 0)"), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("Omega = (0, 0, 0)"), std::string::npos) << t.out;
  EXPECT_EQ(t.out.find("e-1"), std::string::npos) << "rounding noise: " << t.out;
  const nlohmann::json j = nlohmann::json::parse(run(with(args, "--json")).out);
  EXPECT_TRUE(j["degenerate"].is_null());
  EXPECT_EQ(j["solutions"].size(), 1u);
  EXPECT_EQ(j["mirror_candidates_behind_eye"], 1);
  EXPECT_EQ(j["edge_on_at_front_pixel"], 1);
  // Off the axis both planes are seen: two solutions, two mirrors, none edge-on.
  const nlohmann::json off =
      nlohmann::json::parse(run(with(with(with(with(args, "--at"), "100"), "0"), "--json")).out);
  EXPECT_EQ(off["solutions"].size(), 2u);
  EXPECT_EQ(off["mirror_candidates_behind_eye"], 2);
  EXPECT_EQ(off["edge_on_at_front_pixel"], 0);
  // The general case's usual words where both planes are seen.
  const CliResult both = run(with(with(with(args, "--at"), "100"), "0"));
  EXPECT_EQ(both.out.rfind("2 solutions (general case: two planes with two motions make this "
                           "same instantaneous flow; only the later frames tell them apart)\n",
                           0),
            0u)
      << both.out;
}

// The one solution of translation-along-normal stands for two that differ by up to 6.3e-5
// rad, and the text says so.
TEST(ExplainCommand, TranslationAlongTheNormalSaysHowNarrowItsToleranceIs) {
  PlanePose pose;
  pose.point = Vec3(0.1, 0.0, 2.0);
  pose.normal = Vec3(0.3, 0.2, 1.0);
  RigidMotion motion;
  const Vec3 n = glm::normalize(pose.normal);
  const Vec3 across = glm::normalize(glm::cross(n, Vec3(0.0, 1.0, 0.0)));
  const std::string words = "V is parallel to the normal to within 6.3e-5 rad";
  for (const double phi : {5e-5, 8e-5}) {  // angle between V and N, radians
    motion.velocity = 0.4 * (std::cos(phi) * n + std::sin(phi) * across);
    auto args =
        explain_args(planar_flow_coefficients(make_camera(500.0, 640, 480), pose, motion), 500.0);
    args.pop_back();  // text, not --json
    const CliResult t = run(args);
    ASSERT_EQ(t.code, 0) << t.err;
    if (phi < 6.3e-5) {
      EXPECT_NE(t.out.find("1 solution (degenerate: translation-along-normal: " + words),
                std::string::npos)
          << t.out;
    } else {
      EXPECT_EQ(t.out.rfind("2 solutions (general case", 0), 0u) << t.out;
    }
  }
}

TEST(ExplainCommand, FlowExplainRunsTheRoundTripAndPlaysBothForward) {
  const CliResult r = run(with(with(kDefaultFlow, "--explain"), "--json"));
  ASSERT_EQ(r.code, 0) << r.err;
  const auto e = nlohmann::json::parse(r.out)["explain"];
  ASSERT_EQ(e["solutions"].size(), 2u);
  EXPECT_TRUE(e["given_solution"].is_number_integer());
  EXPECT_LT(e["round_trip_relative_error"].get<double>(), 1e-12);
  const auto& f = e["futures"];
  EXPECT_LT(f["distance_px_at_frame_1"].get<double>(), 0.01);
  EXPECT_GT(f["first_frame_apart"].get<int>(), 1);
  // Text: the solutions, which one is given, and the frame the futures part.
  const CliResult t = run(with(kDefaultFlow, "--explain"));
  ASSERT_EQ(t.code, 0);
  EXPECT_NE(t.out.find("2 solutions (general case"), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("is the given plane and motion"), std::string::npos) << t.out;
  EXPECT_NE(t.out.find("first by more than 1 px at frame "), std::string::npos) << t.out;
}

TEST(ExplainCommand, FlowWithoutExplainIsUnchanged) {
  // The text and JSON of `flow` start exactly as they did; --explain only adds.
  for (const bool json : {false, true}) {
    auto plain = kDefaultFlow;
    if (json) plain.push_back("--json");
    const CliResult before = run(plain);
    const CliResult after = run(with(plain, "--explain"));
    ASSERT_EQ(before.code, 0);
    ASSERT_EQ(after.code, 0);
    EXPECT_EQ(before.out.find("explain"), std::string::npos);
    if (json) {
      auto j = nlohmann::json::parse(after.out);
      j.erase("explain");
      EXPECT_EQ(j.dump(2) + "\n", before.out);
    } else {
      EXPECT_EQ(after.out.substr(0, before.out.size()), before.out);
    }
  }
}

TEST(ExplainCommand, BadInputGivesOneLineNamingTheOption) {
  const std::pair<std::vector<std::string>, std::string> refused[] = {
      {{"explain", "--coefficients", "1", "2", "3", "4", "5", "6", "7", "x", "--focal", "500"},
       "oflab-cli explain: --coefficients: 'x' is not a finite number\n"},
      {{"explain", "--coefficients", "1", "2", "3", "4", "5", "6", "7", "2e6", "--focal", "500"},
       "oflab-cli explain: --coefficients: 2e+06 is outside -1e+06..1e+06\n"},
      {{"explain", "--coefficients", "1", "2", "3", "4", "5", "6", "7", "8", "--focal", "0.5"},
       "oflab-cli explain: --focal: 0.5 is outside 1..100000 px\n"},
      {{"explain", "--coefficients", "1", "2", "3", "--focal", "500"},
       "oflab-cli explain: --coefficients: expects 8 values, got 3\n"},
      {{"explain", "--focal", "500"}, "oflab-cli explain: --coefficients: required\n"},
      {{"explain", "--coefficients", "1", "2", "3", "4", "5", "6", "7", "8"},
       "oflab-cli explain: --focal: required\n"},
      {{"explain", "--coefficients", "1", "2", "3", "4", "5", "6", "7", "8", "--focal", "500",
        "--at", "0", "nan"},
       "oflab-cli explain: --at: 'nan' is not a finite number\n"},
  };
  for (const auto& [args, line] : refused) {
    const CliResult r = run(args);
    EXPECT_EQ(r.code, 2) << line;
    EXPECT_EQ(r.err, line);
    EXPECT_EQ(r.out, "");
  }
}

}  // namespace
}  // namespace oflab
