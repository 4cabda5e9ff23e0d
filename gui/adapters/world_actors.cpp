#include "adapters/world_actors.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <array>
#include <cstring>

#include "image/mip_pyramid.h"  // halve_image
#include "image/thread_pool.h"

namespace oflab {
namespace {

// The points of `data` as `points`, reusing the existing vtkPoints.
void set_points(vtkPolyData* data, const std::vector<Vec3>& points) {
  vtkPoints* stored = data->GetPoints();
  if (!stored) {
    data->SetPoints(vtkSmartPointer<vtkPoints>::New());
    stored = data->GetPoints();
  }
  stored->SetNumberOfPoints(vtkIdType(points.size()));
  for (size_t k = 0; k < points.size(); ++k) {
    stored->SetPoint(vtkIdType(k), points[k].x, points[k].y, points[k].z);
  }
  stored->Modified();
}

vtkCellArray* reset_cells(vtkPolyData* data, bool lines) {
  vtkCellArray* cells = lines ? data->GetLines() : data->GetPolys();
  if (!cells || cells == data->GetVerts()) {  // an empty poly data shares a dummy array
    auto fresh = vtkSmartPointer<vtkCellArray>::New();
    lines ? data->SetLines(fresh) : data->SetPolys(fresh);
    cells = fresh;
  }
  cells->Reset();
  return cells;
}

}  // namespace

PolyActor add_poly_actor(vtkRenderer* renderer, const RgbF& colour) {
  PolyActor p{vtkSmartPointer<vtkPolyData>::New(), vtkSmartPointer<vtkActor>::New()};
  p.data->SetPoints(vtkSmartPointer<vtkPoints>::New());
  p.data->SetLines(vtkSmartPointer<vtkCellArray>::New());
  p.data->SetPolys(vtkSmartPointer<vtkCellArray>::New());
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(p.data);
  mapper->ScalarVisibilityOff();
  p.actor->SetMapper(mapper);
  p.actor->GetProperty()->SetColor(colour[0], colour[1], colour[2]);
  p.actor->GetProperty()->LightingOff();
  renderer->AddActor(p.actor);
  return p;
}

void set_polyline(vtkPolyData* data, const std::vector<Vec3>& points, bool closed) {
  set_points(data, points);
  vtkCellArray* cells = reset_cells(data, true);
  if (points.size() >= 2) {
    cells->InsertNextCell(vtkIdType(points.size() + (closed ? 1 : 0)));
    for (size_t k = 0; k < points.size(); ++k) cells->InsertCellPoint(vtkIdType(k));
    if (closed) cells->InsertCellPoint(0);
  }
  cells->Modified();
  data->Modified();
}

void set_segments(vtkPolyData* data, const std::vector<Vec3>& from, const std::vector<Vec3>& to) {
  std::vector<Vec3> points;
  for (size_t k = 0; k < from.size() && k < to.size(); ++k) {
    points.push_back(from[k]);
    points.push_back(to[k]);
  }
  set_points(data, points);
  vtkCellArray* cells = reset_cells(data, true);
  for (vtkIdType k = 0; k + 1 < vtkIdType(points.size()); k += 2) {
    const vtkIdType ends[2] = {k, k + 1};
    cells->InsertNextCell(2, ends);
  }
  cells->Modified();
  data->Modified();
}

void set_textured_quad(vtkPolyData* data, const std::array<Vec3, 4>& corners) {
  const bool built = data->GetNumberOfPolys() == 1;
  set_points(data, std::vector<Vec3>(corners.begin(), corners.end()));
  if (built) {
    data->Modified();
    return;
  }
  vtkCellArray* cells = reset_cells(data, false);
  const vtkIdType quad[4] = {0, 1, 2, 3};
  cells->InsertNextCell(4, quad);
  auto tcoords = vtkSmartPointer<vtkFloatArray>::New();
  tcoords->SetNumberOfComponents(2);
  const float uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (const auto& t : uv) tcoords->InsertNextTuple2(t[0], t[1]);
  data->GetPointData()->SetTCoords(tcoords);
  data->Modified();
}

void set_coloured_polygons(vtkPolyData* data, const std::vector<std::vector<Vec3>>& polygons,
                           const std::vector<std::array<unsigned char, 4>>& colours) {
  std::vector<Vec3> points;
  for (const auto& polygon : polygons) points.insert(points.end(), polygon.begin(), polygon.end());
  set_points(data, points);
  vtkCellArray* cells = reset_cells(data, false);
  vtkIdType next = 0;
  for (const auto& polygon : polygons) {
    cells->InsertNextCell(vtkIdType(polygon.size()));
    for (size_t k = 0; k < polygon.size(); ++k) cells->InsertCellPoint(next++);
  }
  cells->Modified();
  auto scalars = vtkSmartPointer<vtkUnsignedCharArray>::New();
  scalars->SetNumberOfComponents(4);
  data->GetCellData()->SetScalars(scalars);
  set_cell_colours(data, colours);
}

void set_cell_colours(vtkPolyData* data, const std::vector<std::array<unsigned char, 4>>& colours) {
  auto* scalars = vtkUnsignedCharArray::SafeDownCast(data->GetCellData()->GetScalars());
  if (!scalars) return;
  scalars->SetNumberOfTuples(vtkIdType(colours.size()));
  for (size_t k = 0; k < colours.size(); ++k) {
    scalars->SetTypedTuple(vtkIdType(k), colours[k].data());
  }
  scalars->Modified();
  data->Modified();
}

void copy_frame_pixels(const Image& frame, vtkImageData* pixels, const RgbF& backdrop,
                       int reduction) {
  // The frame halved as often as the reduction asks (kept images: no allocation per frame).
  thread_local std::array<Image, 2> halves;
  const Image* reduced = &frame;
  for (int r = 1, k = 0; 2 * r <= reduction && reduced->width() > 1; r *= 2, k ^= 1) {
    halve_image(*reduced, halves[size_t(k)]);
    reduced = &halves[size_t(k)];
  }
  const Image& image = *reduced;
  const int width = image.width(), height = image.height();
  int* dims = pixels->GetDimensions();
  if (dims[0] != width || dims[1] != height || pixels->GetNumberOfScalarComponents() != 4 ||
      !pixels->GetPointData()->GetScalars()) {
    pixels->SetDimensions(width, height, 1);
    pixels->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
  }
  unsigned char* out = static_cast<unsigned char*>(pixels->GetScalarPointer());
  // Premultiplied: the colour plus what shows through (1 - alpha) of the backdrop. What shows
  // through depends on alpha alone, so it is tabled once per channel (the same products).
  std::array<std::array<double, 256>, 3> through;
  for (int c = 0; c < 3; ++c) {
    const double back = std::clamp(static_cast<double>(backdrop[c]), 0.0, 1.0);
    for (int alpha = 0; alpha < 256; ++alpha) through[c][alpha] = (255 - alpha) * back;
  }
  const auto over = [](unsigned char colour, double shown_through) {
    return static_cast<unsigned char>(std::min(255.0, colour + shown_through + 0.5));
  };
  // A pixel's four bytes r, g, b, a are the texel's (Pixel and the RGBA texel share their
  // layout), so an opaque pixel is copied as it is; an empty one takes the backdrop's texel.
  static_assert(sizeof(Pixel) == 4, "a pixel is four bytes r, g, b, a");
  const Pixel backdrop_texel{over(0, through[0][0]), over(0, through[1][0]), over(0, through[2][0]),
                             255};
  // Rows in bands on core's worker threads, each writing its own rows.
  for_each_band(height, 32, [&](int, int y0, int y1) {
    // Locals, as the byte stores below could alias anything the lambda reaches by reference.
    const int w = width;
    const Pixel empty = backdrop_texel;
    for (int y = y0; y < y1; ++y) {
      const Pixel* row = image.row(y);
      unsigned char* to = out + static_cast<std::size_t>(y) * w * 4;
      for (int x = 0; x < w; ++x, to += 4) {
        const Pixel p = row[x];
        Pixel texel;
        if (p.a == 255) {  // opaque: the colour itself (nothing shows through)
          texel = p;
        } else if ((p.a | p.r | p.g | p.b) == 0) {  // empty: the backdrop
          texel = empty;
        } else {
          texel = Pixel{over(p.r, through[0][p.a]), over(p.g, through[1][p.a]),
                        over(p.b, through[2][p.a]), 255};
        }
        std::memcpy(to, &texel, sizeof(texel));
      }
    }
  });
  pixels->Modified();
}

void copy_texture_pixels(const QImage& image, vtkImageData* pixels) {
  const QImage rgba = image.convertToFormat(QImage::Format_RGBA8888);
  pixels->SetDimensions(rgba.width(), rgba.height(), 1);
  pixels->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
  unsigned char* out = static_cast<unsigned char*>(pixels->GetScalarPointer());
  for (int y = 0; y < rgba.height(); ++y) {
    std::memcpy(out + size_t(y) * size_t(rgba.width()) * 4, rgba.constScanLine(y),
                size_t(rgba.width()) * 4);
  }
  pixels->Modified();
}

}  // namespace oflab
