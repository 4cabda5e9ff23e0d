// oflab's command line: every bad input gives a UsageError naming the option.
#include "app/launch_options.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>

#include "app/view_table.h"

namespace oflab {
namespace {

std::string usage_error(const std::vector<std::string>& args) {
  try {
    parse_launch_options(args);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(LaunchOptions, DefaultsOpenTheWholeWindowAt1280By800) {
  const LaunchOptions o = parse_launch_options({});
  EXPECT_EQ(o.width, 1280);
  EXPECT_EQ(o.height, 800);
  EXPECT_TRUE(o.screenshot.empty());
  EXPECT_EQ(o.benchmark, 0);
}

TEST(LaunchOptions, ScreenshotWithFramesAndView) {
  const LaunchOptions o = parse_launch_options(
      {"--screenshot", "a.png", "--frames", "3", "--view", "basis", "--size", "640", "480"});
  EXPECT_EQ(o.screenshot, "a.png");
  EXPECT_EQ(o.frames, 3);
  EXPECT_EQ(o.view, "basis");
  EXPECT_EQ(o.width, 640);
}

TEST(LaunchOptions, BadValuesNameTheirOption) {
  EXPECT_NE(usage_error({"--view", "nope"}).find("--view"), std::string::npos);
  EXPECT_NE(usage_error({"--lesson", "nope"}).find("--lesson"), std::string::npos);
  EXPECT_NE(usage_error({"--frames", "3"}).find("--frames"), std::string::npos);
  EXPECT_NE(usage_error({"--screenshot", "a.png", "--frames", "-1"}).find("--frames"),
            std::string::npos);
  EXPECT_NE(usage_error({"--screenshot", "a.png", "--frames", "x"}).find("--frames"),
            std::string::npos);
  EXPECT_NE(usage_error({"--benchmark", "0"}).find("--benchmark"), std::string::npos);
  EXPECT_NE(usage_error({"--size", "100", "100"}).find("--size"), std::string::npos);
  EXPECT_NE(usage_error({"--size", "640"}).find("--size"), std::string::npos);
  EXPECT_NE(usage_error({"--flow-draw", "arrows,bogus"}).find("--flow-draw"), std::string::npos);
  EXPECT_NE(usage_error({"--basis", "fourier"}).find("--basis"), std::string::npos);
  EXPECT_NE(usage_error({"--bogus"}).find("--bogus"), std::string::npos);
  EXPECT_NE(usage_error({"stray"}).find("stray"), std::string::npos);
}

TEST(LaunchOptions, AStudyIsReadWithItsFieldsAndBadOnesNameTheirOption) {
  const LaunchOptions o = parse_launch_options({"--study", "class", "--study-seed", "9"});
  ASSERT_TRUE(o.study.study.has_value());
  EXPECT_EQ(o.study.study->name, "class");
  EXPECT_EQ(o.study.method, o.study.study->method);
  EXPECT_EQ(o.study.seed, 9u);
  EXPECT_EQ(o.study.simulate_px, 0.0);
  EXPECT_NE(usage_error({"--study", "nope"}).find("--study: "), std::string::npos);
  EXPECT_NE(usage_error({"--study-seed", "1"}).find("only used with --study"), std::string::npos);
  EXPECT_NE(usage_error({"--study", "class", "--study-method", "guess"}).find("--study-method"),
            std::string::npos);
  EXPECT_NE(usage_error({"--study", "class", "--study-simulate", "0.8"}).find("--study-csv"),
            std::string::npos);
  EXPECT_NE(usage_error({"--study", "class", "--study-simulate", "50", "--study-csv", "x.csv"})
                .find("error range"),
            std::string::npos);
  EXPECT_NE(usage_error({"--study", "class", "--study-observer", "a,b"}).find("--study-observer"),
            std::string::npos);
  EXPECT_NE(usage_error({"--study", "class", "--study-ppi", "5"}).find("--study-ppi"),
            std::string::npos);
}

TEST(LaunchOptions, UnknownScenesAndModesAreRejectedSayingWhatIsKnown) {
  const std::string scene = usage_error({"--scene", "office"});
  EXPECT_EQ(scene.rfind("--scene", 0), 0u) << scene;
  EXPECT_NE(scene.find("four-cubes"), std::string::npos) << scene;
  const std::string mode = usage_error({"--mode", "bogus"});
  EXPECT_EQ(mode.rfind("--mode", 0), 0u) << mode;
  EXPECT_NE(mode.find("perspective"), std::string::npos);
  EXPECT_NE(usage_error({"--scene", "cube", "--script", "nowhere"}).find("--script"),
            std::string::npos);
}

TEST(LaunchOptions, ShippedSceneModeAndViewerScriptAreAccepted) {
  const LaunchOptions o = parse_launch_options(
      {"--scene", "cube", "--script", "rotate", "--mode", "affine", "--view", "animation"});
  EXPECT_TRUE(o.state.source == (SourceChoice{"scene", "cube", "rotate"}));
  EXPECT_TRUE(o.state.script.empty());
  EXPECT_STREQ(o.state.settings.policy->name, "affine");
  EXPECT_EQ(o.state.view, "animation");
  EXPECT_EQ(parse_launch_options({"--scene", "cube"}).state.source.viewer, "circle");
  EXPECT_EQ(parse_launch_options({"--view", "analysis"}).view, "analysis");
}

// --view takes its names from the view table, plus "window"; --help lists them.
TEST(LaunchOptions, ViewNamesComeFromTheViewTable) {
  for (const ViewEntry& entry : view_table()) {
    EXPECT_EQ(parse_launch_options({"--view", entry.name}).view, entry.name);
    EXPECT_NE(launch_usage().find(entry.name + " (" + entry.title + ")"), std::string::npos)
        << entry.name;
  }
  EXPECT_EQ(view_table().size(), 6u);
  EXPECT_EQ(screenshot_view_names().back(), "window");
  EXPECT_EQ(screenshot_view_names().size(), view_table().size() + 1);
  const std::string error = usage_error({"--view", "nowhere"});
  EXPECT_NE(error.find("slices"), std::string::npos) << error;
}

TEST(LaunchOptions, SceneShiftingIsASourceOfTheSceneWithItsOwnViewerScript) {
  const LaunchOptions o =
      parse_launch_options({"--scene", "train-window", "--source", "scene-shifting"});
  EXPECT_EQ(o.state.source.kind, "scene-shifting");
  EXPECT_EQ(o.state.source.viewer, "train-sideways");
  EXPECT_EQ(parse_launch_options({"--scene", "cube"}).state.source.kind, "scene");
  const std::string unknown = usage_error({"--scene", "cube", "--source", "plane"});
  EXPECT_EQ(unknown.rfind("--source", 0), 0u) << unknown;
  EXPECT_NE(unknown.find("scene-shifting"), std::string::npos) << unknown;
  EXPECT_EQ(usage_error({"--source", "scene"}).rfind("--source", 0), 0u);
}

TEST(LaunchOptions, ShippedScriptIsReadAndUnknownOneListsTheShippedNames) {
  const LaunchOptions o = parse_launch_options({"--script", "zoom"});
  EXPECT_EQ(o.state.script, "zoom");
  const std::string error = usage_error({"--script", "no-such-script"});
  EXPECT_NE(error.find("--script"), std::string::npos);
  EXPECT_NE(error.find("zoom"), std::string::npos);
}

TEST(LaunchOptions, BrokenScriptFileIsRejectedNamingTheFile) {
  const std::string path = ::testing::TempDir() + "oflab_broken_script.json";
  std::ofstream(path) << "{\"format\": \"oflab-script\", \"version\": 1, \"plane\": ";
  const std::string error = usage_error({"--script", path});
  std::remove(path.c_str());
  EXPECT_NE(error.find("--script"), std::string::npos);
  EXPECT_NE(error.find("oflab_broken_script"), std::string::npos);
}

TEST(LaunchOptions, ComparedPoliciesAreOneToFourDistinctNamesOfTheRegistry) {
  const LaunchOptions o = parse_launch_options({"--compare", "talisman,perspective"});
  EXPECT_EQ(o.state.compared, (std::vector<std::string>{"talisman", "perspective"}));
  EXPECT_EQ(parse_launch_options({}).state.compared, WindowState().compared);
  for (const char* bad :
       {"", "bogus", "affine,affine", "affine,perspective,talisman,rerender,exact"}) {
    const std::string error = usage_error({"--compare", bad});
    EXPECT_EQ(error.rfind("--compare: ", 0), 0u) << bad << ": " << error;
  }
  EXPECT_NE(usage_error({"--compare", "bogus"}).find("perspective"), std::string::npos);
}

TEST(LaunchOptions, ClaimKindsAreKindsOfTheRegistryAndOnlyWithACheck) {
  const LaunchOptions o =
      parse_launch_options({"--check-lesson", "all", "--claim-kinds", "cut_texts,panel_fill"});
  EXPECT_EQ(o.claim_kinds, (std::vector<std::string>{"cut_texts", "panel_fill"}));
  EXPECT_TRUE(parse_launch_options({"--check-lesson", "all"}).claim_kinds.empty());
  const std::string unknown =
      usage_error({"--check-lesson", "all", "--claim-kinds", "cut_texts,bogus"});
  EXPECT_EQ(unknown.rfind("--claim-kinds: unknown claim kind 'bogus'", 0), 0u) << unknown;
  EXPECT_NE(unknown.find("heat_map_width"), std::string::npos) << unknown;  // the known ones
  EXPECT_EQ(usage_error({"--check-lesson", "all", "--claim-kinds", ""}),
            "--claim-kinds: no kind named");
  EXPECT_EQ(usage_error({"--claim-kinds", "cut_texts"}),
            "--claim-kinds: only used with --check-lesson");
}

TEST(LaunchOptions, SessionFileIsReadAndABrokenOneRejectedNamingTheFileAndField) {
  const std::string path = ::testing::TempDir() + "oflab_session_width.json";
  std::ifstream seed(OFLAB_FUZZ_SEEDS_DIR "/session/session.json");
  std::string text((std::istreambuf_iterator<char>(seed)), std::istreambuf_iterator<char>());
  std::ofstream(path) << text;
  const LaunchOptions o = parse_launch_options({"--session", path});
  EXPECT_EQ(o.state.frame, 7);
  EXPECT_EQ(o.state.script, "zoom");
  // The other options go over the session's state.
  EXPECT_EQ(parse_launch_options({"--session", path, "--view", "basis"}).state.view, "basis");
  EXPECT_EQ(parse_launch_options({"--session", path, "--view", "basis"}).state.frame, 7);
  const std::string width = "\"width\": 800";
  const auto at = text.find(width);
  ASSERT_NE(at, std::string::npos);
  std::ofstream(path) << text.replace(at, width.size(), "\"width\": 1e300");
  const std::string error = usage_error({"--session", path});
  EXPECT_EQ(error.rfind("--session: oflab_session_width.json", 0), 0u) << error;
  EXPECT_NE(error.find("'width'"), std::string::npos) << error;
  std::ofstream(path) << text.replace(text.find("1e300"), 5, "9000");
  const std::string wide = usage_error({"--session", path});
  EXPECT_NE(wide.find("'width': image size 9000 is outside 2..8192 px"), std::string::npos) << wide;
  std::remove(path.c_str());
  EXPECT_EQ(usage_error({"--session", path}).rfind("--session: ", 0), 0u);  // gone
}

// Errors found while applying a session (not while parsing it) name the file and the field,
// and no part twice: an unknown display, a plane seen edge-on.
TEST(LaunchOptions, SessionErrorsFoundWhileApplyingNameTheFileAndTheFieldOnce) {
  const std::string path = ::testing::TempDir() + "oflab_session_apply.json";
  std::ifstream seed(OFLAB_FUZZ_SEEDS_DIR "/session/session.json");
  nlohmann::json session = nlohmann::json::parse(seed);
  session["animation"]["display"] = "/tmp";
  std::ofstream(path) << session.dump();
  const std::string display = usage_error({"--session", path});
  EXPECT_EQ(display.rfind("--session: oflab_session_apply.json: animation: field 'display'", 0), 0u)
      << display;
  session["animation"]["display"] = "difference";
  session["plane"]["pose"]["normal"] = {1.0, 0.0, 0.0};
  std::ofstream(path) << session.dump();
  const std::string edge = usage_error({"--session", path});
  EXPECT_EQ(edge.rfind("--session: oflab_session_apply.json: field 'plane': ", 0), 0u) << edge;
  EXPECT_EQ(edge.find("plane: plane"), std::string::npos) << edge;
  std::remove(path.c_str());
}

// The usage names every view of the view table, the scene-shifting view "slices" too.
TEST(LaunchOptions, UsageListsEveryViewIncludingSlices) {
  const std::string usage = launch_usage();
  for (const std::string name : {"flow", "basis", "animation", "analysis", "slices"}) {
    EXPECT_NE(usage.find(name + " ("), std::string::npos) << name;
  }
  EXPECT_NE(usage.find("slices (Scene shifting)"), std::string::npos);
}

TEST(LaunchOptions, FlowOptionsGoOverTheLessonsStateOnlyWhereGiven) {
  const LaunchOptions o =
      parse_launch_options({"--flow-show", "second-order", "--flow-draw", "wheel,zoom"});
  EXPECT_EQ(o.state.flow.part, FlowPart::kSecondOrder);
  EXPECT_TRUE(o.state.flow.colour_wheel);
  EXPECT_TRUE(o.state.flow.zoom_to_plane);
  EXPECT_FALSE(o.state.flow.arrows);
  EXPECT_FALSE(o.state.flow.streamlines);
  // The lesson draws streamlines; --flow-show alone keeps them.
  const LaunchOptions lesson =
      parse_launch_options({"--lesson", "flow-of-a-plane", "--flow-show", "first-order"});
  EXPECT_TRUE(lesson.state.flow.streamlines);
  EXPECT_EQ(lesson.state.flow.part, FlowPart::kFirstOrder);
  EXPECT_EQ(lesson.state.lesson, "flow-of-a-plane");
}

// Every --flow-draw name is a row of flow_draw_options(), so a new drawing option is named
// on the command line without touching the parser.
TEST(LaunchOptions, FlowDrawNamesComeFromTheOptionTable) {
  for (const FlowDrawOption& option : flow_draw_options()) {
    const FlowDisplay d = parse_launch_options({"--flow-draw", option.cli_name}).state.flow;
    for (const FlowDrawOption& other : flow_draw_options()) {
      EXPECT_EQ(d.*other.member, &other == &option) << option.cli_name << " " << other.key;
    }
    EXPECT_NE(launch_usage().find(option.cli_name), std::string::npos) << option.cli_name;
  }
}

TEST(LaunchOptions, OutOfRangeCountsAndSessionWithLessonAreRefused) {
  // The window's frames are bounded more tightly than the CLI's (limits::kWindowFrames): the
  // issue's --frames 1000000 played for hours.
  const std::string million = usage_error({"--screenshot", "a.png", "--frames", "1000000"});
  EXPECT_EQ(million.rfind("--frames: 1e+06 is outside 0..1000 frames", 0), 0u) << million;
  EXPECT_EQ(parse_launch_options({"--screenshot", "a.png", "--frames", "1000"}).frames, 1000);
  // As in the CLI, a count too large for a whole number is named with its range.
  const std::string huge = usage_error({"--screenshot", "a.png", "--frames", "2147483647"});
  EXPECT_EQ(huge.rfind("--frames: 2.14748e+09 is outside 0..1000 frames", 0), 0u) << huge;
  const std::string bench = usage_error({"--benchmark", "1e9"});
  EXPECT_EQ(bench.rfind("--benchmark: 1e+09 is outside 1..1000 frames", 0), 0u) << bench;
  const std::string none = usage_error({"--benchmark", "0"});
  EXPECT_EQ(none.rfind("--benchmark: 0 is outside 1..1000 frames", 0), 0u) << none;
  const std::string threads = usage_error({"--threads", "0"});
  EXPECT_EQ(threads.rfind("--threads: 0 is outside 1..64 threads", 0), 0u) << threads;
  const std::string both = usage_error({"--session", "s.json", "--lesson", "occlusion"});
  EXPECT_EQ(both.rfind("--lesson: give --session or --lesson", 0), 0u) << both;
}

}  // namespace
}  // namespace oflab
