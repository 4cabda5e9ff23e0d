// Runs oflab-cli in-process and captures what it prints, for command tests.
#pragma once

#include <sstream>
#include <string>
#include <vector>

#include "cli/commands.h"

namespace oflab::testing {

struct CliResult {
  int code;
  std::string out, err;
};

inline CliResult run_cli_captured(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  const int code = run_cli(args, out, err);
  return {code, out.str(), err.str()};
}

// A number as a command-line argument with all 17 significant digits, so that it reads back
// as the same double.
inline std::string exact_text(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

}  // namespace oflab::testing
