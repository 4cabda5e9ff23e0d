// oflab: the teaching GUI. Parses the command line first (bad input exits 2 without
// needing a display), then opens the window; all work happens in the oflab_gui library.
#include <QVTKOpenGLNativeWidget.h>

#include <QApplication>
#include <QSurfaceFormat>
#include <iostream>

#include "app/app_runner.h"
#include "app/launch_options.h"

int main(int argc, char** argv) {
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
  // VTK's OpenGL widget needs its surface format before the application exists.
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication app(argc, argv);
  return oflab::run_oflab(options, std::cout, std::cerr);
}
