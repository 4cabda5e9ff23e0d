// oflab-cli: the headless command-line tool: analysis/'s commands and the teaching layer's
// `lesson` and `study`. All work happens in session/, analysis/ and core/; an exception escaping it
// ends the run with one line and kInternalErrorExitCode, never an abort.
#include <csignal>
#include <iostream>

#include "cli/commands.h"
#include "cli/lesson_command.h"
#include "cli/study_command.h"

int main(int argc, char** argv) {
  // A write past the file size limit (ulimit -f) fails with EFBIG like a full disk, and is
  // reported and cleaned up as one (formats/atomic_file.h), instead of killing the process.
  std::signal(SIGXFSZ, SIG_IGN);
  oflab::add_command(oflab::lesson_command());
  oflab::add_command(oflab::study_command());
  return oflab::run_guarded(
      "oflab-cli",
      [&] {
        return oflab::run_cli(oflab::CommandArgs(argv + 1, argv + argc), std::cout, std::cerr);
      },
      std::cerr);
}
