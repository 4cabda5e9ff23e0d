// Runs one oflab-cli command in process through the command table (analysis/cli/commands.h)
// and keeps what it printed: the session commands' tests (lesson, study).
#pragma once

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "cli/commands.h"

namespace oflab::testing {

struct CliRun {
  int code = 0;          // the exit status run_cli returns
  std::string out, err;  // what it printed on each stream
};

// `oflab-cli NAME ARGS...` with `command` (the command called NAME) added to the table unless
// it is there.
inline CliRun run_session_command(const Command& command, const CommandArgs& args) {
  const std::vector<Command>& table = all_commands();
  if (std::none_of(table.begin(), table.end(),
                   [&](const Command& c) { return std::string(c.name) == command.name; })) {
    add_command(command);
  }
  CommandArgs all = {command.name};
  all.insert(all.end(), args.begin(), args.end());
  std::ostringstream out, err;
  CliRun r;
  r.code = run_cli(all, out, err);
  r.out = out.str();
  r.err = err.str();
  return r;
}

}  // namespace oflab::testing
