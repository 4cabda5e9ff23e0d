#include "report/charts.h"

#include <vtkAxis.h>
#include <vtkChartLegend.h>
#include <vtkChartMatrix.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPlot.h>
#include <vtkPlotBar.h>
#include <vtkPlotPoints.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkStringArray.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>
#include <vtkVector.h>
#include <vtkWindowToImageFilter.h>

#include <cmath>
#include <ostream>
#include <sstream>

#include "engine/decision.h"

namespace oflab {
namespace {

void check_chart(const Chart& chart) {
  if (chart.panels.empty()) throw ChartError("chart has no panel");
  if (chart.width < 100 || chart.panel_height < 100) throw ChartError("chart is too small");
  for (const ChartPanel& p : chart.panels) {
    for (const ChartSeries& s : p.series) {
      if (s.x.size() != s.y.size()) {
        throw ChartError("series '" + s.name + "' of '" + p.title + "': x and y differ in length");
      }
    }
  }
}

void set_ticks(vtkAxis* axis, const std::vector<AxisTick>& ticks) {
  if (ticks.empty()) return;
  vtkNew<vtkDoubleArray> positions;
  vtkNew<vtkStringArray> labels;
  for (const auto& [value, label] : ticks) {
    positions->InsertNextValue(value);
    labels->InsertNextValue(label);
  }
  axis->SetCustomTickPositions(positions, labels);
}

void set_range(vtkAxis* axis, const std::optional<std::pair<double, double>>& range) {
  if (!range) return;
  axis->SetBehavior(vtkAxis::FIXED);
  axis->SetRange(range->first, range->second);
}

// The finite points of a series as a two-column table (x, y).
vtkSmartPointer<vtkTable> series_table(const ChartSeries& s) {
  vtkNew<vtkDoubleArray> x;
  x->SetName("x");
  vtkNew<vtkDoubleArray> y;
  y->SetName(s.name.empty() ? "y" : s.name.c_str());
  for (size_t i = 0; i < s.x.size(); ++i) {
    if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
    x->InsertNextValue(s.x[i]);
    y->InsertNextValue(s.y[i]);
  }
  auto table = vtkSmartPointer<vtkTable>::New();
  table->AddColumn(x);
  table->AddColumn(y);
  return table;
}

void add_series(vtkChartXY* chart, const ChartSeries& s) {
  const vtkSmartPointer<vtkTable> table = series_table(s);
  if (table->GetNumberOfRows() == 0) return;  // nothing to draw; VTK dislikes empty plots
  int type = vtkChart::LINE;
  if (s.style == SeriesStyle::kPoints) type = vtkChart::POINTS;
  if (s.style == SeriesStyle::kBars) type = vtkChart::BAR;
  vtkPlot* plot = chart->AddPlot(type);
  plot->SetInputData(table, 0, 1);
  plot->SetColor(s.color.r, s.color.g, s.color.b, 255);
  plot->SetLabel(s.name);
  if (s.style == SeriesStyle::kLine) plot->SetWidth(1.5);
  if (auto* points = vtkPlotPoints::SafeDownCast(plot); points && s.style == SeriesStyle::kPoints) {
    points->SetMarkerStyle(vtkPlotPoints::CIRCLE);
    points->SetMarkerSize(5.0);
  }
}

void fill_panel(vtkChartXY* chart, const ChartPanel& panel) {
  chart->SetTitle(panel.title);
  chart->GetTitleProperties()->SetFontSize(15);
  chart->GetTitleProperties()->SetBold(true);
  vtkAxis* x = chart->GetAxis(vtkAxis::BOTTOM);
  vtkAxis* y = chart->GetAxis(vtkAxis::LEFT);
  x->SetTitle(panel.x_label);
  y->SetTitle(panel.y_label);
  for (vtkAxis* a : {x, y}) {
    a->GetTitleProperties()->SetFontSize(13);
    a->GetLabelProperties()->SetFontSize(12);
  }
  set_range(x, panel.x_range);
  set_range(y, panel.y_range);
  set_ticks(x, panel.x_ticks);
  set_ticks(y, panel.y_ticks);
  for (const ChartSeries& s : panel.series) add_series(chart, s);
  chart->SetShowLegend(panel.series.size() > 1);
  if (chart->GetLegend()) {
    chart->GetLegend()->SetHorizontalAlignment(vtkChartLegend::RIGHT);
    chart->GetLegend()->SetVerticalAlignment(vtkChartLegend::TOP);
    chart->GetLegend()->GetLabelProperties()->SetFontSize(12);
  }
}

std::string csv_number(double v) {
  if (!std::isfinite(v)) return "";
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

std::string csv_text(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string tick_label(const std::vector<AxisTick>& ticks, double x) {
  for (const auto& [value, label] : ticks) {
    if (value == x) return label;
  }
  return "";
}

bool shares_x(const Chart& chart) {
  const std::vector<double>* first = nullptr;
  for (const ChartPanel& p : chart.panels) {
    for (const ChartSeries& s : p.series) {
      if (!first) {
        first = &s.x;
      } else if (s.x != *first) {
        return false;
      }
    }
  }
  return first != nullptr;
}

}  // namespace

ChartColor chart_palette(int index) {
  static const ChartColor colors[] = {
      {31, 119, 180}, {214, 39, 40},   {44, 160, 44},   {255, 127, 14}, {148, 103, 189},
      {140, 86, 75},  {227, 119, 194}, {127, 127, 127}, {188, 189, 34}, {23, 190, 207}};
  const int n = static_cast<int>(sizeof(colors) / sizeof(colors[0]));
  return colors[((index % n) + n) % n];
}

std::vector<AxisTick> level_ticks() {
  std::vector<AxisTick> ticks;
  for (int l = 0; l < kLevelCount; ++l) ticks.push_back({double(l), level_title(Level(l))});
  return ticks;
}

void write_chart_png(const Chart& chart, const std::string& path) {
  check_chart(chart);
  if (const std::string problem = chart_display_problem(); !problem.empty())
    throw ChartError(problem);
  const int panels = static_cast<int>(chart.panels.size());
  vtkNew<vtkContextView> view;
  // No interactor: offscreen charts take no input, and VTK 9.1's X interactor opens a
  // display connection of its own and keeps it after the view is gone.
  view->SetInteractor(nullptr);
  vtkRenderWindow* window = view->GetRenderWindow();
  window->SetDisplayId(shared_x_display());
  window->SetOffScreenRendering(1);
  window->SetSize(chart.width, chart.panel_height * panels);
  view->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
  if (panels == 1) {
    vtkNew<vtkChartXY> xy;
    view->GetScene()->AddItem(xy);
    fill_panel(xy, chart.panels[0]);
    xy->SetAutoSize(true);
    window->Render();
  } else {
    vtkNew<vtkChartMatrix> matrix;
    view->GetScene()->AddItem(matrix);
    matrix->SetSize(vtkVector2i(1, panels));
    matrix->SetGutter(vtkVector2f(40.0f, 70.0f));
    matrix->SetBorders(110, 50, 30, 40);  // room for word tick labels such as "perspective"
    for (int i = 0; i < panels; ++i) {
      // The matrix counts rows from the bottom; panels are listed top to bottom.
      auto* xy = vtkChartXY::SafeDownCast(matrix->GetChart(vtkVector2i(0, panels - 1 - i)));
      if (!xy) throw ChartError("VTK did not create an XY chart for panel " + std::to_string(i));
      fill_panel(xy, chart.panels[i]);
    }
    window->Render();
  }
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputConnection(grab->GetOutputPort());
  writer->Write();
  if (writer->GetErrorCode() != 0) throw ChartError("cannot write chart '" + path + "'");
}

void write_chart_csv(const Chart& chart, std::ostream& out) {
  const bool multi = chart.panels.size() > 1;
  if (shares_x(chart)) {
    const ChartPanel& first = chart.panels.front();
    out << csv_text(first.x_label.empty() ? "x" : first.x_label);
    const std::vector<double>* xs = nullptr;
    std::vector<const ChartSeries*> columns;
    for (const ChartPanel& p : chart.panels) {
      for (const ChartSeries& s : p.series) {
        out << ',' << csv_text(multi ? p.title + ": " + s.name : s.name);
        columns.push_back(&s);
        if (!xs) xs = &s.x;
      }
    }
    const std::vector<AxisTick>& ticks = first.x_ticks;
    if (!ticks.empty()) out << ",label";
    out << '\n';
    for (size_t i = 0; i < xs->size(); ++i) {
      out << csv_number((*xs)[i]);
      for (const ChartSeries* s : columns) out << ',' << csv_number(s->y[i]);
      if (!ticks.empty()) out << ',' << csv_text(tick_label(ticks, (*xs)[i]));
      out << '\n';
    }
    return;
  }
  out << "panel,series,x,y\n";
  for (const ChartPanel& p : chart.panels) {
    for (const ChartSeries& s : p.series) {
      for (size_t i = 0; i < s.x.size(); ++i) {
        out << csv_text(p.title) << ',' << csv_text(s.name) << ',' << csv_number(s.x[i]) << ','
            << csv_number(s.y[i]) << '\n';
      }
    }
  }
}

}  // namespace oflab
