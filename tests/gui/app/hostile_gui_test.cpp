// The real oflab (the GUI) in a child process on every committed fuzz regression input it
// reads, and on the issue's degenerate planes and cameras: under a 2 GB address-space
// limit each must end within 60 s with exit status 0 or 2 and at most a one-line message,
// never a signal (manual/robustness.md, "Time and memory of a hostile input"). Inputs the
// window accepts are played for a few frames in the view that reads them and captured
// (--screenshot), so the run ends by itself; refused ones end before or right after the
// window is made.
//
// What oflab reads, and so what is fed to it: motion scripts (--script), viewer scripts
// (--scene four-cubes --script), scenes (--scene), sessions (--session) and images (as the
// texture of a session). It reads no OBJ file and has no command line of oflab-cli's
// commands, so the `obj` and `command-line` inputs are oflab-cli's alone
// (cli.hostile_inputs_within_limits).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "../../analysis/child_process.h"
#include "../../analysis/scratch_dir.h"

namespace oflab {
namespace {

namespace fs = std::filesystem;

// A session (the fuzz seed's) whose texture is `image`, written into `dir`.
fs::path session_with_texture(const fs::path& image, const fs::path& dir) {
  nlohmann::json session =
      nlohmann::json::parse(std::ifstream(OFLAB_FUZZ_SEEDS_DIR "/session/session.json"));
  session["texture"] = image.string();
  const fs::path file = dir / ("texture-" + image.filename().string() + ".json");
  std::ofstream(file) << session.dump();
  return file;
}

// The arguments that feed a regression input of fuzz target `target` (the folder under
// fuzz/regressions/) to oflab, before the screenshot options; empty for a target oflab
// does not read.
std::vector<std::string> reading(const std::string& target, const fs::path& input,
                                 const fs::path& dir) {
  const std::string file = input.string();
  if (target == "motion-script") return {"--script", file, "--view", "animation"};
  if (target == "viewer-script") {
    return {"--scene", "four-cubes", "--script", file, "--view", "animation"};
  }
  if (target == "scene") return {"--scene", file, "--view", "animation"};
  if (target == "session") return {"--session", file};
  if (target == "image") return {"--session", session_with_texture(input, dir).string()};
  return {};
}

// Qt warns on stderr when XDG_RUNTIME_DIR is not set (as under ctest and xvfb-run), a line
// that is the environment's, not oflab's: the children get a private runtime directory.
void give_children_a_runtime_dir(const fs::path& dir) {
  const fs::path runtime = dir / "runtime";
  fs::create_directories(runtime);
  fs::permissions(runtime, fs::perms::owner_all, fs::perm_options::replace);
  ::setenv("XDG_RUNTIME_DIR", runtime.c_str(), 1);
}

// oflab with `args`, playing 5 frames and saving a screenshot when the input is accepted.
void expect_gui_ends_cleanly(std::vector<std::string> args, const fs::path& dir,
                             const std::string& what) {
  give_children_a_runtime_dir(dir);
  for (const char* a : {"--screenshot", "", "--force", "--frames", "5", "--size", "640", "480"}) {
    args.emplace_back(a);
  }
  args[args.size() - 7] = (dir / "shot.png").string();  // replaced by each run: --force
  testing::expect_ends_cleanly(OFLAB_GUI_BINARY, args, dir, what);
}

TEST(HostileGuiInputs, EveryRegressionInputOflabReadsEndsWithin60sAnd2GB) {
  const fs::path dir = testing::fresh_test_dir("oflab-hostile-gui");
  int run = 0;
  for (const auto& target : fs::directory_iterator(OFLAB_FUZZ_REGRESSIONS_DIR)) {
    for (const auto& input : fs::directory_iterator(target.path())) {
      const auto args = reading(target.path().filename().string(), input.path(), dir);
      if (args.empty()) continue;
      expect_gui_ends_cleanly(args, dir, input.path().string());
      ++run;
    }
  }
  EXPECT_GE(run, 13);  // 5 motion scripts, 2 viewer scripts, 1 scene, 2 sessions, 3 images
  fs::remove_all(dir);
}

// The single-plane engine in the animation view on a plane closer to the eye than the warp
// can take, a plane of size 1e-300 and focal lengths of 1e6 and 1e-300.
TEST(HostileGuiInputs, DegeneratePlanesAndCamerasEndWithin60sAnd2GB) {
  const fs::path dir = testing::fresh_test_dir("oflab-hostile-gui-planes");
  for (const fs::path& file : testing::write_degenerate_plane_scripts(dir)) {
    expect_gui_ends_cleanly({"--script", file.string(), "--view", "animation"}, dir,
                            file.filename().string());
  }
  fs::remove_all(dir);
}

// oflab asked to play `scene` with viewer script `viewer` and save a screenshot
// (dir/shot.png) of its animation view, under the hostile-input limits (2 GB, 60 s).
testing::ChildResult screenshot_of_scene(const fs::path& scene, const std::string& viewer,
                                         const fs::path& dir) {
  return testing::run_child(
      OFLAB_GUI_BINARY,
      {"--scene", scene.string(), "--script", viewer, "--view", "animation", "--screenshot",
       (dir / "shot.png").string(), "--frames", "2", "--size", "640", "480"},
      dir, 2L << 30, testing::kHostileTimeLimitSeconds);
}

// A scene the CLI refuses is refused by the window with exit status 2 and the CLI's message
// (the issue's 1000 repeated polygons, over the scene engine's memory limit at the walk
// viewer's 1280 x 720): the same reader and the same check, not a screenshot of the default
// scene with exit 0.
TEST(HostileGuiInputs, ASceneTheCliRefusesIsExitTwoWithTheCliMessage) {
  const fs::path dir = testing::fresh_test_dir("oflab-hostile-gui-memory");
  give_children_a_runtime_dir(dir);
  const fs::path scene = testing::write_repeated_polygon_scene(dir);
  const std::string why =
      "the scene's 1000 polygons at 1280 x 720 px may hold 28188 MiB of layers and textures, "
      "more than 768 MiB (the scene engine memory limit)\n";
  const testing::ChildResult gui = screenshot_of_scene(scene, "walk", dir);
  EXPECT_EQ(gui.code, 2) << gui.err;
  EXPECT_FALSE(fs::exists(dir / "shot.png"));
  // The line names the option and the file, then the figure and the limit (issue 39).
  EXPECT_EQ(gui.err, "oflab: --scene: " + scene.string() + ": " + why);
  EXPECT_EQ(std::count(gui.err.begin(), gui.err.end(), '\n'), 1) << gui.err;
  fs::remove_all(dir);
}

// The caps that multiplied (BSP vertices, impostor detail) refuse the same scenes in the
// window as in the CLI: exit 2 and one line naming the limit, within 60 s and 2 GB.
TEST(HostileGuiInputs, ScenesOverTheVertexAndDetailCapsAreExitTwoWithOneLine) {
  const fs::path dir = testing::fresh_test_dir("oflab-hostile-gui-caps");
  give_children_a_runtime_dir(dir);
  const std::pair<fs::path, std::string> cases[] = {
      {testing::write_intersecting_circles_scene(dir), "vertices in all (the limit)"},
      {testing::write_detailed_impostor_scene(dir), "(the scene impostor detail limit)"}};
  for (const auto& [scene, limit] : cases) {
    const testing::ChildResult gui = screenshot_of_scene(scene, "circle", dir);
    EXPECT_EQ(gui.code, 2) << gui.err;
    EXPECT_FALSE(fs::exists(dir / "shot.png"));
    EXPECT_NE(gui.err.find(limit), std::string::npos) << gui.err;
    EXPECT_EQ(std::count(gui.err.begin(), gui.err.end(), '\n'), 1) << gui.err;
  }
  fs::remove_all(dir);
}

// The issue's large scenes (points 1 to 3; oflab reads no OBJ file) in the window, as the
// scene source and as scene shifting's: each ends within 60 s and 2 GB with exit 0 or 2
// and one line, the CLI's limits refusing what would not fit.
TEST(HostileGuiInputs, TheIssuesLargeScenesEndWithin60sAnd2GBInBothSceneSources) {
  const fs::path dir = testing::fresh_test_dir("oflab-hostile-gui-large");
  const fs::path scenes[] = {testing::write_cube_grid_scene(dir),
                             testing::write_random_squares_scene(dir),
                             testing::write_shared_texture_scene(dir)};
  for (const fs::path& scene : scenes) {
    for (const char* source : {"scene", "scene-shifting"}) {
      expect_gui_ends_cleanly({"--scene", scene.string(), "--source", source, "--script", "walk",
                               "--view", "animation"},
                              dir, scene.filename().string() + " as " + source);
    }
  }
  expect_gui_ends_cleanly(
      {"--scene", "train-window", "--source", "scene-shifting", "--script",
       testing::write_large_camera_viewer_script(dir).string(), "--view", "animation"},
      dir, "train-window at 4096 x 4096 px");
  fs::remove_all(dir);
}

// A session (the fuzz seed's, written into `dir` as NAME.json) showing the animation view's
// comparison layout of all four compared policies, with `source` (a session's "source"
// object: kind, name, viewer) and, when `camera` > 0, a plane camera of camera x camera px.
fs::path comparison_session(const std::string& name, const nlohmann::json& source, int camera,
                            const fs::path& dir) {
  nlohmann::json session =
      nlohmann::json::parse(std::ifstream(OFLAB_FUZZ_SEEDS_DIR "/session/session.json"));
  session["texture"] = "";
  session["script"] = "";
  session["frame"] = 0;
  session["view"] = "animation";
  session["animation"]["display"] = "comparison";
  session["animation"]["compared"] = {"affine", "perspective", "talisman", "rerender"};
  session["animation"]["source"] = source;
  if (camera > 0) {
    session["plane"]["camera"] = {{"focal_px", 600.0}, {"width", camera}, {"height", camera}};
  }
  const fs::path file = dir / (name + ".json");
  std::ofstream(file) << session.dump();
  return file;
}

// The issue's comparison layouts that crashed or passed 4 GB, each compared policy holding
// its own engine: ten squares sharing one 4096 x 4096 PNG, the 108 squares the old estimate
// admitted, and a plane seen by an 8192 x 8192 px camera, each with four compared policies.
// Each ends within 60 s and 2 GB with exit 0 or 2 and one line: the scene engine's limit
// refuses the scenes, and the run memory limit the plane's comparison (its panels say why;
// the animation itself plays: 942 816 KiB at the peak; its first frames at 8192 x 8192 px
// took 93 s at a load average of 21 on the 2-core machine, so the test needs the machine
// far less loaded than that to meet the 60 s).
TEST(HostileGuiInputs, ComparisonsOfFourPoliciesEndWithin60sAnd2GB) {
  const fs::path dir = testing::fresh_test_dir("oflab-hostile-gui-comparison");
  const auto scene = [](const fs::path& file) {
    return nlohmann::json{{"kind", "scene"}, {"name", file.string()}, {"viewer", "walk"}};
  };
  const std::pair<fs::path, int> sessions[] = {
      {comparison_session("shared", scene(testing::write_shared_texture_scene(dir)), 0, dir), 2},
      {comparison_session("squares", scene(testing::write_repeated_polygon_scene(dir, 108)), 0,
                          dir),
       2},
      {comparison_session("plane", {{"kind", "plane"}, {"name", ""}, {"viewer", ""}}, 8192, dir),
       0}};
  for (const auto& [session, code] : sessions) {
    give_children_a_runtime_dir(dir);
    const testing::ChildResult r = testing::run_child(
        OFLAB_GUI_BINARY,
        {"--session", session.string(), "--screenshot", (dir / "shot.png").string(), "--force",
         "--frames", "1", "--size", "640", "480"},
        dir, testing::kHostileAddressSpace, testing::kHostileTimeLimitSeconds);
    EXPECT_TRUE(r.exited && !r.timed_out) << session;
    EXPECT_EQ(r.code, code) << session << ": " << r.err;  // read, then refused or played
    EXPECT_LE(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    if (code == 2) {
      EXPECT_NE(r.err.find("(the scene engine memory limit)"), std::string::npos) << r.err;
    }
  }
  fs::remove_all(dir);
}

// The issue's `--frames 1000000` (within the CLI's cap) played for hours in the window: the
// window's own limit refuses it before anything is opened, exit 2 and one line.
TEST(HostileGuiInputs, AMillionWindowFramesAreRefusedWithOneLine) {
  const fs::path dir = testing::fresh_test_dir("oflab-hostile-gui-frames");
  give_children_a_runtime_dir(dir);
  const testing::ChildResult r = testing::run_child(
      OFLAB_GUI_BINARY,
      {"--screenshot", (dir / "shot.png").string(), "--frames", "1000000", "--size", "640", "480"},
      dir, testing::kHostileAddressSpace, testing::kHostileTimeLimitSeconds);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_EQ(r.err, "oflab: --frames: 1e+06 is outside 0..1000 frames\n");
  EXPECT_FALSE(fs::exists(dir / "shot.png"));
  fs::remove_all(dir);
}

// Files that are not regular files (a FIFO, /dev/zero, a link to it, a directory) given as
// each input oflab reads: refused at once with exit 2 and one line, nothing waiting for a
// writer or reading without end.
TEST(HostileGuiInputs, NonRegularFilesAreRefusedAtOnceWithOneLine) {
  const fs::path dir = testing::fresh_test_dir("oflab-hostile-gui-nonregular");
  give_children_a_runtime_dir(dir);
  ASSERT_EQ(::mkfifo((dir / "fifo.json").c_str(), 0600), 0);
  fs::create_symlink("/dev/zero", dir / "zero.json");
  fs::create_directories(dir / "folder.json");
  for (const std::string input : {"/dev/zero", "zero.json", "fifo.json", "folder.json"}) {
    const std::string path = input[0] == '/' ? input : (dir / input).string();
    for (const char* option : {"--session", "--scene", "--script"}) {
      const testing::ChildResult r =
          testing::run_child(OFLAB_GUI_BINARY,
                             {option, path, "--screenshot", (dir / "shot.png").string(), "--frames",
                              "2", "--size", "640", "480"},
                             dir, testing::kHostileAddressSpace, 10.0);
      EXPECT_EQ(r.code, 2) << option << " " << input << ": " << r.err;
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
      EXPECT_FALSE(fs::exists(dir / "shot.png"));
    }
  }
  fs::remove_all(dir);
}

// Lesson names that are paths the file system cannot read (a link to itself, a name of 5000
// characters, a device, a directory) are refused with exit 2 and one line naming the path
// and why, as --lesson and as --check-lesson (issue 39, point 5).
TEST(HostileGuiInputs, LessonPathsThatCannotBeReadAreOneLineNamingThem) {
  const fs::path dir = testing::fresh_test_dir("oflab-hostile-gui-lessons");
  give_children_a_runtime_dir(dir);
  fs::create_symlink(dir / "loop.json", dir / "loop.json");
  const std::pair<std::string, std::string> cases[] = {
      {(dir / "loop.json").string(), "cannot open the file (Too many levels of symbolic links)"},
      {std::string(5000, 'a'), "cannot open the file (File name too long)"},
      {"/dev/zero", "is not a regular file (a FIFO, device or socket)"},
      {dir.string(), "is a directory"}};
  for (const auto& [path, why] : cases) {
    for (const std::string option : {"--lesson", "--check-lesson"}) {
      const testing::ChildResult r =
          testing::run_child(OFLAB_GUI_BINARY, {option, path, "--size", "640", "480"}, dir,
                             testing::kHostileAddressSpace, testing::kHostileTimeLimitSeconds);
      EXPECT_EQ(r.code, 2) << option << " " << path.substr(0, 80) << ": " << r.err;
      EXPECT_EQ(r.err, "oflab: " + option + ": " + path + ": " + why + "\n");
    }
  }
  fs::remove_all(dir);
}

// A session whose texture cannot be read is refused naming the session file, the field and
// the texture's own problem (issue 39, point 12).
TEST(HostileGuiInputs, ASessionsUnreadableTextureNamesTheSession) {
  const fs::path dir = testing::fresh_test_dir("oflab-hostile-gui-session");
  give_children_a_runtime_dir(dir);
  const fs::path session = dir / "s.json";
  std::ofstream(session) << R"({"format": "oflab-session", "version": 2, "texture": "none.png"})";
  const testing::ChildResult r =
      testing::run_child(OFLAB_GUI_BINARY,
                         {"--session", session.string(), "--screenshot",
                          (dir / "shot.png").string(), "--size", "640", "480"},
                         dir, testing::kHostileAddressSpace, testing::kHostileTimeLimitSeconds);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_EQ(r.err.rfind("oflab: --session: " + session.string() + ": texture: none.png: ", 0), 0u)
      << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace oflab
