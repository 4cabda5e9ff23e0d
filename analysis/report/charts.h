// Report charts: line, point and bar plots drawn with VTK's chart classes (vtkChartXY in a
// vtkContextView, several panels stacked with vtkChartMatrix) offscreen into PNG files,
// and the CSV of the numbers behind each chart. VTK stays inside charts.cpp.
//
// Rendering needs an X display (Debian's VTK 9.1 renders through X11 only): run under
// `xvfb-run -a` on a machine without one. Without a display write_chart_png throws
// ChartError instead of letting VTK abort.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace oflab {

class ChartError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ChartColor {
  std::uint8_t r = 0, g = 0, b = 0;
};

// A fixed palette of distinguishable colours; index wraps around.
ChartColor chart_palette(int index);

enum class SeriesStyle { kLine, kPoints, kBars };

// One plotted series. x and y have the same length; points with a non-finite x or y are
// left out of the picture (and written as empty cells in the CSV).
struct ChartSeries {
  std::string name;
  std::vector<double> x;
  std::vector<double> y;
  SeriesStyle style = SeriesStyle::kLine;
  ChartColor color;
};

// A labelled axis position, e.g. (2, "affine") on a level axis.
using AxisTick = std::pair<double, std::string>;

// One chart; a Chart stacks several, top to bottom, sharing the picture's width.
struct ChartPanel {
  std::string title;
  std::string x_label;
  std::string y_label;
  std::vector<ChartSeries> series;
  std::optional<std::pair<double, double>> x_range;  // fixed axis range, else automatic
  std::optional<std::pair<double, double>> y_range;
  std::vector<AxisTick> x_ticks;  // custom labelled ticks, else automatic
  std::vector<AxisTick> y_ticks;
};

struct Chart {
  std::vector<ChartPanel> panels;
  int width = 960;         // pixels
  int panel_height = 300;  // pixels per panel
};

// Empty when charts can be drawn here; otherwise why not (no X display).
std::string chart_display_problem();

// The process's one X display connection (an X11 Display*) for offscreen VTK windows, to
// pass to vtkRenderWindow::SetDisplayId before the window first renders. It is opened once,
// retrying for up to two seconds: a busy X server (Xvfb on a loaded machine) now and then
// refuses a new connection (EAGAIN, or reset by peer), and a VTK window that opens its own
// connection aborts the process when that happens. Throws ChartError when no connection
// can be made. Closed at exit.
void* shared_x_display();

// Draws `chart` offscreen and writes it as an RGB PNG to `path` (overwriting it). Throws
// ChartError when there is no X display, the chart has no panel, a series' x and y differ
// in length, or the file cannot be written.
void write_chart_png(const Chart& chart, const std::string& path);

// The numbers behind `chart` as one CSV table. When every series of every panel has the
// same x values it is written wide: the x column (named after the first panel's x label),
// then one column per series ("panel title: series name" when there are several panels).
// Otherwise it is written long: panel,series,x,y, one row per point.
void write_chart_csv(const Chart& chart, std::ostream& out);

// The tick labels of the five update levels (0 none .. 4 re-render) for a level axis.
std::vector<AxisTick> level_ticks();

}  // namespace oflab
