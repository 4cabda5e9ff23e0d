// ParaView data through VTK's XML writers (formats/vtk_export.h). Each file is made in memory
// (the writers' output string) and written through formats/atomic_file.h, so what ParaView
// finds is whole. The flow's parts come from core (flow_at, taylor_terms, taylor_order_terms,
// taylor_flow_at); nothing here re-derives the flow.
#include "formats/vtk_export.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLPolyDataWriter.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "flow/basis.h"
#include "flow/limits.h"
#include "formats/atomic_file.h"
#include "runs/frame_maps.h"

namespace oflab {
namespace {

// A writer of VTK's XML family set to give its file as a string: appended raw binary data,
// zlib-compressed. Throws std::runtime_error when VTK reports a failure.
template <class Writer, class Data>
std::string xml_bytes(Data* data) {
  vtkNew<Writer> writer;
  writer->SetInputData(data);
  writer->SetWriteToOutputString(true);
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();
  writer->SetCompressorTypeToZLib();
  if (writer->Write() != 1) throw std::runtime_error("VTK's XML writer failed");
  return writer->GetOutputString();
}

vtkNew<vtkDoubleArray> vector_array(const char* name, long points) {
  vtkNew<vtkDoubleArray> a;
  a->SetName(name);
  a->SetNumberOfComponents(3);
  a->SetNumberOfTuples(points);
  return a;
}

// One point per pixel centre of the camera's image, in centred pixels.
vtkNew<vtkImageData> pixel_grid(const Camera& camera, const Image& image) {
  if (image.width() != camera.width || image.height() != camera.height) {
    throw std::invalid_argument("an image of " + std::to_string(image.width()) + " x " +
                                std::to_string(image.height()) + " px is not the camera's " +
                                std::to_string(camera.width) + " x " +
                                std::to_string(camera.height));
  }
  vtkNew<vtkImageData> grid;
  grid->SetOrigin(0.5 - camera.cx, 0.5 - camera.cy, 0.0);
  grid->SetSpacing(1.0, 1.0, 1.0);
  grid->SetDimensions(camera.width, camera.height, 1);
  return grid;
}

// The first and last multiples of `step` in [low, high], and how many there are.
void multiples_within(double low, double high, int step, double* first, int* count) {
  const double a = std::ceil(low / step), b = std::floor(high / step);
  *first = a * step;
  *count = static_cast<int>(b - a) + 1;
}

std::string frame_file(int frame, const char* part, const char* extension) {
  std::ostringstream name;
  name << "frame_" << std::setw(5) << std::setfill('0') << frame << "_" << part << extension;
  return name.str();
}

}  // namespace

FlowGrid flow_grid(const Camera& camera, int step) {
  FlowGrid g;
  g.step = step;
  multiples_within(-camera.cx, camera.width - camera.cx, step, &g.x0, &g.columns);
  multiples_within(-camera.cy, camera.height - camera.cy, step, &g.y0, &g.rows);
  return g;
}

std::string flow_grid_problem(const Camera& camera, double step) {
  if (!limits::kVtkGridStep.allows(step)) return limits::kVtkGridStep.problem(step);
  const int s = static_cast<int>(step);
  const FlowGrid g = flow_grid(camera, s);
  if (limits::kVtkGridPoints.allows(static_cast<double>(g.points()))) return "";
  int fits = s;
  while (fits < limits::kVtkGridStep.maximum &&
         !limits::kVtkGridPoints.allows(static_cast<double>(flow_grid(camera, fits).points()))) {
    ++fits;
  }
  std::ostringstream text;
  text << s << " gives " << g.columns << " x " << g.rows << " = " << g.points()
       << " grid points, more than " << static_cast<long>(limits::kVtkGridPoints.maximum)
       << "; a step of " << fits << " or more fits";
  return text.str();
}

std::string flow_field_vti(const Camera& camera, const PlanarFlowCoefficients& c, int step) {
  if (c.origin != Vec2(0.0, 0.0)) {
    throw std::invalid_argument("flow_field_vti: coefficients about the principal point only");
  }
  const std::string problem = flow_grid_problem(camera, step);
  if (!problem.empty()) throw std::invalid_argument("flow_field_vti: grid step " + problem);
  const FlowGrid g = flow_grid(camera, step);
  vtkNew<vtkImageData> grid;
  grid->SetOrigin(g.x0, g.y0, 0.0);
  grid->SetSpacing(step, step, 1.0);
  grid->SetDimensions(g.columns, g.rows, 1);

  const TaylorTerms terms = taylor_terms(c);
  const TaylorTerms orders[3] = {taylor_order_terms(terms, 0), taylor_order_terms(terms, 1),
                                 taylor_order_terms(terms, 2)};
  auto flow = vector_array("flow", g.points());
  vtkNew<vtkDoubleArray> magnitude;
  magnitude->SetName("magnitude");
  magnitude->SetNumberOfTuples(g.points());
  vtkNew<vtkDoubleArray> parts[3] = {vector_array("translation", g.points()),
                                     vector_array("first_order", g.points()),
                                     vector_array("second_order", g.points())};
  for (int j = 0; j < g.rows; ++j) {
    for (int i = 0; i < g.columns; ++i) {
      const vtkIdType k = static_cast<vtkIdType>(j) * g.columns + i;
      const Vec2 p(g.x0 + i * step, g.y0 + j * step);
      const Vec2 v = flow_at(c, p);
      flow->SetTuple3(k, v.x, v.y, 0.0);
      magnitude->SetValue(k, glm::length(v));
      for (int order = 0; order < 3; ++order) {
        const Vec2 part = taylor_flow_at(orders[order], p);
        parts[order]->SetTuple3(k, part.x, part.y, 0.0);
      }
    }
  }
  vtkPointData* data = grid->GetPointData();
  data->SetVectors(flow);
  data->SetScalars(magnitude);
  for (auto& part : parts) data->AddArray(part);
  return xml_bytes<vtkXMLImageDataWriter>(grid.Get());
}

std::string image_vti(const Camera& camera, const Image& image) {
  vtkNew<vtkImageData> grid = pixel_grid(camera, image);
  vtkNew<vtkUnsignedCharArray> rgba;
  rgba->SetName("rgba");
  rgba->SetNumberOfComponents(4);
  rgba->SetNumberOfTuples(static_cast<vtkIdType>(image.pixel_count()));
  for (std::size_t k = 0; k < image.pixel_count(); ++k) {
    const Pixel p = unpremultiply(image.pixels()[k]);
    const unsigned char tuple[4] = {p.r, p.g, p.b, p.a};
    rgba->SetTypedTuple(static_cast<vtkIdType>(k), tuple);
  }
  grid->GetPointData()->SetScalars(rgba);
  return xml_bytes<vtkXMLImageDataWriter>(grid.Get());
}

std::string difference_vti(const Camera& camera, const Image& shown, const Image& exact) {
  vtkNew<vtkImageData> grid = pixel_grid(camera, shown);
  pixel_grid(camera, exact);  // the same check for the other image
  vtkNew<vtkUnsignedCharArray> difference;
  difference->SetName("difference");
  difference->SetNumberOfTuples(static_cast<vtkIdType>(shown.pixel_count()));
  const std::vector<std::uint8_t> map = channel_difference_map(shown, exact);
  for (std::size_t k = 0; k < map.size(); ++k) {
    difference->SetValue(static_cast<vtkIdType>(k), map[k]);
  }
  grid->GetPointData()->SetScalars(difference);
  return xml_bytes<vtkXMLImageDataWriter>(grid.Get());
}

std::string layers_vtp(const Camera& camera, const std::vector<LayerOutline>& layers) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> polygons;
  vtkNew<vtkIntArray> level, polygon;
  level->SetName("level");
  polygon->SetName("polygon");
  vtkNew<vtkDoubleArray> error;
  error->SetName("error_px");
  for (const LayerOutline& layer : layers) {
    polygons->InsertNextCell(static_cast<vtkIdType>(layer.points.size()));
    for (const Vec2& corner : layer.points) {
      const Vec2 c = pixel_to_centred(camera, corner);
      polygons->InsertCellPoint(points->InsertNextPoint(c.x, c.y, 0.0));
    }
    level->InsertNextValue(static_cast<int>(layer.level));
    polygon->InsertNextValue(layer.polygon);
    error->InsertNextValue(layer.error_px);
  }
  vtkNew<vtkPolyData> data;
  data->SetPoints(points);
  data->SetPolys(polygons);
  data->GetCellData()->SetScalars(level);
  data->GetCellData()->AddArray(polygon);
  data->GetCellData()->AddArray(error);
  return xml_bytes<vtkXMLPolyDataWriter>(data.Get());
}

std::string pvd_collection(const std::vector<double>& times,
                           const std::vector<std::string>& files) {
  if (times.size() != files.size()) {
    throw std::invalid_argument("pvd_collection: one time per file");
  }
  std::ostringstream xml;
  xml.precision(17);
  xml << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "  <Collection>\n";
  for (std::size_t k = 0; k < files.size(); ++k) {
    xml << "    <DataSet timestep=\"" << times[k] << "\" group=\"\" part=\"0\" file=\"" << files[k]
        << "\"/>\n";
  }
  xml << "  </Collection>\n</VTKFile>\n";
  return xml.str();
}

VtkSeriesWriter::VtkSeriesWriter(std::string dir, std::string shown_dir)
    : dir_(std::move(dir)), shown_dir_(std::move(shown_dir)) {}

void VtkSeriesWriter::add_frame(const VtkFrame& frame) {
  namespace fs = std::filesystem;
  const Camera& camera = *frame.camera;
  const auto write = [&](const std::string& name, const std::string& bytes) {
    write_file_inside((fs::path(dir_) / name).string(), bytes,
                      (fs::path(shown_dir_) / name).string());
  };
  write(frame_file(frame.frame, "shown", ".vti"), image_vti(camera, *frame.shown));
  write(frame_file(frame.frame, "exact", ".vti"), image_vti(camera, *frame.exact));
  write(frame_file(frame.frame, "difference", ".vti"),
        difference_vti(camera, *frame.shown, *frame.exact));
  write(frame_file(frame.frame, "layers", ".vtp"), layers_vtp(camera, frame.layers));
  frames_.push_back(frame.frame);
}

void VtkSeriesWriter::finish() {
  namespace fs = std::filesystem;
  const struct {
    const char* part;
    const char* extension;
  } series[] = {{"shown", ".vti"}, {"exact", ".vti"}, {"difference", ".vti"}, {"layers", ".vtp"}};
  for (const auto& s : series) {
    std::vector<double> times;
    std::vector<std::string> files;
    for (int f : frames_) {
      times.push_back(f);
      files.push_back(frame_file(f, s.part, s.extension));
    }
    const std::string name = std::string(s.part) + ".pvd";
    write_file_inside((fs::path(dir_) / name).string(), pvd_collection(times, files),
                      (fs::path(shown_dir_) / name).string());
  }
}

}  // namespace oflab
