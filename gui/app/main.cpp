// oflab: the teaching GUI. Parses the command line first (bad input exits 2 without
// needing a display), then opens the window; all work happens in the oflab_gui library.
// Its last resort is oflab-cli's (run_guarded, analysis/cli/commands.h).
#include <QApplication>
#include <iostream>

#include "app/app_runner.h"
#include "app/launch_options.h"
#include "cli/commands.h"

namespace {

int run_main(int argc, char** argv) {
  oflab::LaunchOptions options;
  try {
    options = oflab::parse_launch_options(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const oflab::UsageError& e) {
    std::cerr << "oflab: " << e.what() << "\n";  // one line; --help shows the usage
    return 2;
  }
  if (options.help) {
    std::cout << oflab::launch_usage();
    return 0;
  }
  // No surface format of VTK's OpenGL widget: the window holds no OpenGL widget (VTK renders
  // offscreen, adapters/offscreen_vtk.h), and that format's alpha buffer gave the window an
  // ARGB visual whose backing store Qt clears before every repaint (a full pass over the view).
  oflab::GuardedApplication app(argc, argv);
  return oflab::run_oflab(options, std::cout, std::cerr);
}

}  // namespace

// An exception that reaches main (from the command line, the window's set-up, or one Qt's
// event loop passes on) ends the process with one line and kInternalErrorExitCode, not an
// abort.
int main(int argc, char** argv) {
  return oflab::run_guarded(
      "oflab", [&] { return run_main(argc, argv); }, std::cerr);
}
