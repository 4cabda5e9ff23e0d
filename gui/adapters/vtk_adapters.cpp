#include "adapters/vtk_adapters.h"

#include <vtkCellArray.h>
#include <vtkPointData.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

#include <cmath>
#include <cstring>

namespace oflab {

Vec3 image_plane_point(const Camera& camera, const Vec2& p) {
  return Vec3(p.x / camera.focal_px, p.y / camera.focal_px, 1.0);
}

vtkSmartPointer<vtkImageData> image_data_from_qimage(const QImage& image) {
  const QImage rgba = image.convertToFormat(QImage::Format_RGBA8888);
  auto data = vtkSmartPointer<vtkImageData>::New();
  data->SetDimensions(rgba.width(), rgba.height(), 1);
  data->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
  auto* out = static_cast<unsigned char*>(data->GetScalarPointer());
  const int row_bytes = 4 * rgba.width();
  for (int row = 0; row < rgba.height(); ++row) {
    std::memcpy(out + static_cast<size_t>(rgba.height() - 1 - row) * row_bytes,
                rgba.constScanLine(row), row_bytes);
  }
  return data;
}

vtkSmartPointer<vtkPolyData> polylines(const std::vector<std::vector<Vec3>>& lines) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  for (const auto& line : lines) {
    if (line.size() < 2) continue;
    cells->InsertNextCell(static_cast<vtkIdType>(line.size()));
    for (const Vec3& p : line) cells->InsertCellPoint(points->InsertNextPoint(p.x, p.y, p.z));
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetLines(cells);
  return data;
}

vtkSmartPointer<vtkPolyData> closed_outline(const std::vector<Vec3>& points) {
  std::vector<Vec3> loop = points;
  if (!points.empty()) loop.push_back(points.front());
  return polylines({loop});
}

vtkSmartPointer<vtkPolyData> coloured_disc(double radius,
                                           const std::function<Rgb8(const Vec2&)>& colour_at) {
  constexpr int kRings = 16, kSectors = 72;
  constexpr double kTwoPi = 6.283185307179586;
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto colours = vtkSmartPointer<vtkUnsignedCharArray>::New();
  colours->SetNumberOfComponents(3);
  auto add_point = [&](const Vec2& offset) {
    const Rgb8 c = colour_at(offset);
    colours->InsertNextTuple3(c.r, c.g, c.b);
    return points->InsertNextPoint(offset.x, offset.y, 0.0);
  };
  const vtkIdType centre_id = add_point(Vec2(0.0));
  for (int ring = 1; ring <= kRings; ++ring) {
    for (int s = 0; s < kSectors; ++s) {
      const double a = kTwoPi * s / kSectors, r = radius * ring / kRings;
      add_point(Vec2(r * std::cos(a), r * std::sin(a)));
    }
  }
  auto id = [&](int ring, int s) {
    return ring == 0 ? centre_id : 1 + (ring - 1) * kSectors + (s % kSectors);
  };
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  for (int ring = 0; ring < kRings; ++ring) {
    for (int s = 0; s < kSectors; ++s) {
      const vtkIdType quad[4] = {id(ring, s), id(ring + 1, s), id(ring + 1, s + 1),
                                 id(ring, s + 1)};
      if (ring == 0) {
        const vtkIdType tri[3] = {quad[0], quad[1], quad[2]};
        polys->InsertNextCell(3, tri);
      } else {
        polys->InsertNextCell(4, quad);
      }
    }
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetPolys(polys);
  data->GetPointData()->SetScalars(colours);
  return data;
}

vtkSmartPointer<vtkLookupTable> magnitude_lookup_table(double max_value, double top) {
  auto table = vtkSmartPointer<vtkLookupTable>::New();
  table->SetNumberOfTableValues(256);
  table->SetRange(0.0, max_value > 0.0 ? max_value : 1.0);
  for (int i = 0; i < 256; ++i) {
    const RgbF c = rgb(magnitude_colour(top * i / 255.0));
    table->SetTableValue(i, c[0], c[1], c[2], 1.0);
  }
  return table;
}

RgbF rgb(const Rgb8& colour) { return {colour.r / 255.0, colour.g / 255.0, colour.b / 255.0}; }

void set_line_style(vtkProperty* property, const RgbF& colour, double width) {
  property->SetColor(colour[0], colour[1], colour[2]);
  property->SetLineWidth(static_cast<float>(width));
  property->LightingOff();
}

double font_points_to_px(int points, vtkRenderWindow* window) {
  return points * window->GetDPI() / 72.0;
}

void set_text_style(vtkTextProperty* property, const RgbF& colour, int font_size) {
  property->SetColor(colour[0], colour[1], colour[2]);
  property->SetFontSize(font_size);
  property->SetFontFamilyToArial();
}

}  // namespace oflab
