#include "app/launch_options.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <sstream>

#include "adapters/exact_frames.h"
#include "app/view_table.h"
#include "cli/cli_args.h"
#include "engine/engine.h"
#include "engine/reuse_policy.h"
#include "flow/limits.h"
#include "formats/datasets.h"
#include "formats/scene_file.h"
#include "formats/script_file.h"
#include "formats/viewer_script_file.h"
#include "image/thread_pool.h"
#include "lessons/claim_kinds.h"
#include "lessons/lessons.h"
#include "player/animation_sources.h"
#include "runs/policy_runs.h"
#include "state/window_state_file.h"
#include "study/adaptive_methods.h"

namespace oflab {
namespace {

void read_script(const CliArgs& cli, LaunchOptions* options) {
  if (!cli.has("--script")) return;
  const std::string name = cli.values("--script").at(0);
  try {
    if (cli.has("--scene")) {  // a viewer script walks through the scene
      read_viewer_script_file(resolve_viewer_script_path(name));
      options->state.source.viewer = name;
      return;
    }
    read_script_file(resolve_script_path(name));
    options->state.script = name;
  } catch (const std::runtime_error& e) {  // reader errors and lookup failures
    throw UsageError("--script: " + std::string(e.what()));
  }
}

// --scene NAME [--source KIND] [--script VIEWER]: the scene plays, by default as "scene" with
// the kind's default viewer script. Call after read_script.
void read_scene(const CliArgs& cli, LaunchOptions* options) {
  if (!cli.has("--scene")) return;
  const std::string name = cli.values("--scene").at(0);
  try {
    read_scene_file(resolve_scene_path(name));
  } catch (const std::runtime_error& e) {  // SceneError and lookup failures
    throw UsageError("--scene: " + std::string(e.what()));
  }
  options->scene_origin = "--scene: " + name;
  SourceChoice& source = options->state.source;
  const std::string viewer = cli.has("--script") ? source.viewer : std::string();
  source.kind = cli.has("--source") ? cli.values("--source").at(0) : "scene";
  source.name = name;
  source.viewer = viewer.empty() ? find_animation_source_kind(source.kind)->default_viewer : viewer;
}

// The kinds --source accepts: those a viewer script walks through (what --scene plays).
std::vector<std::string> scene_source_kinds() {
  std::vector<std::string> names;
  for (const AnimationSourceKind& kind : animation_source_kinds()) {
    if (kind.uses_viewer) names.push_back(kind.name);
  }
  return names;
}

void check_source(const CliArgs& cli) {
  if (!cli.has("--source")) return;
  const std::string text = cli.values("--source").at(0);
  const std::vector<std::string> kinds = scene_source_kinds();
  if (std::find(kinds.begin(), kinds.end(), text) == kinds.end()) {
    throw UsageError("--source: unknown source '" + text + "' (known: " + joined_names(kinds) +
                     ")");
  }
  if (!cli.has("--scene")) throw UsageError("--source: only used with --scene");
}

void read_mode(const CliArgs& cli, LaunchOptions* options) {
  if (!cli.has("--mode")) return;
  const std::string text = cli.values("--mode").at(0);
  const ReusePolicy* policy = find_reuse_policy(text);
  if (!policy) {
    throw UsageError("--mode: unknown mode '" + text + "' (known: " + reuse_policy_names() + ")");
  }
  options->state.settings.policy = policy;
}

void read_compared(const CliArgs& cli, LaunchOptions* options) {
  if (!cli.has("--compare")) return;
  std::vector<const ReusePolicy*> policies;
  try {
    policies = parse_policy_list(cli.values("--compare").at(0));
  } catch (const std::invalid_argument& e) {
    throw UsageError("--compare: " + std::string(e.what()));
  }
  if (int(policies.size()) > kMaxComparedPolicies) {
    throw UsageError("--compare: at most " + std::to_string(kMaxComparedPolicies) +
                     " policies, not " + std::to_string(policies.size()));
  }
  options->state.compared.clear();
  for (const ReusePolicy* policy : policies) options->state.compared.push_back(policy->name);
}

// The lesson `name_or_file` for `option`: a shipped lesson, or a lesson file (added for the
// run, session/lessons/lessons.h add_lesson).
const Lesson& lesson_named(const std::string& option, const std::string& name_or_file) {
  try {
    return find_or_read_lesson(name_or_file);
  } catch (const SessionError& e) {  // not a lesson, or a lesson file that cannot be used
    throw UsageError(option + ": " + std::string(e.what()));
  }
}

// The state the other options go over: --session's, --lesson's or the default window's.
void read_base_state(const CliArgs& cli, LaunchOptions* options) {
  if (cli.has("--session") && cli.has("--lesson")) {
    throw UsageError("--lesson: give --session or --lesson, not both (a session keeps its lesson)");
  }
  if (cli.has("--session")) {
    try {
      options->state = read_session_file(cli.values("--session").at(0));
      options->state_origin = "--session: " + cli.values("--session").at(0);
    } catch (const SessionError& e) {
      throw UsageError("--session: " + std::string(e.what()));
    }
  }
  if (!cli.has("--lesson")) return;
  options->state = lesson_named("--lesson", cli.values("--lesson").at(0)).state;
  options->state_origin = "--lesson: " + cli.values("--lesson").at(0);
}

// --check-lesson NAME|FILE|all: the lessons whose claims are checked.
void read_check_lessons(const CliArgs& cli, LaunchOptions* options) {
  if (!cli.has("--check-lesson")) return;
  const std::string name = cli.values("--check-lesson").at(0);
  try {
    if (name == "all") {
      for (const Lesson& lesson : lessons()) options->check_lessons.push_back(lesson.name);
      return;
    }
  } catch (const SessionError& e) {
    throw UsageError("--check-lesson: " + std::string(e.what()));
  }
  options->check_lessons.push_back(lesson_named("--check-lesson", name).name);
}

// --claim-kinds K1,K2,...: with --check-lesson; each a kind of the claim registry, or
// `screen`: every kind the screen measures but the timed ones (a window's size or look
// changes only those; the engine's hold whatever the window).
void read_claim_kinds(const CliArgs& cli, LaunchOptions* options) {
  if (!cli.has("--claim-kinds")) return;
  if (options->check_lessons.empty()) {
    throw UsageError("--claim-kinds: only used with --check-lesson");
  }
  std::stringstream list(cli.values("--claim-kinds").at(0));
  for (std::string kind; std::getline(list, kind, ',');) {
    if (kind == "screen") {
      for (const ClaimKind& k : claim_kinds()) {
        if (k.source == ClaimSource::kScreen && !k.timed) options->claim_kinds.push_back(k.name);
      }
      continue;
    }
    if (!find_claim_kind(kind)) {
      throw UsageError("--claim-kinds: unknown claim kind '" + kind + "' (known: screen, " +
                       joined_names(claim_kind_names()) + ")");
    }
    options->claim_kinds.push_back(kind);
  }
  if (options->claim_kinds.empty()) throw UsageError("--claim-kinds: no kind named");
}

// --step-shots DIR: with --check-lesson; DIR an existing directory; every picture it would
// write checked now as --screenshot's file is (no overwrite without --force).
void read_step_shots(const CliArgs& cli, LaunchOptions* options) {
  if (!cli.has("--step-shots")) return;
  const std::string dir = cli.values("--step-shots").at(0);
  if (options->check_lessons.empty()) {
    throw UsageError("--step-shots: only used with --check-lesson");
  }
  if (!std::filesystem::is_directory(dir)) {
    throw UsageError("--step-shots: '" + dir + "' is not a directory");
  }
  for (const std::string& name : options->check_lessons) {
    const Lesson* lesson = find_lesson(name);
    for (size_t part = 0; lesson && part <= lesson->steps.size(); ++part) {
      check_out_file("--step-shots", step_shot_path(dir, name, int(part)), cli.has("--force"));
    }
  }
  options->step_shots = dir;
}

void read_animation_show(const CliArgs& cli, LaunchOptions* options) {
  if (!cli.has("--animation-show")) return;
  const std::string text = cli.values("--animation-show").at(0);
  if (!parse_panel_display(text, &options->state.display)) {
    throw UsageError("--animation-show: unknown display '" + text +
                     "' (known: " + panel_display_names() + ")");
  }
}

void read_animation_exact(const CliArgs& cli, LaunchOptions* options) {
  if (!cli.has("--animation-exact")) return;
  const std::string text = cli.values("--animation-exact").at(0);
  if (!find_exact_renderer(text)) {
    throw UsageError("--animation-exact: unknown renderer '" + text +
                     "' (known: " + exact_renderer_names() + ")");
  }
  options->state.exact_renderer = text;
}

void read_size(const CliArgs& cli, LaunchOptions* options) {
  if (!cli.has("--size")) return;
  const Vec2 size = cli.vec2("--size");
  for (double v : {size.x, size.y}) {
    if (v != static_cast<int>(v) || v < 320 || v > 8192) {
      throw UsageError("--size: width and height must be whole numbers from 320 to 8192");
    }
  }
  options->width = static_cast<int>(size.x);
  options->height = static_cast<int>(size.y);
}

// The --flow-draw names of every drawing option, and "none".
std::string flow_draw_names(const std::string& separator) {
  std::string names;
  for (const FlowDrawOption& option : flow_draw_options()) names += option.cli_name + separator;
  return names + "none";
}

// "--flow-draw arrows,wheel": the listed drawings on, the others off.
void parse_flow_draw(const std::string& list, FlowDisplay* d) {
  for (const FlowDrawOption& option : flow_draw_options()) d->*option.member = false;
  std::stringstream items(list);
  std::string item;
  while (std::getline(items, item, ',')) {
    if (item == "none") continue;
    const auto& options = flow_draw_options();
    const auto found = std::find_if(options.begin(), options.end(),
                                    [&](const FlowDrawOption& o) { return item == o.cli_name; });
    if (found == options.end()) {
      throw UsageError("--flow-draw: unknown item '" + item + "' (known: " + flow_draw_names(", ") +
                       ")");
    }
    d->*found->member = true;
  }
}

void read_view_overrides(const CliArgs& cli, LaunchOptions* options) {
  if (cli.has("--flow-show")) {
    FlowPart part = FlowPart::kFull;
    const std::string key = cli.values("--flow-show").at(0);
    if (!parse_flow_part(key, &part)) {
      std::vector<std::string> keys;
      for (int k = 0; k < kFlowPartCount; ++k) keys.push_back(flow_part_key(FlowPart(k)));
      throw UsageError("--flow-show: unknown part '" + key + "' (known: " + joined_names(keys) +
                       ")");
    }
    options->state.flow.part = part;
  }
  if (cli.has("--flow-draw"))
    parse_flow_draw(cli.values("--flow-draw").at(0), &options->state.flow);
  if (cli.has("--basis")) {
    BasisKind kind = BasisKind::kPlanar;
    const std::string key = cli.values("--basis").at(0);
    if (!parse_basis_kind(key, &kind)) {
      throw UsageError("--basis: unknown basis '" + key +
                       "' (known: taylor, waxman-ullman, planar)");
    }
    options->state.basis = kind;
  }
  if (cli.has("--presentation")) options->state.presentation = true;
  if (cli.has("--cause-and-effect")) options->state.cause_and_effect = true;
  if (cli.has("--basis-explorer")) options->state.basis_explorer = true;
  if (cli.has("--world-camera")) {
    const std::string key = cli.values("--world-camera").at(0);
    if (!parse_world_camera(key, &options->state.world_camera)) {
      throw UsageError("--world-camera: unknown camera '" + key + "' (known: orbit, eye)");
    }
  }
}

void read_run_mode(const CliArgs& cli, LaunchOptions* options) {
  options->screenshot = cli.text_or("--screenshot", "");
  if (cli.has("--screenshot") && options->screenshot.empty()) {
    throw UsageError("--screenshot: the file name is empty");
  }
  if (cli.has("--force") && options->screenshot.empty() && !cli.has("--step-shots") &&
      !cli.has("--study-csv")) {
    throw UsageError("--force: only used with --screenshot, --step-shots or --study-csv");
  }
  if (!options->screenshot.empty()) {
    // As oflab-cli's outputs: PNG by its extension, no overwrite without --force, never a
    // directory or a device (the file is then written whole, app/app_runner.cpp).
    std::string ext = std::filesystem::path(options->screenshot).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext != ".png") {
      throw UsageError("--screenshot: '" + options->screenshot +
                       "': a screenshot is a PNG file; give a name ending in .png");
    }
    check_out_file("--screenshot", options->screenshot, cli.has("--force"));
  }
  options->whole_window = cli.has("--whole-window");
  if (options->whole_window && options->screenshot.empty()) {
    throw UsageError("--whole-window: only used with --screenshot");
  }
  if (cli.has("--frames") && options->screenshot.empty()) {
    throw UsageError("--frames: only used with --screenshot");
  }
  // The CLI's rule for counts: the range is checked on the number as written, so a huge
  // one is named with its range rather than as too large for a whole number.
  options->frames = cli.has("--frames") ? cli.integer_in("--frames", limits::kWindowFrames) : 0;
  options->benchmark =
      cli.has("--benchmark") ? cli.integer_in("--benchmark", limits::kWindowPlayedFrames) : 0;
  if (options->benchmark > 0 && !options->screenshot.empty()) {
    throw UsageError("--benchmark: cannot be combined with --screenshot");
  }
  options->time_claims = cli.has("--time-claims");
  if (options->time_claims && options->check_lessons.empty()) {
    throw UsageError("--time-claims: only used with --check-lesson");
  }
  options->threads =
      cli.has("--threads")
          ? cli.integer_in("--threads", limits::kWorkerThreads)
          : std::min(machine_cores(), static_cast<int>(limits::kWorkerThreads.maximum));
}

}  // namespace

std::string step_shot_path(const std::string& dir, const std::string& lesson, int part) {
  const std::string name =
      "lesson-" + lesson + (part == 0 ? std::string() : "-step-" + std::to_string(part)) + ".png";
  return (std::filesystem::path(dir) / name).string();
}

const std::vector<std::string>& screenshot_view_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> all = view_table_names();
    all.push_back("window");
    return all;
  }();
  return names;
}

// --study and the options that go with it.
void read_study(const CliArgs& cli, LaunchOptions* options) {
  for (const char* o : {"--study-method", "--study-seed", "--study-observer", "--study-ppi",
                        "--study-simulate", "--study-csv"}) {
    if (cli.has(o) && !cli.has("--study"))
      throw UsageError(std::string(o) + ": only used with --study");
  }
  if (!cli.has("--study")) return;
  StudyLaunch& s = options->study;
  try {
    s.study = find_or_read_study(cli.values("--study").at(0));
  } catch (const StudyError& e) {
    throw UsageError("--study: " + std::string(e.what()));
  }
  s.method = cli.text_or("--study-method", s.study->method);
  if (!find_adaptive_method(s.method)) {
    throw UsageError("--study-method: unknown method '" + s.method +
                     "' (known: " + adaptive_method_names() + ")");
  }
  s.seed = cli.has("--study-seed")
               ? std::uint64_t(cli.integer_in("--study-seed", study_limits::kSeed))
               : s.study->seed;
  s.observer = cli.text_or("--study-observer", cli.has("--study-simulate") ? "simulated" : "");
  if ((cli.has("--study-observer") && s.observer.empty()) ||
      s.observer.find_first_of(",\n\r") != std::string::npos) {
    throw UsageError("--study-observer: a name without commas or line breaks");
  }
  s.ppi = cli.has("--study-ppi") ? cli.number_in("--study-ppi", study_limits::kPpi) : 96.0;
  if (cli.has("--study-simulate") != cli.has("--study-csv")) {
    throw UsageError("--study-simulate: give it with --study-csv FILE, the trials' file");
  }
  if (!cli.has("--study-simulate")) return;
  s.simulate_px = cli.number_in("--study-simulate", study_limits::kErrorPx);
  if (s.simulate_px < s.study->min_px || s.simulate_px > s.study->max_px) {
    throw UsageError("--study-simulate: " + std::to_string(s.simulate_px) +
                     " px is outside the study's error range");
  }
  s.csv = cli.values("--study-csv").at(0);
  s.force = cli.has("--force");
  check_out_file("--study-csv", s.csv, s.force);
}

LaunchOptions parse_launch_options(const std::vector<std::string>& args) {
  const CliArgs cli(args,
                    {{"--session", 1},        {"--lesson", 1},         {"--scene", 1},
                     {"--script", 1},         {"--source", 1},         {"--mode", 1},
                     {"--animation-show", 1}, {"--compare", 1},        {"--animation-exact", 1},
                     {"--view", 1},           {"--screenshot", 1},     {"--whole-window", 0},
                     {"--frames", 1},         {"--benchmark", 1},      {"--size", 2},
                     {"--flow-show", 1},      {"--flow-draw", 1},      {"--basis", 1},
                     {"--presentation", 0},   {"--help", 0},           {"--check-lesson", 1},
                     {"--step-shots", 1},     {"--force", 0},          {"--cause-and-effect", 0},
                     {"--basis-explorer", 0}, {"--threads", 1},        {"--time-claims", 0},
                     {"--world-camera", 1},   {"--claim-kinds", 1},    {"--study", 1},
                     {"--study-method", 1},   {"--study-seed", 1},     {"--study-observer", 1},
                     {"--study-ppi", 1},      {"--study-simulate", 1}, {"--study-csv", 1}});
  LaunchOptions options;
  options.help = cli.has("--help");
  read_base_state(cli, &options);
  read_check_lessons(cli, &options);
  read_claim_kinds(cli, &options);
  read_step_shots(cli, &options);
  read_script(cli, &options);
  check_source(cli);
  read_scene(cli, &options);
  read_mode(cli, &options);
  read_animation_show(cli, &options);
  read_compared(cli, &options);
  read_animation_exact(cli, &options);
  options.view = cli.text_or("--view", "");
  const auto& views = screenshot_view_names();
  if (!options.view.empty() && std::find(views.begin(), views.end(), options.view) == views.end()) {
    throw UsageError("--view: unknown view '" + options.view + "' (known: " + joined_names(views) +
                     ")");
  }
  if (!options.view.empty() && options.view != "window") options.state.view = options.view;
  read_run_mode(cli, &options);
  read_size(cli, &options);
  read_view_overrides(cli, &options);
  read_study(cli, &options);
  const std::string problem = window_state_problem(options.state);
  if (!problem.empty()) throw UsageError(problem);
  return options;
}

std::string launch_usage() {
  std::vector<std::string> titled;
  for (const ViewEntry& view : view_table()) titled.push_back(view.name + " (" + view.title + ")");
  return "usage: oflab [--session FILE | --lesson NAME] [--script NAME|FILE] [--scene NAME|FILE]\n"
         "             [--source " +
         joined_names(scene_source_kinds(), "|") +
         "]\n"
         "             [--mode " +
         reuse_policy_names("|") +
         "]\n"
         "             [--animation-show side-by-side|difference|blink|comparison]\n"
         "             [--compare P1,P2,... (up to " +
         std::to_string(kMaxComparedPolicies) +
         " policies)]\n"
         "             [--animation-exact " +
         exact_renderer_names("|") +
         "]\n"
         "             [--view " +
         joined_names(screenshot_view_names(), "|") +
         "]\n"
         "             [--screenshot FILE.png [--force] --frames N [--whole-window]] [--benchmark "
         "N] [--size "
         "W H]\n"
         "             [--flow-show PART] [--flow-draw " +
         flow_draw_names(",") +
         "]\n"
         "             [--basis taylor|waxman-ullman|planar] [--presentation] "
         "[--cause-and-effect] [--basis-explorer]\n"
         "             [--world-camera orbit|eye]\n"
         "             [--threads N (the pixel loops' threads; default: the machine's cores)]\n"
         "             [--check-lesson NAME|FILE|all [--step-shots DIR [--force]] [--time-claims]\n"
         "                [--claim-kinds K1,K2,... (only these kinds of claims; screen: every\n"
         "                 untimed kind the screen measures)]]\n"
         "             [--study NAME|FILE [--study-method M] [--study-seed S] [--study-observer "
         "NAME]\n"
         "                [--study-ppi P] [--study-simulate PX --study-csv FILE [--force]]] "
         "[--help]\n"
         "  --study: the threshold study's window (how much error can you see?); with "
         "--study-simulate\n"
         "    a simulated observer of threshold PX answers in it and --study-csv gets the "
         "trials\n"
         "  views: " +
         joined_names(titled) +
         "; window is the whole window\n"
         "  --cause-and-effect: the world view beside the flow view (F8 in the window)\n"
         "  --world-camera eye: the world view looks through the eye (its \"View from the "
         "camera\"); orbit (the default) frames the whole world from beside it\n"
         "  --basis-explorer: the basis view's explorer (dial the planar terms, solve for the "
         "world)\n"
         "  lessons: " +
         lesson_names() + "\n  shipped scripts: " + joined_names(shipped_script_names()) +
         "\n  shipped scenes (--script then names a viewer script: " +
         joined_names(shipped_viewer_script_names()) + "): " + joined_names(shipped_scene_names()) +
         "\n";
}

}  // namespace oflab
