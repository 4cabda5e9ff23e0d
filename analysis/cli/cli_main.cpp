// oflab-cli: the headless command-line tool. All work happens in analysis/ and core/; an
// exception escaping it ends the run with one line and kInternalErrorExitCode, never an abort.
#include <iostream>

#include "cli/commands.h"

int main(int argc, char** argv) {
  return oflab::run_guarded(
      "oflab-cli",
      [&] {
        return oflab::run_cli(oflab::CommandArgs(argv + 1, argv + argc), std::cout, std::cerr);
      },
      std::cerr);
}
