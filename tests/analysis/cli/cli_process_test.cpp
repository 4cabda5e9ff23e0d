// The real oflab-cli binary in a child process, where a test can see what a user sees: its
// exit status (a signal, an abort), its wall time and its peak memory.
//
// - Long runs (ctest label `soak`): 100 000 frames of the loop script keep the peak
//   resident memory within 10 % of a 1000-frame run, and `--repeat 40` within 10 % of
//   `--repeat 2` (manual/robustness.md, "Long runs").
// - Hostile inputs: every committed fuzz regression input and the issue's hand-made files
//   end, under a 2 GB address-space limit, within 60 s with exit status 0 or 2 and at most a
//   one-line message (manual/robustness.md, "Limits").
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <new>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "child_process.h"
#include "cli/commands.h"
#include "formats/datasets.h"
#include "scratch_dir.h"

namespace oflab {
namespace {

namespace fs = std::filesystem;

// oflab-cli in a child process (child_process.h).
testing::ChildResult run_cli_child(const std::vector<std::string>& args, const fs::path& dir,
                                   long address_space, double limit_s) {
  return testing::run_child(OFLAB_CLI_BINARY, args, dir, address_space, limit_s);
}

// ---- Long runs ----

// The loop script (datasets/scripts/loop.json) at a quarter of its image size and focal
// length, the same motion seen smaller, so 100 000 frames with the re-render baseline and
// PSNR take seconds.
fs::path small_loop(const fs::path& dir) {
  nlohmann::json script = nlohmann::json::parse(std::ifstream(resolve_script_path("loop")));
  script["camera"] = {{"focal_px", 64}, {"image", {160, 120}}};
  const fs::path file = dir / "loop-160x120.json";
  std::ofstream(file) << script.dump();
  return file;
}

// `animate` of `frames` frames of the small loop, streamed: one timed pass, no warm-up,
// the CSV written into dir/NAME as it goes.
testing::ChildResult play_loop(const fs::path& dir, int frames, const std::string& name) {
  const int repeat = frames / 629 + 1;  // loop.json has 629 frames
  return run_cli_child(
      {"animate", "--script", small_loop(dir).string(), "--repeat", std::to_string(repeat),
       "--frames", std::to_string(frames), "--repeat-timing", "1", "--no-warm-up", "--quiet",
       "--json", "--out", (dir / name).string()},
      dir, 0, 600.0);
}

long csv_rows(const fs::path& file) {
  std::ifstream in(file);
  long lines = 0;
  for (std::string line; std::getline(in, line);) ++lines;
  return lines - 1;  // the header
}

TEST(LongRun, HundredThousandFramesPeakWithinTenPercentOfAThousand) {
  const fs::path dir = testing::fresh_test_dir("oflab-long-run");
  const testing::ChildResult short_run = play_loop(dir, 1000, "short");
  ASSERT_EQ(short_run.code, 0) << short_run.err;
  const testing::ChildResult long_run = play_loop(dir, 100000, "long");
  ASSERT_EQ(long_run.code, 0) << long_run.err;
  EXPECT_EQ(nlohmann::json::parse(long_run.out).at("frames"), 100000);
  EXPECT_EQ(csv_rows(dir / "long" / "frames.csv"), 100000);
  EXPECT_EQ(csv_rows(dir / "short" / "frames.csv"), 1000);
  std::cout << "peak resident memory: 1000 frames " << short_run.peak_rss_kb
            << " KB, 100000 frames " << long_run.peak_rss_kb << " KB (" << long_run.seconds
            << " s)\n";
  EXPECT_LE(long_run.peak_rss_kb, short_run.peak_rss_kb * 1.10);
  fs::remove_all(dir);
}

// The issue's shape: `animate --script loop --repeat 40` (25 160 frames, the default timing,
// which is one timed pass with --repeat) peaks within 10 % of `--repeat 2`.
TEST(LongRun, RepeatFortyPeaksWithinTenPercentOfRepeatTwo) {
  const fs::path dir = testing::fresh_test_dir("oflab-long-run");
  std::vector<testing::ChildResult> runs;
  for (const char* repeat : {"2", "40"}) {
    runs.push_back(run_cli_child(
        {"animate", "--script", "loop", "--repeat", repeat, "--quiet", "--json"}, dir, 0, 300.0));
    ASSERT_EQ(runs.back().code, 0) << runs.back().err;
  }
  EXPECT_EQ(nlohmann::json::parse(runs[1].out).at("frames"), 40 * 629);
  std::cout << "peak resident memory: --repeat 2 " << runs[0].peak_rss_kb << " KB, --repeat 40 "
            << runs[1].peak_rss_kb << " KB (" << runs[1].seconds << " s)\n";
  EXPECT_LE(runs[1].peak_rss_kb, runs[0].peak_rss_kb * 1.10);
  fs::remove_all(dir);
}

// ---- Hostile inputs ----

// The command line that feeds a regression input of fuzz target `target` (the folder
// under fuzz/regressions/) to oflab-cli; empty for a target the CLI does not read.
std::vector<std::string> command_for(const std::string& target, const fs::path& input,
                                     const fs::path& dir) {
  const std::string file = input.string();
  if (target == "motion-script") return {"animate", "--script", file, "--frames", "20"};
  if (target == "viewer-script")
    return {"animate", "--scene", "four-cubes", "--script", file, "--frames", "5"};
  if (target == "scene") return {"animate", "--scene", file, "--script", "circle", "--frames", "5"};
  if (target == "image") return {"animate", "--script", "zoom", "--texture", file, "--frames", "5"};
  if (target == "obj")
    return {"make-scene", "--from-obj", file, "--out", (dir / "o.json").string(), "--force"};
  if (target == "command-line") {
    std::vector<std::string> args;
    std::ifstream in(input);
    for (std::string a; std::getline(in, a, '\n');) args.push_back(a);
    return args;
  }
  return {};  // session: the GUI's files
}

void expect_ends_cleanly(const std::vector<std::string>& args, const fs::path& dir,
                         const std::string& what) {
  testing::expect_ends_cleanly(OFLAB_CLI_BINARY, args, dir, what);
}

TEST(HostileInputs, EveryRegressionInputEndsWithin60sAnd2GBWithACleanStatus) {
  const fs::path dir = testing::fresh_test_dir("oflab-hostile-process");
  int run = 0;
  for (const auto& target : fs::directory_iterator(OFLAB_FUZZ_REGRESSIONS_DIR)) {
    for (const auto& input : fs::directory_iterator(target.path())) {
      fs::path file = input.path();
      if (target.path().filename() == "obj") {  // animate --scene knows OBJ by its extension
        expect_ends_cleanly(
            {"animate", "--scene", file.string(), "--script", "circle", "--frames", "5"}, dir,
            file.string() + " as --scene");
      }
      const auto args = command_for(target.path().filename().string(), file, dir);
      if (args.empty()) continue;
      expect_ends_cleanly(args, dir, file.string());
      ++run;
    }
  }
  EXPECT_GE(run, 15);
  fs::remove_all(dir);
}

// The issue's hand-made files that are not fuzz inputs: a plane closer to the eye than the
// warp can take, a plane of size 1e-300, focal lengths of 1e6 and 1e-300.
TEST(HostileInputs, DegeneratePlanesAndCamerasEndWithin60sAnd2GB) {
  const fs::path dir = testing::fresh_test_dir("oflab-hostile-planes");
  for (const fs::path& file : testing::write_degenerate_plane_scripts(dir)) {
    expect_ends_cleanly({"animate", "--script", file.string(), "--frames", "20"}, dir,
                        file.filename().string());
  }
  fs::remove_all(dir);
}

// A JSON data file `name` in `dir`: `head` (an object's text) with an unknown field
// "padding" whose value is `open` + element(0) + ... + element(count - 1) + `close`.
fs::path padded_json(const fs::path& dir, const std::string& name, std::string head,
                     const std::string& open, const std::function<std::string(long)>& element,
                     long count, const std::string& close) {
  head.erase(head.rfind('}'));  // the closing brace
  std::ofstream out(dir / name, std::ios::binary);
  out << head << ", \"padding\": " << open;
  for (long i = 0; i < count; ++i) out << element(i);
  out << close << "}";
  return dir / name;
}

// The issue's point 4: 64 MiB of "{}," in an unknown field took 2.28 GB before the refusal.
// The JSON readers now count values and nesting before they build the document (formats/
// json_fields.h JsonBudget): such a lesson, session or script is refused at once naming the
// limit, before anything is built; so is one nested a million lists deep.
TEST(HostileInputs, JsonFilesAreBoundedWhileParsedWithin60sAnd2GB) {
  const fs::path dir = testing::fresh_test_dir("oflab-hostile-json");
  std::ifstream zoom_in(resolve_script_path("zoom"));
  const std::string zoom((std::istreambuf_iterator<char>(zoom_in)), {});
  const auto lesson = [](const std::string& name) {
    return R"({"format": "oflab-lesson", "version": 1, "name": ")" + name +
           R"(", "order": 99, "title": "T", "narrative": "n", "state": {}})";
  };
  const long objects = ((64L << 20) - 4096) / 3;  // 64 MiB of "{},", under the file limit
  struct Case {
    std::vector<std::string> args;
    std::string says;
  };
  const auto empty_object = [](long) { return std::string("{},"); };
  const auto bracket = [](long) { return std::string("["); };
  const Case cases[] = {
      {{"lesson", "state",
        padded_json(dir, "empty-objects.json", lesson("empty-objects"), "[", empty_object, objects,
                    "{}]")
            .string()},
       "empty-objects.json: more than 4194304 JSON values, the limit for data files"},
      {{"animate", "--script",
        padded_json(dir, "deep.json", zoom, "", bracket, 1000000, "").string(), "--frames", "5"},
       "deep.json: lists and objects nested more than 64 deep, the limit for data files"},
  };
  for (const Case& c : cases) {
    const testing::ChildResult r = run_cli_child(c.args, dir, testing::kHostileAddressSpace,
                                                 testing::kHostileTimeLimitSeconds);
    EXPECT_TRUE(r.exited && !r.timed_out) << c.says << ": signal " << r.signal;
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << "one line: " << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << r.err;
    RecordProperty(c.says.substr(0, c.says.find(':')) + "_peak_rss_kb", r.peak_rss_kb);
  }
  fs::remove_all(dir);
}

// ---- The last resort of main (oflab-cli's and oflab's) ----

// The issue's 93 KB scene of one polygon repeated 1000 times, played with the walk viewer
// (1280 x 720): refused at once by the scene engine's memory limit, naming the figure and
// the limit, instead of ending in bad_alloc at 2.8 GB. The figure: per polygon two layers of
// the frame grown by the guard band (4 x 1280 x 720 x 4 bytes each) and its copy of the
// 128 x 128 tile, and two copies of the tile: (29491200 + 65536) x 1000 + 131072 bytes =
// 28187.6 MiB. Its 9 KB cut of 100 copies (2819 MiB) was estimated at 709 MiB before the
// layers grown into the guard band were counted, admitted, and ended in bad_alloc at 2.8 GB
// by frame 15: now refused too.
TEST(HostileInputs, ARepeatedPolygonSceneIsRefusedByTheMemoryLimitWithin60sAnd2GB) {
  const fs::path dir = testing::fresh_test_dir("oflab-hostile-memory");
  for (const auto& [copies, mib] : {std::pair{1000, 28188}, std::pair{100, 2819}}) {
    const fs::path scene = testing::write_repeated_polygon_scene(dir, copies);
    const std::vector<std::string> args = {
        "animate", "--scene", scene.string(), "--script", "walk", "--frames", "3", "--quiet"};
    expect_ends_cleanly(args, dir, "repeated polygon");
    const testing::ChildResult r = testing::run_child(OFLAB_CLI_BINARY, args, dir, 2L << 30, 60.0);
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.err, "oflab-cli animate: --scene: the scene's " + std::to_string(copies) +
                         " polygons at 1280 x 720 px may hold " + std::to_string(mib) +
                         " MiB of layers and textures, more than 768 MiB (the scene engine "
                         "memory limit)\n");
  }
  fs::remove_all(dir);
}

// The most copies the limit admits (27 at 1280 x 720, 762 MiB), played for 60 frames of the
// walk viewer with its exact baseline (a second engine of the scene): every layer may grow
// into the guard band as the viewer walks up to the squares, and the run stays within the
// 2 GB address space (exit 0; 820 MB resident at its peak). Before the estimate counted the
// guard band, 108 copies were admitted and their layers ran out of memory. The baseline
// re-renders all 27 squares every frame, so the run takes 15 to 95 s on the 2-core machine
// (by its load): it gets 300 s, the promise under test being its memory. One copy more is
// refused (the control).
TEST(HostileInputs, ASceneAdmittedAtTheMemoryLimitPlaysSixtyFramesWithin2GB) {
  const fs::path dir = testing::fresh_test_dir("oflab-hostile-at-limit");
  const fs::path scene = testing::write_repeated_polygon_scene(dir, 27);
  const testing::ChildResult r =
      testing::run_child(OFLAB_CLI_BINARY,
                         {"animate", "--scene", scene.string(), "--script", "walk", "--frames",
                          "60", "--quiet", "--repeat-timing", "1", "--no-warm-up"},
                         dir, testing::kHostileAddressSpace, 300.0);
  EXPECT_TRUE(r.exited && r.code == 0) << r.signal << " " << r.err;
  std::cout << "27 copies, 60 frames of walk: " << r.seconds << " s, peak " << r.peak_rss_kb
            << " KiB\n";
  const testing::ChildResult over = testing::run_child(
      OFLAB_CLI_BINARY,
      {"animate", "--scene", testing::write_repeated_polygon_scene(dir, 28).string(), "--script",
       "walk", "--frames", "3", "--quiet"},
      dir, testing::kHostileAddressSpace, testing::kHostileTimeLimitSeconds);
  EXPECT_EQ(over.code, 2) << over.err;
  EXPECT_NE(over.err.find("the scene's 28 polygons at 1280 x 720 px may hold 790 MiB"),
            std::string::npos)
      << over.err;
  fs::remove_all(dir);
}

// The issue's lessons without bounds: 16 MiB of empty steps (each step held a whole window
// state: 3 GB) and 171 bytes asking for 100000 frames played at each of a few steps (15
// minutes of `--check-lesson`). Both are refused when the file is read, with exit 2 and one
// line naming the file, the step and the limit, within 60 s and 2 GB.
TEST(HostileInputs, LessonsOverTheirBudgetsAreRefusedWhenRead) {
  const fs::path dir = testing::fresh_test_dir("oflab-hostile-lessons");
  const std::string head = R"({"format": "oflab-lesson", "version": 1, "name": "%", "order": 1,
 "title": "T", "narrative": "N", "state": {}, )";
  const auto write = [&](const std::string& name, const std::string& rest) {
    std::string text = head;
    text.replace(text.find('%'), 1, name);
    std::ofstream(dir / (name + ".json")) << text << rest;
    return (dir / (name + ".json")).string();
  };
  std::string steps = R"("steps": [)";
  const std::string step = R"({"say": ""},)";
  long count = 0;
  for (; steps.size() < (16u << 20); ++count) steps += step;
  steps.back() = ']';
  const std::string many = write("many-steps", steps + "}");
  const std::string fixture =
      std::string(OFLAB_SOURCE_DIR) + "/tests/session/fixtures/long-play.json";
  const std::pair<std::string, std::string> cases[] = {
      {many, "oflab-cli lesson: many-steps.json: step 65: the lesson has " + std::to_string(count) +
                 " steps, more than 64 (the lesson steps limit)\n"},
      {fixture,
       "oflab-cli lesson: long-play.json: field 'play': the lesson plays 100000 frames "
       "up to here, more than 1000 (the lesson frames limit)\n"}};
  for (const auto& [file, message] : cases) {
    const std::vector<std::string> args = {"lesson", "check", file};
    const testing::ChildResult r =
        testing::run_child(OFLAB_CLI_BINARY, args, dir, testing::kHostileAddressSpace,
                           testing::kHostileTimeLimitSeconds);
    EXPECT_EQ(r.code, 2);
    EXPECT_EQ(r.err, message);
  }
  fs::remove_all(dir);
}

// The issue's video of an 8192 x 8192 px camera: x264 printed its malloc failure and a
// second line. The frame is refused before the encoder is opened (exit 2, one line naming
// the limit); the control, a 640 x 480 video of the same script, is written (exit 0).
TEST(HostileInputs, AVideoFrameOverTheLimitIsRefusedBeforeTheEncoderOpens) {
  const fs::path dir = testing::fresh_test_dir("oflab-hostile-video");
  nlohmann::json script = nlohmann::json::parse(std::ifstream(resolve_script_path("zoom")));
  script["camera"] = {{"focal_px", 3277}, {"image", {8192, 8192}}};
  const fs::path large = dir / "zoom-8192.json";
  std::ofstream(large) << script.dump();
  const std::vector<std::string> args = {
      "animate", "--script", large.string(),           "--frames",
      "2",       "--video",  (dir / "x.mp4").string(), "--quiet"};
  const testing::ChildResult r =
      testing::run_child(OFLAB_CLI_BINARY, args, dir, testing::kHostileAddressSpace,
                         testing::kHostileTimeLimitSeconds);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err, "oflab-cli animate: --video: '" + (dir / "x.mp4").string() +
                       "': a frame of 8192 x 8192 pixels is larger than 3686400 pixels (the "
                       "video frame limit)\n");
  EXPECT_FALSE(fs::exists(dir / "x.mp4"));
  const testing::ChildResult small =
      testing::run_child(OFLAB_CLI_BINARY,
                         {"animate", "--script", "zoom", "--frames", "2", "--video",
                          (dir / "y.mp4").string(), "--quiet"},
                         dir, testing::kHostileAddressSpace, testing::kHostileTimeLimitSeconds);
  EXPECT_EQ(small.code, 0) << small.err;
  EXPECT_TRUE(fs::exists(dir / "y.mp4"));
  fs::remove_all(dir);
}

// The issue's inputs whose caps multiplied into minutes a frame: circles of 2000
// vertices cutting each other (past the BSP vertex cap) and 20 impostor facades at quality
// 256 (past the impostor detail limit). Each is refused at once with exit 2 and one line
// naming its limit, within 60 s and 2 GB.
TEST(HostileInputs, CapsThatMultiplyAreRefusedUpFrontWithin60sAnd2GB) {
  const fs::path dir = testing::fresh_test_dir("oflab-hostile-caps");
  const std::pair<fs::path, std::string> cases[] = {
      {testing::write_intersecting_circles_scene(dir), "vertices in all (the limit)"},
      {testing::write_detailed_impostor_scene(dir), "(the scene impostor detail limit)"}};
  for (const auto& [scene, limit] : cases) {
    const std::vector<std::string> args = {
        "animate", "--scene", scene.string(), "--script", "circle", "--frames", "3", "--quiet"};
    expect_ends_cleanly(args, dir, scene.filename().string());
    const testing::ChildResult r = testing::run_child(OFLAB_CLI_BINARY, args, dir, 2L << 30, 60.0);
    EXPECT_EQ(r.code, 2) << scene;
    EXPECT_NE(r.err.find(limit), std::string::npos) << r.err;
  }
  fs::remove_all(dir);
}

// The issue's large inputs (points 1 to 3): an OBJ file of 60 552 faces, make-scene's
// largest output (`--cubes 20000`, written here by oflab-cli itself), 3000 random squares
// cutting each other, and ten texture entries naming one 4096 x 4096 PNG (and scene
// shifting at a camera of 4096 x 4096 px). Each is played
// with the walk viewer by the scene engine (a reuse policy) and by scene shifting: each run
// ends within 60 s and 2 GB with exit 0 or 2 and one line, refused up front by a limit
// (the memory of the scene engine or of scene shifting, the BSP caps) or played.
TEST(HostileInputs, TheIssuesLargeScenesEndWithin60sAnd2GBInBothSceneModes) {
  const fs::path dir = testing::fresh_test_dir("oflab-hostile-large");
  const fs::path cubes = dir / "cubes.json";
  const testing::ChildResult made = testing::run_child(
      OFLAB_CLI_BINARY, {"make-scene", "--cubes", "20000", "--out", cubes.string()}, dir,
      testing::kHostileAddressSpace, testing::kHostileTimeLimitSeconds);
  ASSERT_EQ(made.code, 0) << made.err;
  const fs::path scenes[] = {testing::write_large_obj(dir), cubes,
                             testing::write_random_squares_scene(dir),
                             testing::write_shared_texture_scene(dir)};
  for (const fs::path& scene : scenes) {
    for (const char* mode : {"perspective", "scene-shifting"}) {
      expect_ends_cleanly({"animate", "--scene", scene.string(), "--mode", mode, "--script", "walk",
                           "--frames", "3", "--quiet"},
                          dir, scene.filename().string() + " in " + mode);
    }
  }
  // Scene shifting's slice layers at a camera of 4096 x 4096 px: refused after the cut.
  const std::vector<std::string> large_camera = {
      "animate",
      "--scene",
      "train-window",
      "--mode",
      "scene-shifting",
      "--script",
      testing::write_large_camera_viewer_script(dir).string(),
      "--frames",
      "3",
      "--quiet"};
  expect_ends_cleanly(large_camera, dir, "train-window at 4096 x 4096 px");
  const testing::ChildResult layers =
      testing::run_child(OFLAB_CLI_BINARY, large_camera, dir, testing::kHostileAddressSpace,
                         testing::kHostileTimeLimitSeconds);
  EXPECT_EQ(layers.code, 2) << layers.err;
  EXPECT_NE(layers.err.find("in 5 slices at 4096 x 4096 px may hold"), std::string::npos)
      << layers.err;
  // The ten entries share one decoded image: ten copies would be 640 MB before the scene
  // engine's memory limit refuses the scene.
  const testing::ChildResult shared = testing::run_child(
      OFLAB_CLI_BINARY,
      {"animate", "--scene", scenes[3].string(), "--script", "walk", "--frames", "3", "--quiet"},
      dir, testing::kHostileAddressSpace, testing::kHostileTimeLimitSeconds);
  EXPECT_EQ(shared.code, 2) << shared.err;
  EXPECT_LT(shared.peak_rss_kb, 400L * 1024) << "the texture decoded more than once?";
  fs::remove_all(dir);
}

// Shaded content at quality 256: on a single plane seen by a camera of 8192 x 8192 px (17
// billion samples a frame, hours) and on the street's 13 shaded facades at 1280 x 720 (3
// billion). Both refused before anything is drawn, exit 2 and one line naming the limit.
TEST(HostileInputs, ShadedContentOverTheSamplesLimitIsRefusedUpFront) {
  const fs::path dir = testing::fresh_test_dir("oflab-hostile-shaded");
  nlohmann::json zoom = nlohmann::json::parse(std::ifstream(datasets_dir() + "/scripts/zoom.json"));
  zoom["camera"] = {{"focal_px", 8000}, {"image", {8192, 8192}}};
  const fs::path script = dir / "zoom-8192.json";
  std::ofstream(script) << zoom.dump();
  const std::vector<std::string> cases[] = {
      {"animate", "--script", script.string(), "--content", "shaded", "--quality", "256",
       "--frames", "3", "--quiet"},
      {"animate", "--scene", "street", "--script", "walk", "--content", "shaded", "--quality",
       "256", "--frames", "3", "--quiet"}};
  for (const auto& args : cases) {
    expect_ends_cleanly(args, dir, args[2]);
    const testing::ChildResult r =
        testing::run_child(OFLAB_CLI_BINARY, args, dir, testing::kHostileAddressSpace,
                           testing::kHostileTimeLimitSeconds);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("shaded samples a frame, more than 134217728 (the shaded samples limit)"),
              std::string::npos)
        << r.err;
  }
  fs::remove_all(dir);
}

TEST(LastResort, AnEscapedExceptionIsOneLineAndTheInternalErrorCode) {
  std::ostringstream err;
  EXPECT_EQ(run_guarded(
                "oflab-cli", [] { return 0; }, err),
            0);
  EXPECT_EQ(run_guarded(
                "oflab-cli", [] { return 2; }, err),
            2);
  EXPECT_EQ(err.str(), "");
  EXPECT_EQ(run_guarded(
                "oflab-cli", []() -> int { throw std::runtime_error("two\nlines"); }, err),
            kInternalErrorExitCode);
  EXPECT_EQ(err.str(), "oflab-cli: internal error: two lines\n");
  err.str("");
  EXPECT_EQ(run_guarded(
                "oflab", []() -> int { throw std::bad_alloc(); }, err),
            kInternalErrorExitCode);
  EXPECT_EQ(err.str(), "oflab: internal error: std::bad_alloc\n");
  err.str("");
  EXPECT_EQ(run_guarded(
                "oflab", []() -> int { throw 42; }, err),
            kInternalErrorExitCode);
  EXPECT_EQ(err.str(), "oflab: internal error: an unknown exception\n");
  EXPECT_NE(kInternalErrorExitCode, 2);  // not the bad-input code
}

}  // namespace
}  // namespace oflab
