#include "cli/commands.h"

#include <algorithm>
#include <exception>
#include <ostream>
#include <string>

#include "cli/cli_args.h"
#include "content/layer_content.h"
#include "engine/reuse_policy.h"
#include "experiments/experiments.h"
#include "flow/decomposition.h"
#include "flow/motion.h"
#include "formats/atomic_file.h"
#include "formats/vtk_export.h"
#include "image/thread_pool.h"
#include "image/warp.h"
#include "runs/run_driver.h"
#include "runs/source_kinds.h"

namespace oflab {

namespace {

// `animate --help`: the --mode and --sampling values come from their registries.
std::string animate_usage() {
  std::string usage = "oflab-cli animate --script NAME|FILE [--texture FILE]\n";
  usage += "               [--mode " + reuse_policy_names("|") + "]\n";
  usage += "               [--threshold PX | --thresholds T0 T1 T2 T3]\n";
  usage += "               [--delta " + delta_policy_name_list("|") + "]\n";
  usage += "               [--sampling " + sampling_name_list("|") + "] [--frames N]\n";
  usage += "               [--content " + content_name_list("|") + "] [--quality N]\n";
  usage += "               [--budget-pixels N | --budget-ms T]   (--mode budget only)\n";
  usage +=
      "               [--cadence N] [--stabilization-plane X Y Z NX NY NZ]\n"
      "                 (a policy on a fixed cadence: render every N-th frame, 1..8)\n";
  usage += "               [--repeat-timing N]   (timed passes after a warm-up, default " +
           std::to_string(kDefaultTimingRepetitions) +
           ")\n"
           "               [--no-warm-up] [--repeat N]   (the script N times back to back)\n";
  usage +=
      "               [--out DIR [--force] [--frames-png]] [--json] [--quiet]\n"
      "               [--video FILE.mp4|FILE.gif|FILE.ogv [--fps N] [--force]]\n"
      "               [--vtk-series DIR [--force]]   (each frame as ParaView data)\n"
      "       oflab-cli animate --scene NAME|FILE --script NAME|FILE [same options]\n"
      "               [--compare-conventional [--conventional-single-sample]]\n"
      "               [--near Z] [--guard-band G] [--hole-fill none|stretch|background]\n"
      "               [--cache-angle DEG] [--node-polygons N] [--safety-radius R]\n"
      "               [--mesh-grid PX] [--mesh-split Z] [--mesh-rebuild D] [--mesh-jump J]\n"
      "               [--rubber-sheets drop|keep] [--warp visible|whole]\n"
      "               [--no-skip-hidden]   (--compare-conventional needs an X display)\n"
      "       oflab-cli animate --mode " +
      source_kind_modes("|") +
      " --scene NAME|FILE --script NAME|FILE\n"
      "               [--epsilon PX] [--sampling, --frames, --repeat-timing, --no-warm-up,\n"
      "               --out, --video, --json, --quiet as above]\n"
      "  modes: the reuse policies of 'oflab-cli policies', or " +
      source_kind_modes(", ");
  return usage;
}

// `flow --help`: the --motion values come from core/flow/motion.h.
std::string flow_usage() {
  return "oflab-cli flow --focal F --image W H --plane-point X Y Z --plane-normal NX NY NZ\n"
         "               --velocity V1 V2 V3 --omega O1 O2 O3 [--plane-up UX UY UZ\n"
         "               --plane-size SW SH] [--dt T] [--motion " +
         motion_model_name_list("|") +
         "] [--explain] [--json]\n"
         "               [--vtk FILE.vti [--vtk-step N] [--force]]\n"
         "  --vtk: the flow field for ParaView, on a grid every N px (default " +
         std::to_string(kDefaultVtkGridStep) + ")";
}

// `experiments --help`: the --only values come from the experiments table.
std::string experiments_usage() {
  std::string only;
  for (const std::string& name : experiment_names()) only += (only.empty() ? "" : "|") + name;
  return "oflab-cli experiments [--out DIR] [--only " + only +
         " ...] [--quick]\n"
         "               [--videos mp4|gif|ogv] [--force]\n"
         "               (draws charts: needs an X display, e.g. xvfb-run -a)";
}

}  // namespace

namespace {

std::vector<Command>& command_table() {
  static std::vector<Command> commands = {
      {"flow", "instantaneous optic flow of a moving plane: coefficients, bases, homographies",
       flow_usage(), run_flow_command},
      {"explain",
       "the planes and motions that make a planar flow: the eight coefficients back to 3D",
       "oflab-cli explain --coefficients TX TY J11 J12 J21 J22 PX PY --focal F [--at X Y]\n"
       "               [--json]   (coefficients in centred pixels per unit time; --at: the\n"
       "               centred pixel where the plane must be in front, default 0 0)",
       run_explain_command},
      {"animate", "play a motion script through the engine: levels, errors, savings",
       animate_usage(), run_animate_command},
      {"policies", "list the engine's reuse policies (the values of animate --mode)",
       "oflab-cli policies [--json]", run_policies_command},
      {"compare", "play one script under several reuse policies, one row per policy",
       "oflab-cli compare --script NAME|FILE [--scene NAME|FILE] --policies P1,P2,...\n"
       "               [--texture FILE] [--threshold T | --thresholds T0 T1 T2 T3]\n"
       "               [--delta ...] [--sampling ...] [--frames N] [--repeat-timing N]\n"
       "               [--content texture|shaded|impostor] [--quality N]\n"
       "               [--budget-pixels N | --budget-ms T]   (with budget in the list)\n"
       "               [--cadence N] [--stabilization-plane X Y Z NX NY NZ]\n"
       "               [--near Z] [--guard-band G] [--no-skip-hidden]\n"
       "               [--warp visible|whole] [--hole-fill none|stretch|background]\n"
       "               [--cache-angle DEG] [--node-polygons N] [--safety-radius R]\n"
       "               [--mesh-grid PX] [--mesh-split Z] [--mesh-rebuild D] [--mesh-jump J]\n"
       "               [--rubber-sheets drop|keep]\n"
       "               [--json] [--out DIR [--force]] [--quiet]\n"
       "  policies: the names of 'oflab-cli policies'",
       run_compare_command},
      {"make-butterfly", "write the bundled butterfly texture as a PNG",
       "oflab-cli make-butterfly --out FILE [--force]", run_make_butterfly_command},
      {"make-scene", "write a grid-of-cubes scene, an OBJ file as a scene, or the tile texture",
       "oflab-cli make-scene (--cubes N | --from-obj FILE | --tile-texture) --out FILE\n"
       "               [--texture PATH] [--force]",
       run_make_scene_command},
      {"slices", "scene-shifting slices of a sideways-moving viewer and their asymptote",
       "oflab-cli slices --speed V --focal K --epsilon E [--near Z0] [--json]", run_slices_command},
      {"experiments", "re-run the dissertation's experiments; report beside the published figures",
       experiments_usage(), run_experiments_command},
  };
  return commands;
}

}  // namespace

const std::vector<Command>& all_commands() { return command_table(); }

void add_command(const Command& command) { command_table().push_back(command); }

namespace {

void print_help(std::ostream& out) {
  out << "oflab-cli: headless tools of Optic Flow Lab\n\nCommands:\n";
  for (const Command& c : all_commands()) out << "  " << c.name << "  " << c.summary << "\n";
  out << "\nRun 'oflab-cli COMMAND --help' for a command's options. Every command takes\n"
         "--threads N: the threads of the pixel loops (1..64; default: the machine's cores).\n";
}

// Takes `--threads N` (the one option of every command) out of a command's arguments and
// sets core's worker threads: N, or the machine's cores without it.
CommandArgs take_threads_option(const CommandArgs& args) {
  CommandArgs rest;
  int threads = machine_cores();
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] != "--threads") {
      rest.push_back(args[i]);
      continue;
    }
    std::vector<std::string> option(
        args.begin() + static_cast<std::ptrdiff_t>(i),
        args.begin() + static_cast<std::ptrdiff_t>(std::min(i + 2, args.size())));
    threads = CliArgs(option, {{"--threads", 1}}).integer_in("--threads", limits::kWorkerThreads);
    ++i;
  }
  set_worker_threads(std::min(threads, kMaxWorkerThreads));
  return rest;
}

}  // namespace

int run_cli(const CommandArgs& args, std::ostream& out, std::ostream& err) {
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    print_help(args.empty() ? err : out);
    return args.empty() ? 2 : 0;
  }
  for (const Command& c : all_commands()) {
    if (args[0] != c.name) continue;
    const CommandArgs given(args.begin() + 1, args.end());
    if (!given.empty() && (given[0] == "--help" || given[0] == "-h")) {
      out << "usage: " << c.usage << " [--threads N]\n";
      return 0;
    }
    try {
      return c.run(take_threads_option(given), out, err);
    } catch (const UsageError& e) {  // bad input, in any command: one line naming the option
      err << "oflab-cli " << c.name << ": " << e.what() << "\n";
      return 2;
    } catch (const FileWriteError& e) {  // an output that could not be written: one line
      err << "oflab-cli " << c.name << ": " << e.what() << "\n";
      return 1;
    }
  }
  err << "oflab-cli: unknown command '" << args[0] << "' (try oflab-cli --help)\n";
  return 2;
}

int run_guarded(const char* program, const std::function<int()>& body, std::ostream& err) {
  try {
    return body();
  } catch (const std::exception& e) {
    std::string what = e.what();
    for (char& c : what) c = c == '\n' ? ' ' : c;  // one line
    err << program << ": internal error: " << what << "\n";
  } catch (...) {
    err << program << ": internal error: an unknown exception\n";
  }
  return kInternalErrorExitCode;
}

}  // namespace oflab
