// The subcommands of oflab-cli. Each takes its arguments (after the subcommand name) and
// the output streams, and returns the process exit code: 0 on success, 2 on bad input
// (one line on `err` naming the argument; a subcommand throws UsageError for a bad option
// and run_cli prints it), 1 on a failure while running, and kInternalErrorExitCode when an
// exception escapes every command (a bug, or memory run out).
#pragma once

#include <functional>
#include <iosfwd>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace oflab {

using CommandArgs = std::vector<std::string>;

struct Command {
  const char* name;
  const char* summary;
  std::string usage;
  int (*run)(const CommandArgs& args, std::ostream& out, std::ostream& err);
};

// All subcommands, in the order `oflab-cli --help` lists them.
const std::vector<Command>& all_commands();

// Adds a subcommand of a layer above analysis to all_commands(), after the others: oflab-cli's
// main adds the teaching layer's `lesson` (session/cli/lesson_command.h) before run_cli.
void add_command(const Command& command);

// `oflab-cli flow`: the instantaneous flow of one moving plane (analysis/cli/flow_command.cpp).
int run_flow_command(const CommandArgs& args, std::ostream& out, std::ostream& err);
// `oflab-cli explain`: the planes and motions behind eight planar flow coefficients
// (analysis/cli/explain_command.cpp, core/flow/inverse_flow.h).
int run_explain_command(const CommandArgs& args, std::ostream& out, std::ostream& err);
// `oflab-cli slices`: Hofmann's scene-shifting slices (analysis/cli/slices_command.cpp).
int run_slices_command(const CommandArgs& args, std::ostream& out, std::ostream& err);

// `oflab-cli animate`: plays a motion script through the engine (analysis/cli/animate_command.cpp).
int run_animate_command(const CommandArgs& args, std::ostream& out, std::ostream& err);

// `oflab-cli make-butterfly`: writes the bundled demo texture.
int run_make_butterfly_command(const CommandArgs& args, std::ostream& out, std::ostream& err);

// `oflab-cli experiments`: re-runs the dissertation's experiments and writes a report
// (analysis/cli/experiments_command.cpp, manual/experiments.md).
int run_experiments_command(const CommandArgs& args, std::ostream& out, std::ostream& err);

// `oflab-cli policies`: lists the engine's reuse policies, the values of `animate --mode`
// (analysis/cli/policies_command.cpp, core/engine/reuse_policy.h).
// `oflab-cli policies --json`'s object: {"policies": [{"name", "summary", "models", "breaks",
// "schedule", "warp", "latency_frames"} per entry of reuse_policies()],
// "interpolation_latency_frames"}; the Python module's policies() returns its list.
nlohmann::ordered_json policies_json();
int run_policies_command(const CommandArgs& args, std::ostream& out, std::ostream& err);

// `oflab-cli compare`: one script under several reuse policies, a row each
// (analysis/cli/compare_command.cpp, analysis/runs/policy_runs.h).
int run_compare_command(const CommandArgs& args, std::ostream& out, std::ostream& err);

// `oflab-cli make-scene`: writes a grid-of-cubes scene, an OBJ file as a scene, or the
// scenes' tile texture (analysis/cli/make_scene_command.cpp, manual/scenes.md).
int run_make_scene_command(const CommandArgs& args, std::ostream& out, std::ostream& err);

// Dispatches argv[1..] to a subcommand; prints help for no arguments or --help. A
// UsageError (analysis/cli/cli_args.h) escaping a subcommand is reported here, for every
// subcommand alike: "oflab-cli COMMAND: WHAT" on `err` and exit code 2; so is a
// FileWriteError (an output that could not be written, formats/atomic_file.h), with exit
// code 1.
int run_cli(const CommandArgs& args, std::ostream& out, std::ostream& err);

// The exit code of oflab-cli and oflab when an exception escaped everything that turns
// errors into messages.
constexpr int kInternalErrorExitCode = 3;

// A main's last resort: runs `body` and returns its exit code; any exception escaping it
// (std::exception or not) becomes one line on `err`, "<program>: internal error: <what>",
// and kInternalErrorExitCode instead of an abort.
int run_guarded(const char* program, const std::function<int()>& body, std::ostream& err);

}  // namespace oflab
