// `oflab-cli flow` against an independent computation: finite differences of the exact
// projection of moving plane points, and exact projections of the moved corners.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>

#include "cli/commands.h"
#include "cli_capture.h"
#include "flow/homography.h"

namespace oflab {
namespace {

using testing::CliResult;
using testing::exact_text;

CliResult run(const std::vector<std::string>& args) { return testing::run_cli_captured(args); }

struct Case {
  double f;
  Vec3 point, normal, up, velocity, omega;
  Vec2 size;
};

std::vector<std::string> flow_args(const Case& c, double dt) {
  return {"flow",
          "--focal",
          exact_text(c.f),
          "--image",
          "800",
          "600",
          "--plane-point",
          exact_text(c.point.x),
          exact_text(c.point.y),
          exact_text(c.point.z),
          "--plane-normal",
          exact_text(c.normal.x),
          exact_text(c.normal.y),
          exact_text(c.normal.z),
          "--velocity",
          exact_text(c.velocity.x),
          exact_text(c.velocity.y),
          exact_text(c.velocity.z),
          "--omega",
          exact_text(c.omega.x),
          exact_text(c.omega.y),
          exact_text(c.omega.z),
          "--plane-up",
          exact_text(c.up.x),
          exact_text(c.up.y),
          exact_text(c.up.z),
          "--plane-size",
          exact_text(c.size.x),
          exact_text(c.size.y),
          "--dt",
          exact_text(dt),
          "--json"};
}

// Independent: position of the plane point seen at centred pixel p, moved rigidly by
// the screw motion for time t, integrated numerically with small Runge-Kutta steps.
Vec3 integrate(const Case& c, Vec3 r, double t) {
  const int steps = 200;
  const double h = t / steps;
  auto vel = [&](const Vec3& x) { return c.velocity + glm::cross(c.omega, x); };
  for (int i = 0; i < steps; ++i) {
    const Vec3 k1 = vel(r), k2 = vel(r + 0.5 * h * k1), k3 = vel(r + 0.5 * h * k2),
               k4 = vel(r + h * k3);
    r += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
  return r;
}

Vec2 project(const Case& c, const Vec3& r) { return c.f * Vec2(r.x / r.z, r.y / r.z); }

TEST(FlowCommand, JsonMatchesIndependentComputationOnRandomCases) {
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 40; ++i) {
    Case c{400.0 + 200.0 * u(rng),
           Vec3(0.3 * u(rng), 0.3 * u(rng), 3.0 + u(rng)),
           Vec3(0.4 * u(rng), 0.4 * u(rng), 1.0),
           Vec3(0.0, -1.0, 0.0),
           Vec3(0.4 * u(rng), 0.4 * u(rng), 0.4 * u(rng)),
           Vec3(0.4 * u(rng), 0.4 * u(rng), 0.4 * u(rng)),
           Vec2(0.8, 0.6)};
    const double dt = 0.04;
    const CliResult r = run(flow_args(c, dt));
    ASSERT_EQ(r.code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    const auto& k = j["coefficients"];
    // Flow at a few pixels from finite differences of integrated trajectories.
    for (const Vec2 p : {Vec2(0, 0), Vec2(60, -40), Vec2(-50, 30)}) {
      const Vec3 ray(p.x / c.f, p.y / c.f, 1.0);
      const Vec3 r0 = ray * (glm::dot(c.normal, c.point) / glm::dot(c.normal, ray));
      const double h = 1e-3;
      const Vec2 v = (project(c, integrate(c, r0, h)) - project(c, integrate(c, r0, -h))) / (2 * h);
      const double q = k["px"].get<double>() * p.x + k["py"].get<double>() * p.y;
      const Vec2 cli(k["tx"].get<double>() + k["j11"].get<double>() * p.x +
                         k["j12"].get<double>() * p.y + q * p.x,
                     k["ty"].get<double>() + k["j21"].get<double>() * p.x +
                         k["j22"].get<double>() * p.y + q * p.y);
      EXPECT_LT(glm::length(cli - v), 1e-5 * std::max(1.0, glm::length(v))) << "case " << i;
    }
    // The exact homography maps the current corner images to the integrated ones.
    Mat3 h_exact(1.0);
    for (int row = 0; row < 3; ++row)
      for (int col = 0; col < 3; ++col) entry(h_exact, row, col) = j["homography_exact"][row][col];
    EXPECT_DOUBLE_EQ(entry(h_exact, 2, 2), 1.0);
    const Vec3 n = glm::normalize(c.normal);
    const Vec3 up = glm::normalize(c.up - glm::dot(c.up, n) * n);
    const Vec3 right = glm::cross(n, up);
    double taylor_worst = 0.0;
    for (const Vec2 s : {Vec2(-0.4, 0.3), Vec2(0.4, 0.3), Vec2(0.4, -0.3), Vec2(-0.4, -0.3)}) {
      const Vec3 corner = c.point + s.x * right + s.y * up;
      const Vec2 later = project(c, integrate(c, corner, dt));
      EXPECT_LT(glm::length(apply_homography(h_exact, project(c, corner)) - later), 1e-6);
      Mat3 h_taylor(1.0);
      for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col)
          entry(h_taylor, row, col) = j["homography_taylor"][row][col];
      taylor_worst = std::max(taylor_worst,
                              glm::length(apply_homography(h_taylor, project(c, corner)) - later));
    }
    EXPECT_NEAR(j["corner_error_px"]["taylor"].get<double>(), taylor_worst, 1e-6);
  }
}

// A plane translating sideways has px = py = 0 computed as -0: the text says "0".
TEST(FlowCommand, TextNeverPrintsANegativeZero) {
  const CliResult r = run({"flow",
                           "--focal",
                           "600",
                           "--image",
                           "800",
                           "600",
                           "--plane-point",
                           "0",
                           "0",
                           "3",
                           "--plane-normal",
                           "0",
                           "0",
                           "1",
                           "--velocity",
                           "0.3",
                           "0",
                           "0",
                           "--omega",
                           "0",
                           "0",
                           "0"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("  px = 0\n"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("-0\n"), std::string::npos) << r.out;
}

TEST(FlowCommand, BadInputGivesOneLineErrorNamingTheArgument) {
  const Case ok{500.0,           Vec3(0, 0, 2),   Vec3(0, 0, 1), Vec3(0, -1, 0),
                Vec3(0.1, 0, 0), Vec3(0, 0, 0.1), Vec2(1, 1)};
  struct Bad {
    int index;          // which argument to replace
    std::string value;  // its new value
    std::string names;  // the option the error must name
  };
  const auto base = flow_args(ok, 0.1);
  const Bad bad[] = {
      {11, "0", "--plane-normal"},  // with the following two zeroed below
      {9, "-2", "--plane-point"},   // plane behind the camera
      {2, "abc", "--focal"},       {2, "-5", "--focal"},
      {4, "nan", "--image"},       {15, "inf", "--velocity"},
  };
  for (const Bad& b : bad) {
    auto args = base;
    args[b.index] = b.value;
    if (b.names == "--plane-normal") args[12] = args[13] = "0";
    const CliResult r = run(args);
    EXPECT_EQ(r.code, 2) << b.names;
    EXPECT_NE(r.err.find(b.names), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  // The plane through the eye.
  auto through_eye = base;
  through_eye[11] = "1";
  through_eye[12] = "0";
  through_eye[13] = "0";
  through_eye[7] = "0";  // plane point x: the plane X = 0 contains the eye
  EXPECT_EQ(run(through_eye).code, 2);
  // A missing value.
  auto missing = base;
  missing.resize(4);
  const CliResult m = run(missing);
  EXPECT_EQ(m.code, 2);
  EXPECT_NE(m.err.find("--image"), std::string::npos);
  // Values outside their limits (core/flow/limits.h): the option, the value, the range.
  const std::pair<std::pair<int, std::string>, std::string> refused[] = {
      {{2, "0.5"}, "--focal: 0.5 is outside 1..100000 px"},
      {{2, "1e6"}, "--focal: 1e+06 is outside 1..100000 px"},
      {{15, "2000"}, "--velocity: 2000 is outside -1000..1000 u/s"},
      {{19, "-101"}, "--omega: -101 is outside -100..100 rad/s"},
      {{4, "1"}, "--image: 1 is outside 2..8192 px"},
  };
  for (const auto& [change, line] : refused) {
    auto args = base;
    args[change.first] = change.second;
    const CliResult r = run(args);
    EXPECT_EQ(r.code, 2) << line;
    EXPECT_EQ(r.err, "oflab-cli flow: " + line + "\n");
  }
  // A missing required option.
  EXPECT_NE(run({"flow", "--focal", "500"}).err.find("required"), std::string::npos);
}

}  // namespace
}  // namespace oflab
