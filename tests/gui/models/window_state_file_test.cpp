// Session files (format 2, by name) and the window state's rules: random states round-trip
// through a file exactly, format-1 files still read, and an unknown field or a value out of
// its limit is refused naming the file, the field, the value and the allowed range.
#include "state/window_state_file.h"

#include <gtest/gtest.h>

#include <QTemporaryDir>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>

#include "engine/reuse_policy.h"
#include "flow/limits.h"

namespace oflab {
namespace {

using nlohmann::json;

// A state with every field drawn at random within its limits: numbers of full precision
// (no rounding to friendly decimals), names from their tables.
WindowState random_state(std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const auto in = [&](double lo, double hi) { return lo + (hi - lo) * unit(rng); };
  const auto coin = [&] { return unit(rng) < 0.5; };
  const auto pick = [&](int n) { return int(unit(rng) * n) % n; };
  WindowState s;
  const std::vector<std::string> views = {"flow", "basis", "animation", "analysis", "slices"};
  s.view = views[size_t(pick(5))];
  s.flow.part = FlowPart(pick(kFlowPartCount));
  for (const FlowDrawOption& option : flow_draw_options()) s.flow.*option.member = coin();
  s.flow.spacing_px = coin() ? 0.0 : in(4.0, 100.0);
  s.basis = BasisKind(pick(kBasisKindCount));
  s.basis_playing = coin();
  s.basis_explorer = coin();
  for (int k = 0; k < kExplorerTermCount; ++k) {
    const Limit& limit = *explorer_terms()[size_t(k)].limit;
    s.explorer_terms[size_t(k)] = in(limit.minimum, limit.maximum);
  }
  s.plane.camera = make_camera(in(100.0, 3000.0), 2 + pick(2000), 2 + pick(2000));
  s.plane.pose.point = Vec3(in(-1, 1), in(-1, 1), in(1.0, 20.0));
  s.plane.pose.normal = Vec3(in(-0.5, 0.5), in(-0.5, 0.5), in(0.5, 1.0));
  s.plane.pose.up = Vec3(in(-0.1, 0.1), -1.0, in(-0.1, 0.1));
  s.plane.pose.size = Vec2(in(0.1, 2.0), in(0.1, 2.0));
  s.plane.pose.texture_size = {1 + pick(4096), 1 + pick(4096)};
  s.plane.motion.velocity = Vec3(in(-3, 3), in(-3, 3), in(-3, 3));
  s.plane.motion.omega = Vec3(in(-3, 3), in(-3, 3), in(-3, 3));
  s.plane.motion.model = MotionModel(pick(3));
  s.script = coin() ? "" : "zoom";
  s.texture = coin() ? "" : "/tmp/t" + std::to_string(pick(1000)) + ".png";
  s.source = {coin() ? "plane" : "scene", coin() ? "" : "two", coin() ? "" : "translate"};
  const auto& policies = reuse_policies();
  s.settings.policy = &policies[size_t(pick(int(policies.size())))];
  for (double& t : s.settings.thresholds) t = in(0.0, 100.0);
  s.settings.delta = DeltaPolicy(pick(5));
  s.settings.sampling = coin() ? Sampling::kNearest : Sampling::kBilinear;
  s.settings.content.quality = 1 + pick(256);
  s.settings.budget = {FrameBudget::Unit(pick(3)), 0.0};
  if (s.settings.budget.unit != FrameBudget::Unit::kNone) s.settings.budget.amount = in(0, 1e6);
  s.settings.cadence = 1 + pick(8);
  s.settings.stabilization.automatic = coin();
  // A given plane meets the optical axis in front of the eye (window_state_problem): its point
  // is 1 to 100 u along the normal from the eye, plus any offset within the plane.
  s.settings.stabilization.normal = Vec3(in(-1, 1), in(-1, 1), in(0.1, 1));
  const Vec3 axis = glm::normalize(s.settings.stabilization.normal);
  Vec3 side(in(-100, 100), in(-100, 100), in(-100, 100));
  side -= axis * glm::dot(side, axis);
  s.settings.stabilization.point = axis * in(1, 100) + side;
  s.display = PanelDisplay(pick(4));
  s.compared.clear();
  for (const ReusePolicy& p : policies) {
    if (int(s.compared.size()) < kMaxComparedPolicies && coin()) s.compared.push_back(p.name);
  }
  if (s.compared.empty()) s.compared.push_back(policies.front().name);
  s.exact_renderer = coin() ? "core" : "vtk";
  s.zoom = in(0.25, 8.0);
  s.presentation = coin();
  s.cause_and_effect = coin();
  s.play_rate = 1 + pick(240);
  s.playing = coin();
  s.frame = pick(1000000);
  s.lesson = coin() ? "" : "occlusion";
  return s;
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const SessionError& e) {
    return e.what();
  }
  return "";
}

// The default state's session text with `edit` applied, parsed as "s.json": the error.
template <class Edit>
std::string error_after(Edit edit) {
  json j = json::parse(window_state_to_json(WindowState()));
  edit(j);
  return error_of([&] { parse_session(j.dump(), "s.json"); });
}

TEST(WindowStateFile, RandomStatesRoundTripThroughTheTextExactly) {
  std::mt19937 rng(20261125);
  for (int i = 0; i < 500; ++i) {
    const WindowState s = random_state(rng);
    ASSERT_EQ(window_state_problem(s), "") << i;
    const std::string text = window_state_to_json(s);
    const WindowState back = parse_session(text, "s.json");
    ASSERT_TRUE(back == s) << i << "\n" << text;
    ASSERT_EQ(window_state_to_json(back), text);
  }
}

// The property test can fail: a state that differs in any one field is not equal.
TEST(WindowStateFile, StatesDifferingInOneFieldAreNotEqual) {
  std::mt19937 rng(7);
  const WindowState s = random_state(rng);
  WindowState t = s;
  t.settings.thresholds[2] = std::nextafter(t.settings.thresholds[2], 1e9);
  EXPECT_FALSE(t == s);
  t = s;
  t.flow.common_scale = !t.flow.common_scale;
  EXPECT_FALSE(t == s);
  t = s;
  t.compared.push_back(t.compared.front() == "exact" ? "affine" : "exact");
  EXPECT_FALSE(t == s);
  t = s;
  t.cause_and_effect = !t.cause_and_effect;
  EXPECT_FALSE(t == s);
  t = s;
  t.basis_explorer = !t.basis_explorer;
  EXPECT_FALSE(t == s);
  t = s;
  t.explorer_terms[6] = std::nextafter(t.explorer_terms[6], 1.0);
  EXPECT_FALSE(t == s);
  t = s;
  t.settings.cadence = t.settings.cadence % 8 + 1;
  EXPECT_FALSE(t == s);
  t = s;
  t.settings.stabilization.normal.y = std::nextafter(t.settings.stabilization.normal.y, 1e9);
  EXPECT_FALSE(t == s);
}

// The explorer's values are fields of "basis" by their term's key; a file may give some of
// them (the rest keep the base state's), and each is refused beyond its limit, which is
// stated once (core/flow/limits.h) for the file, the sliders' fields and the model.
TEST(WindowStateFile, TheExplorersTermsRoundTripByNameWithinTheirLimits) {
  WindowState s;
  s.basis_explorer = true;
  s.explorer_terms = {1.5, -2.25, 0.125, -0.5, 0.75, -1.0, 0.000125, -0.0625};
  const json j = json::parse(window_state_to_json(s));
  EXPECT_EQ(j["basis"]["terms"]["px"], 0.000125);
  EXPECT_EQ(j["basis"]["explorer"], true);
  const WindowState back = parse_session(window_state_to_json(s), "s.json");
  EXPECT_TRUE(back == s);
  EXPECT_EQ(back.explorer_terms, s.explorer_terms);
  // Only some terms given: the others stay the base state's.
  WindowState base;
  const WindowState some = read_window_state_object(
      json::parse(R"({"basis": {"terms": {"scale": 0.5}}})"), "l.json", "state", base);
  EXPECT_EQ(some.explorer_terms[2], 0.5);
  EXPECT_EQ(some.explorer_terms[0], base.explorer_terms[0]);
  EXPECT_EQ(error_after([](json& j) { j["basis"]["terms"]["tx"] = 20000; }),
            "s.json: basis.terms: field 'tx': translation rate 20000 is outside "
            "-10000..10000 px/s");
  EXPECT_EQ(error_after([](json& j) { j["basis"]["terms"]["rotation"] = -101; }),
            "s.json: basis.terms: field 'rotation': first-order rate -101 is outside "
            "-100..100 1/s");
  EXPECT_NE(
      error_after([](json& j) { j["basis"]["terms"]["py"] = 0.2; }).find("-0.1..0.1 1/(px s)"),
      std::string::npos);
  EXPECT_NE(error_after([](json& j) { j["basis"]["terms"]["np_x"] = 0; }).find("np_x"),
            std::string::npos);
  EXPECT_NE(error_after([](json& j) { j["basis"]["terms"]["scale"] = "big"; }).find("scale"),
            std::string::npos);
  // The limits a file checks are the explorer's table's (one place).
  for (const ExplorerTerm& term : explorer_terms()) {
    ExplorerTerms terms{};
    terms[size_t(find_explorer_term(term.key))] = term.limit->maximum;
    EXPECT_EQ(explorer_terms_problem(terms), "") << term.key;
    terms[size_t(find_explorer_term(term.key))] = std::nextafter(term.limit->maximum, 1e300);
    EXPECT_NE(explorer_terms_problem(terms).find(term.key), std::string::npos) << term.key;
  }
}

// The reprojection settings in a session: the cadence within limits::kCadence, the plane's
// coordinates within limits::kStabilizationPlane, refused naming the field and the range.
TEST(WindowStateFile, CadenceAndStabilizationPlaneAreCheckedByTheirLimits) {
  const std::string cadence = error_after([](json& j) { j["animation"]["cadence"] = 9; });
  EXPECT_NE(cadence.find("s.json"), std::string::npos) << cadence;
  EXPECT_NE(cadence.find("cadence"), std::string::npos) << cadence;
  EXPECT_NE(cadence.find("1..8"), std::string::npos) << cadence;
  const std::string point = error_after([](json& j) {
    j["animation"]["stabilization"] = {{"automatic", false}, {"point", {0, 0, 1e6}}};
  });
  EXPECT_NE(point.find("stabilization"), std::string::npos) << point;
  EXPECT_NE(point.find("1e+06"), std::string::npos) << point;
  const std::string normal = error_after([](json& j) {
    j["animation"]["stabilization"] = {{"automatic", false}, {"normal", {0, 0, 0}}};
  });
  EXPECT_NE(normal.find("normal"), std::string::npos) << normal;
  const std::string unknown = error_after([](json& j) {
    j["animation"]["stabilization"] = {{"height", 2}};
  });
  EXPECT_NE(unknown.find("height"), std::string::npos) << unknown;
  // A plane in the file reads back as given.
  WindowState s;
  s.settings.cadence = 5;
  s.settings.stabilization = {false, Vec3(0.0, 0.0, 1.25), Vec3(0.0, 0.0, 1.0)};
  EXPECT_TRUE(parse_session(window_state_to_json(s), "s.json") == s);
}

TEST(WindowStateFile, TheCauseAndEffectLayoutIsAFlagOfTheFile) {
  WindowState s;
  s.cause_and_effect = true;
  EXPECT_TRUE(parse_session(window_state_to_json(s), "s.json").cause_and_effect);
  const std::string error =
      error_after([](json& j) { j["cause_and_effect"] = "yes"; });  // not a boolean
  EXPECT_NE(error.find("s.json"), std::string::npos) << error;
  EXPECT_NE(error.find("cause_and_effect"), std::string::npos) << error;
}

TEST(WindowStateFile, WrittenFileReadsBackAndIsReplacedOnlyWhenAsked) {
  QTemporaryDir dir;
  const std::string path = dir.filePath("s.json").toStdString();
  std::mt19937 rng(3);
  const WindowState s = random_state(rng);
  write_session_file(path, s, false);
  EXPECT_TRUE(read_session_file(path) == s);
  const std::string refused = error_of([&] { write_session_file(path, WindowState(), false); });
  EXPECT_NE(refused.find("exists"), std::string::npos) << refused;
  EXPECT_TRUE(read_session_file(path) == s);
  write_session_file(path, WindowState(), true);
  EXPECT_TRUE(read_session_file(path) == WindowState());
  // A write that cannot happen leaves no file behind and the old one as it was.
  const std::string missing = dir.filePath("no/such/dir/s.json").toStdString();
  EXPECT_NE(error_of([&] { write_session_file(missing, s, true); }).find("cannot"),
            std::string::npos);
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path().toStdString()),
                          std::filesystem::directory_iterator()),
            1);
}

// Format 1 (flow options as six booleans, no compared policies) still reads.
TEST(WindowStateFile, Version1FilesStillRead) {
  std::ifstream in(OFLAB_FUZZ_SEEDS_DIR "/session/session.json");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const WindowState s = parse_session(text, "session.json");
  EXPECT_EQ(s.frame, 7);
  EXPECT_EQ(s.view, "analysis");
  EXPECT_EQ(s.script, "zoom");
  EXPECT_TRUE(s.source == (SourceChoice{"scene", "two", "translate"}));
  EXPECT_STREQ(s.settings.policy->name, "affine");
  EXPECT_EQ(s.settings.thresholds[1], 1.5);
  EXPECT_EQ(s.display, PanelDisplay::kDifference);
  EXPECT_EQ(s.plane.motion.model, MotionModel::kSpinAboutCentre);
  EXPECT_EQ(s.compared, WindowState().compared);
  json j = json::parse(text);
  j["window"] = {{"flow_part", "second-order"},
                 {"flow_draw", {false, true, true, false, false, true}},
                 {"basis", "taylor"},
                 {"basis_playing", true},
                 {"presentation", true},
                 {"lesson", "occlusion"},
                 {"play_rate", 15}};
  const WindowState w = parse_session(j.dump(), "session.json");
  EXPECT_EQ(w.flow.part, FlowPart::kSecondOrder);
  EXPECT_FALSE(w.flow.arrows);
  EXPECT_TRUE(w.flow.streamlines);
  EXPECT_TRUE(w.flow.colour_wheel);
  EXPECT_FALSE(w.flow.texture);
  EXPECT_FALSE(w.flow.zoom_to_plane);
  EXPECT_TRUE(w.flow.common_scale);
  EXPECT_EQ(w.basis, BasisKind::kTaylor);
  EXPECT_EQ(w.play_rate, 15);
  EXPECT_EQ(w.lesson, "occlusion");
}

TEST(WindowStateFile, UnknownFieldsAreRefusedNamingThemAndTheKnownOnes) {
  const std::string top = error_after([](json& j) { j["colour"] = 1; });
  EXPECT_EQ(top.rfind("s.json: field 'colour': unknown field (known: view,", 0), 0u) << top;
  const std::string flow = error_after([](json& j) { j["flow"]["glyphs"] = true; });
  EXPECT_EQ(flow.rfind("s.json: flow: field 'glyphs': unknown field", 0), 0u) << flow;
  EXPECT_NE(flow.find("common_scale"), std::string::npos) << flow;
  const std::string version = error_after([](json& j) { j["version"] = 3; });
  EXPECT_NE(version.find("must be 1 or 2"), std::string::npos) << version;
}

// One rule per value: the limits of core/flow/limits.h, with the field, value and range.
TEST(WindowStateFile, ValuesOutsideTheirLimitsAreRefusedNamingFieldValueAndRange) {
  const std::string threshold = error_after([](json& j) { j["animation"]["thresholds"][1] = 1e6; });
  EXPECT_EQ(threshold,
            "s.json: animation: field 'thresholds': threshold 1e+06 is outside 0..100 px");
  const std::string focal = error_after([](json& j) { j["plane"]["camera"]["focal_px"] = 0.5; });
  EXPECT_EQ(focal,
            "s.json: plane.camera: field 'focal_px': focal length 0.5 is outside "
            "1..100000 px");
  const std::string distance = error_after([](json& j) { j["plane"]["pose"]["point"][2] = 99999; });
  EXPECT_EQ(distance, "s.json: plane.pose: field 'point': distance 99999 is outside 0.01..10000 u");
  const std::string velocity =
      error_after([](json& j) { j["plane"]["motion"]["velocity"][0] = -5000; });
  EXPECT_NE(velocity.find("velocity -5000 is outside -1000..1000 u/s"), std::string::npos)
      << velocity;
  EXPECT_NE(error_after([](json& j) { j["animation"]["zoom"] = 9; }).find("0.25..8"),
            std::string::npos);
  EXPECT_NE(error_after([](json& j) { j["play_rate"] = 0; }).find("1..240 fps"), std::string::npos);
  EXPECT_NE(error_after([](json& j) {
              j["animation"]["compared"] = json::array();
            }).find("animation: field 'compared'"),
            std::string::npos);
  EXPECT_NE(error_after([](json& j) {
              j["animation"]["compared"] = {"affine", "affine"};
            }).find("named twice"),
            std::string::npos);
}

TEST(WindowStateFile, BadTypesAndNamesAreNamedWithTheirPart) {
  EXPECT_NE(error_after([](json& j) {
              j["flow"]["arrows"] = 1;
            }).find("flow: field 'arrows': must be true or false"),
            std::string::npos);
  EXPECT_NE(
      error_after([](json& j) { j["basis"]["kind"] = "fourier"; }).find("basis: field 'kind'"),
      std::string::npos);
  EXPECT_NE(
      error_after([](json& j) { j["animation"]["mode"] = "bogus"; }).find(reuse_policy_names()),
      std::string::npos);
  EXPECT_NE(error_after([](json& j) { j["animation"]["display"] = "quad"; }).find("side-by-side"),
            std::string::npos);
  EXPECT_NE(error_after([](json& j) {
              j["animation"]["budget"]["unit"] = "joules";
            }).find("animation.budget: field 'unit'"),
            std::string::npos);
  EXPECT_NE(error_of([] {
              parse_session("{\"format\": \"oflab-session\"", "t.json");
            }).find("t.json: not valid JSON"),
            std::string::npos);
}

}  // namespace
}  // namespace oflab
