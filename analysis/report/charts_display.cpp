// The X display of the report charts (charts.h): kept apart from charts.cpp because Xlib's
// macros (None, Status, Bool) must not meet VTK's headers.
#include <X11/Xlib.h>

#include <chrono>
#include <cstdlib>
#include <memory>
#include <thread>

#include "report/charts.h"

namespace oflab {

std::string chart_display_problem() {
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display) return "drawing charts needs an X display; run under 'xvfb-run -a'";
  return "";
}

void* shared_x_display() {
  struct Closer {
    void operator()(Display* d) const {
#ifndef __SANITIZE_ADDRESS__
      XCloseDisplay(d);
#else
      // Under AddressSanitizer the connection stays open at exit (the system closes it):
      // closing it unloads Mesa's software driver (swrast_dri.so), and two blocks of 56
      // bytes the driver still holds then count as leaked, against no library (found with a
      // calloc wrapper printing glibc backtraces). Left loaded, they stay reachable.
      static_cast<void>(d);
#endif
    }
  };
  static std::unique_ptr<Display, Closer> display;
  if (display) return display.get();
  if (const std::string problem = chart_display_problem(); !problem.empty()) {
    throw ChartError(problem);
  }
  // 100 attempts 20 ms apart: a refused connection is a busy server, not a missing one.
  for (int attempt = 0; attempt < 100 && !display; ++attempt) {
    display.reset(XOpenDisplay(nullptr));
    if (!display) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  if (!display) {
    throw ChartError(std::string("cannot connect to the X display '") + std::getenv("DISPLAY") +
                     "'");
  }
  return display.get();
}

}  // namespace oflab
