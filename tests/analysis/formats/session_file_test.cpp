// Session files: what is written reads back unchanged, and every malformed session gives a
// SessionError naming the file, the part and the field, never a crash.
#include "formats/session_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <nlohmann/json.hpp>

#include "engine/budget.h"
#include "scratch_dir.h"

namespace oflab {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A session whose every field differs from the defaults.
Session sample_session() {
  Session s;
  s.plane = default_demo_scene();
  s.plane.motion.model = MotionModel::kSpinAboutCentre;
  s.script = "zoom";
  s.texture = "/tmp/texture.png";
  s.source_kind = "scene";
  s.source_name = "two";
  s.viewer_script = "translate";
  s.settings.policy = &reuse_policy("affine");
  s.settings.thresholds = {0.5, 1.5, 2.0, 0.75};
  s.settings.delta = DeltaPolicy::kOne;
  s.settings.sampling = Sampling::kBilinear;
  s.settings.content.kind = ContentKind::kImpostor;
  s.settings.content.quality = 3;
  s.display = "difference";
  s.exact_renderer = "vtk";
  s.frame = 7;
  s.view = "analysis";
  s.flow_part = "second-order";
  s.flow_draw = {false, true, true, false, false, true};
  s.basis = "taylor";
  s.basis_playing = true;
  s.presentation = true;
  s.lesson = "basis-deformations";
  s.play_rate = 15;
  return s;
}

// The sample session's JSON with `edit` applied, parsed as "s.json"; the error's text, or ""
// when it parses.
template <class Edit>
std::string error_after(Edit edit) {
  json j = json::parse(session_to_json(sample_session()));
  edit(j);
  try {
    parse_session(j.dump(), "s.json");
  } catch (const SessionError& e) {
    return e.what();
  }
  return "";
}

TEST(SessionFile, WrittenSessionReadsBackUnchanged) {
  const Session s = sample_session();
  const fs::path file = testing::fresh_test_dir("oflab-session") / "round_trip.json";
  write_session_file(file.string(), s, false);
  const Session back = read_session_file(file.string());
  EXPECT_EQ(back.plane.camera.focal_px, s.plane.camera.focal_px);
  EXPECT_EQ(back.plane.camera.width, s.plane.camera.width);
  EXPECT_EQ(back.plane.camera.height, s.plane.camera.height);
  EXPECT_EQ(back.plane.pose.point, s.plane.pose.point);
  EXPECT_EQ(back.plane.pose.normal, s.plane.pose.normal);
  EXPECT_EQ(back.plane.pose.up, s.plane.pose.up);
  EXPECT_EQ(back.plane.pose.size, s.plane.pose.size);
  EXPECT_EQ(back.plane.motion.velocity, s.plane.motion.velocity);
  EXPECT_EQ(back.plane.motion.omega, s.plane.motion.omega);
  EXPECT_EQ(back.plane.motion.model, MotionModel::kSpinAboutCentre);
  EXPECT_EQ(back.script, s.script);
  EXPECT_EQ(back.texture, s.texture);
  EXPECT_EQ(back.source_kind, s.source_kind);
  EXPECT_EQ(back.source_name, s.source_name);
  EXPECT_EQ(back.viewer_script, s.viewer_script);
  EXPECT_EQ(back.settings.policy, &reuse_policy("affine"));
  EXPECT_EQ(back.settings.thresholds, s.settings.thresholds);
  EXPECT_EQ(back.settings.delta, DeltaPolicy::kOne);
  EXPECT_EQ(back.settings.sampling, Sampling::kBilinear);
  EXPECT_EQ(back.settings.content.kind, ContentKind::kImpostor);
  EXPECT_EQ(back.settings.content.quality, 3);
  EXPECT_EQ(back.display, s.display);
  EXPECT_EQ(back.exact_renderer, "vtk");
  EXPECT_EQ(back.frame, 7);
  EXPECT_EQ(back.view, s.view);
  EXPECT_EQ(back.flow_part, "second-order");
  EXPECT_EQ(back.flow_draw, s.flow_draw);
  EXPECT_EQ(back.basis, "taylor");
  EXPECT_TRUE(back.basis_playing);
  EXPECT_TRUE(back.presentation);
  EXPECT_EQ(back.lesson, "basis-deformations");
  EXPECT_EQ(back.play_rate, 15);
  fs::remove(file);
}

// Sessions saved before the window's state was kept have no "window" object: they read
// with the window's defaults.
TEST(SessionFile, ASessionWithoutWindowStateReadsWithTheDefaults) {
  json j = json::parse(session_to_json(sample_session()));
  j.erase("window");
  const Session back = parse_session(j.dump(), "old.json");
  const Session defaults;
  EXPECT_EQ(back.flow_part, defaults.flow_part);
  EXPECT_EQ(back.flow_draw, defaults.flow_draw);
  EXPECT_EQ(back.basis, defaults.basis);
  EXPECT_FALSE(back.presentation);
  EXPECT_TRUE(back.lesson.empty());
  EXPECT_EQ(back.play_rate, 30);
  EXPECT_EQ(back.view, "analysis");  // the rest is read as before
}

// Sessions saved before the exact panel's renderer was kept read with the default, core's.
TEST(SessionFile, ASessionWithoutAnExactRendererReadsWithCores) {
  json j = json::parse(session_to_json(sample_session()));
  ASSERT_EQ(j["animation"]["exact_renderer"], "vtk");
  j["animation"].erase("exact_renderer");
  EXPECT_EQ(parse_session(j.dump(), "old.json").exact_renderer, "core");
}

// Sessions saved before the layer content was kept play the texture at quality 1.
TEST(SessionFile, ASessionWithoutContentPlaysTheTexture) {
  json j = json::parse(session_to_json(sample_session()));
  j["animation"].erase("content");
  j["animation"].erase("content_quality");
  const Session back = parse_session(j.dump(), "old.json");
  EXPECT_EQ(back.settings.content.kind, ContentKind::kTexture);
  EXPECT_EQ(back.settings.content.quality, 1);
  EXPECT_EQ(back.settings.policy, &reuse_policy("affine"));  // the rest is read as before
}

// The budget policy's frame budget is kept (pixels or milliseconds); a session without one
// has none, and a negative budget or both units are refused naming the field.
TEST(SessionFile, TheFrameBudgetIsKeptAndABadOneRefused) {
  Session s = sample_session();
  s.settings.policy = &reuse_policy("budget");
  s.settings.budget = {FrameBudget::Unit::kPixels, 12000};
  Session back = parse_session(session_to_json(s), "budget.json");
  EXPECT_EQ(back.settings.policy, &reuse_policy("budget"));
  EXPECT_EQ(back.settings.budget.unit, FrameBudget::Unit::kPixels);
  EXPECT_EQ(back.settings.budget.amount, 12000);
  s.settings.budget = {FrameBudget::Unit::kMilliseconds, 2.5};
  back = parse_session(session_to_json(s), "budget.json");
  EXPECT_EQ(back.settings.budget.unit, FrameBudget::Unit::kMilliseconds);
  EXPECT_EQ(back.settings.budget.amount, 2.5);
  json j = json::parse(session_to_json(s));
  j["animation"].erase("budget_ms");
  EXPECT_EQ(parse_session(j.dump(), "old.json").settings.budget.unit, FrameBudget::Unit::kNone);
  j["animation"]["budget_pixels"] = -5;
  try {
    parse_session(j.dump(), "bad.json");
    ADD_FAILURE() << "a negative budget was accepted";
  } catch (const SessionError& e) {
    EXPECT_NE(std::string(e.what()).find("budget_pixels"), std::string::npos) << e.what();
  }
  j["animation"]["budget_pixels"] = 100;
  j["animation"]["budget_ms"] = 2;
  EXPECT_THROW(parse_session(j.dump(), "both.json"), SessionError);
}

TEST(SessionFile, ExistingFileIsOverwrittenOnlyWhenAsked) {
  const fs::path file = testing::fresh_test_dir("oflab-session") / "exists.json";
  std::ofstream(file) << "keep";
  EXPECT_THROW(write_session_file(file.string(), sample_session(), false), SessionError);
  std::ifstream kept(file);
  std::string text;
  kept >> text;
  EXPECT_EQ(text, "keep");
  EXPECT_NO_THROW(write_session_file(file.string(), sample_session(), true));
  EXPECT_EQ(read_session_file(file.string()).frame, 7);
  fs::remove(file);
}

TEST(SessionFile, UnreadableEmptyAndTruncatedFilesAreNamed) {
  const fs::path missing = testing::fresh_test_dir("oflab-session") / "oflab_no_such_session.json";
  try {
    read_session_file(missing.string());
    FAIL() << "a missing file was read";
  } catch (const SessionError& e) {
    EXPECT_NE(std::string(e.what()).find("oflab_no_such_session.json"), std::string::npos);
  }
  const std::string whole = session_to_json(sample_session());
  for (const std::string& text : {std::string(), whole.substr(0, whole.size() / 2),
                                  std::string("[1, 2]"), std::string("\"oflab-session\"")}) {
    try {
      parse_session(text, "s.json");
      FAIL() << "parsed: " << text;
    } catch (const SessionError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("s.json: ", 0), 0u) << e.what();
    }
  }
}

TEST(SessionFile, EveryBadFieldIsNamedWithItsPart) {
  const double huge = 1e300;
  const double inf = std::numeric_limits<double>::infinity();
  const struct {
    std::function<void(json&)> edit;
    std::string expected;
  } cases[] = {
      {[](json& j) { j["format"] = "oflab-scene"; }, "s.json: field 'format'"},
      {[](json& j) { j["version"] = 2; }, "s.json: field 'version'"},
      {[](json& j) { j.erase("plane"); }, "s.json: field 'plane': is missing"},
      {[](json& j) { j["plane"] = 3; }, "s.json: field 'plane': must be an object"},
      {[](json& j) { j["plane"]["camera"]["focal_px"] = "600"; },
       "s.json: plane.camera: field 'focal_px': must be a number"},
      {[&](json& j) { j["plane"]["camera"]["width"] = huge; },
       "s.json: plane.camera: field 'width'"},
      {[](json& j) { j["plane"]["camera"]["focal_px"] = 0; }, "s.json: plane: "},
      {[](json& j) {
         j["plane"]["pose"]["normal"] = json::array({0, 1});
       },
       "s.json: plane.pose: field 'normal': must be a list of 3 numbers"},
      {[](json& j) {
         j["plane"]["pose"]["normal"] = json::array({0, 0, 0});
       },
       "s.json: plane: "},
      {[](json& j) { j["plane"]["pose"].erase("size"); },
       "s.json: plane.pose: field 'size': is missing"},
      {[&](json& j) {
         j["plane"]["motion"]["omega"] = json::array({0, inf, 0});
       },
       "s.json: plane.motion: field 'omega'"},
      {[](json& j) { j["plane"]["motion"]["model"] = "spin"; },
       "s.json: plane.motion: field 'model': unknown motion model"},
      {[](json& j) { j["script"] = 1; }, "s.json: field 'script': must be a string"},
      {[](json& j) { j["window"] = 1; }, "s.json: field 'window': must be an object"},
      {[](json& j) { j["window"]["flow_draw"] = json::array({true}); },
       "s.json: window: field 'flow_draw': must be a list of 6 booleans"},
      {[](json& j) { j["window"]["flow_draw"][2] = 1; },
       "s.json: window: field 'flow_draw': must be a list of booleans"},
      {[](json& j) { j["window"]["presentation"] = "yes"; },
       "s.json: window: field 'presentation': must be true or false"},
      {[](json& j) { j["window"]["play_rate"] = 0; }, "s.json: window: field 'play_rate'"},
      {[](json& j) { j["window"]["play_rate"] = 12.5; }, "s.json: window: field 'play_rate'"},
      {[](json& j) { j["window"].erase("basis"); }, "s.json: window: field 'basis': is missing"},
      {[](json& j) { j["animation"]["source"].erase("viewer"); },
       "s.json: animation.source: field 'viewer': is missing"},
      {[](json& j) { j["animation"]["mode"] = "fast"; }, "s.json: animation: field 'mode'"},
      {[](json& j) {
         j["animation"]["thresholds"] = json::array({1, 2, 3});
       },
       "s.json: animation: field 'thresholds': must be a list of 4 numbers"},
      {[](json& j) { j["animation"]["thresholds"][2] = -1; },
       "s.json: animation: field 'thresholds': must not be negative"},
      {[](json& j) { j["animation"]["delta"] = "two"; }, "s.json: animation: field 'delta'"},
      {[](json& j) { j["animation"]["content"] = "marble"; },
       "s.json: animation: field 'content': one of texture, shaded, impostor"},
      {[](json& j) { j["animation"]["content"] = 2; },
       "s.json: animation: field 'content': must be a string"},
      {[](json& j) { j["animation"]["content_quality"] = 0; },
       "s.json: animation: field 'content_quality'"},
      {[](json& j) { j["animation"]["content_quality"] = 257; },
       "s.json: animation: field 'content_quality'"},
      {[](json& j) { j["animation"]["content_quality"] = 2.5; },
       "s.json: animation: field 'content_quality'"},
      {[](json& j) { j["animation"]["sampling"] = "cubic"; },
       "s.json: animation: field 'sampling'"},
      {[](json& j) { j["frame"] = 2.5; }, "s.json: field 'frame': must be a whole number"},
      {[](json& j) { j["frame"] = -1; }, "s.json: field 'frame': must be a whole number"},
      {[&](json& j) { j["frame"] = huge; }, "s.json: field 'frame'"},
      {[](json& j) { j["view"] = json::array(); }, "s.json: field 'view': must be a string"},
  };
  for (const auto& c : cases) {
    const std::string error = error_after(c.edit);
    EXPECT_EQ(error.rfind(c.expected, 0), 0u)
        << "expected '" << c.expected << "', got '" << error << "'";
  }
}

}  // namespace
}  // namespace oflab
