// The command line of oflab:
//   oflab [--session FILE | --lesson NAME] [--scene S] [--script T] [--source KIND] [--mode M]
//         [--compare P1,P2,...] [--view NAME] [--animation-show LAYOUT]
//         [--animation-exact RENDERER]
//         [--screenshot FILE --frames N] [--benchmark N] [--size W H]
//         [--flow-show PART] [--flow-draw LIST] [--basis NAME] [--presentation]
//         [--cause-and-effect] [--basis-explorer] [--world-camera orbit|eye]
//         [--check-lesson NAME|FILE|all] [--study NAME|FILE [--study-method M] [--study-seed S]
//          [--study-observer NAME] [--study-ppi P] [--study-simulate PX --study-csv FILE]]
//         [--help]
// The options that say what the window shows are one WindowState (gui/models/
// window_state.h): the session's or the lesson's state (or the default window), with each
// such option set over it; the window applies it whole (WindowModel::apply). The others
// say how oflab runs (a screenshot, a benchmark, the window's size). Plain C++ over
// analysis/cli/cli_args.h, so it is checked before any window opens and bad input never
// needs a display.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cli/cli_args.h"
#include "state/window_state.h"
#include "study/study_file.h"

namespace oflab {

// --study and its options: the threshold study window (gui/views/study_window.h).
struct StudyLaunch {
  std::optional<Study> study;  // --study NAME|FILE, read and checked
  std::string method;          // --study-method (default: the study's)
  std::uint64_t seed = 0;      // --study-seed (default: the study's)
  std::string observer;        // --study-observer ("simulated" in a simulated run, else "")
  double ppi = 96.0;           // --study-ppi: the screen's pixels per inch
  // --study-simulate PX: a simulated observer (threshold PX, the study's assumed slope and
  // lapse, seeded by the seed) answers in the study window to the end, and --study-csv FILE
  // (required with it; replaced only with --force) gets the trials; 0: a person answers.
  double simulate_px = 0.0;
  std::string csv;
  bool force = false;
};

struct LaunchOptions {
  // What the window shows first: --session FILE's state or --lesson NAME's, or the default
  // window, with the other options over it. The files it names are checked when the window
  // applies it.
  WindowState state;
  // Where `state` came from, for the messages of files it names that cannot be used when the
  // window applies it: "--session: PATH", "--lesson: NAME" or "" (the default window);
  // and "--scene: NAME" when --scene chose the animation's source.
  std::string state_origin;
  std::string scene_origin;
  // --view: the view captured by --screenshot and measured by --benchmark; "window" (or
  // empty) for the whole window. A view name also brings that view to the front.
  std::string view;
  std::string screenshot;  // PNG path; when set, play `frames` frames, save, exit
  int frames = 0;          // frames to play before the screenshot (limits::kWindowFrames)
  // --whole-window: the screenshot is of the whole window, with `view` in front.
  bool whole_window = false;
  int benchmark = 0;  // frames to render as fast as possible (> 0; limits::kWindowPlayedFrames)
  // --threads N: the threads of core's pixel loops (core/image/thread_pool.h;
  // limits::kWorkerThreads), the machine's cores without it.
  int threads = 1;
  int width = 1280;  // window size in pixels
  int height = 800;
  bool help = false;  // --help: print the usage and exit 0
  // --check-lesson NAME|FILE|all: check the claims of these lessons (gui/app/lesson_check.h)
  // in the window at the --size, print one line per claim and exit 0 when all hold, else 1.
  std::vector<std::string> check_lessons;
  // --step-shots DIR (with --check-lesson): a picture of the window after each part of each
  // lesson, at step_shot_path(DIR, lesson, part); an existing picture is replaced only with
  // --force.
  std::string step_shots;
  // --time-claims (with --check-lesson): also measure the claims of timed kinds (frame_rate),
  // which other checks leave out.
  bool time_claims = false;
  // --claim-kinds K1,K2,... (with --check-lesson): only the claims of these kinds (names of
  // session/lessons/claim_kinds.h) are measured, every part still played; empty: all kinds.
  std::vector<std::string> claim_kinds;
  // --study ...: open the study window (with --study-simulate: run it and exit).
  StudyLaunch study;
};

// DIR/lesson-NAME.png for the narrative (part 0), DIR/lesson-NAME-step-K.png for step K: the
// names manual/lessons.md shows.
std::string step_shot_path(const std::string& dir, const std::string& lesson, int part);

// The view names a screenshot can capture, in order: the view table's
// (gui/app/view_table.h), then "window".
const std::vector<std::string>& screenshot_view_names();

// Parses the arguments after the program name. Throws UsageError with one line naming
// the option for: unknown options or values, a missing value, --session with --lesson, a
// --lesson or --check-lesson that is neither a shipped lesson nor a lesson file
// (session/lessons/lessons.h; a file's lesson is added for the run),
// --frames without --screenshot, --screenshot with --benchmark, a size outside 320..8192, a
// frame or benchmark count outside limits::kWindowFrames (a benchmark must be positive), a
// script that is neither a file nor a shipped name or that analysis/formats/script_file.h
// rejects (the message names the file and field), a scene or viewer script that is neither
// a file nor a shipped name or that its reader rejects, a session or lesson that
// session/state/window_state_file.h rejects, an unknown --mode or --animation-exact, a
// --compare list that is empty, longer than kMaxComparedPolicies, repeats a policy or names
// an unknown one, and a --source that is not a kind with a viewer script or comes without
// --scene.
LaunchOptions parse_launch_options(const std::vector<std::string>& args);

// Usage text, a few lines.
std::string launch_usage();

}  // namespace oflab
