// VTK pieces of the world view (gui/views/world_view.h): actors over poly data whose points,
// cells and pixels are replaced in place every frame, so the view builds its actors once and
// never rebuilds them. Points are world units in the view's world frame
// (session/display/world_geometry.h).
#pragma once

#include <vtkSmartPointer.h>

#include <QImage>
#include <array>
#include <string>
#include <vector>

#include "adapters/view_theme.h"
#include "flow/geometry.h"
#include "image/image.h"

class vtkActor;
class vtkImageData;
class vtkPolyData;
class vtkRenderer;

namespace oflab {

// An actor drawing one poly data (lines or polygons) in one colour.
struct PolyActor {
  vtkSmartPointer<vtkPolyData> data;
  vtkSmartPointer<vtkActor> actor;
};

// Makes an empty PolyActor coloured `colour` and adds it to `renderer`.
PolyActor add_poly_actor(vtkRenderer* renderer, const RgbF& colour);

// Replaces the lines of `data`: `points` joined in order (closed: back to the first) as
// one polyline; fewer than two points draw nothing. Reuses the points' storage.
void set_polyline(vtkPolyData* data, const std::vector<Vec3>& points, bool closed);

// Replaces the lines of `data` by separate segments, from[k] to to[k] (same lengths).
void set_segments(vtkPolyData* data, const std::vector<Vec3>& from, const std::vector<Vec3>& to);

// Makes `data` one quadrilateral with texture coordinates: corners in the order top-left,
// top-right, bottom-right, bottom-left of a texture whose first row is its top (texture
// coordinates (0,0), (1,0), (1,1), (0,1)); moving the quad later replaces only its points.
void set_textured_quad(vtkPolyData* data, const std::array<Vec3, 4>& corners);

// Replaces the polygons of `data` by `polygons` (one cell each) with one RGBA colour per
// cell (`colours`, same length), drawn directly.
void set_coloured_polygons(vtkPolyData* data, const std::vector<std::vector<Vec3>>& polygons,
                           const std::vector<std::array<unsigned char, 4>>& colours);
// Replaces only the cell colours of `data` (same cell count as before).
void set_cell_colours(vtkPolyData* data, const std::vector<std::array<unsigned char, 4>>& colours);

// Copies a premultiplied core image into `pixels` as opaque RGBA (alpha 255 everywhere) over
// `backdrop` (0..1 per channel; what shows where nothing was drawn), row 0 first (the top of
// the image is texture coordinate 0), reusing its storage when the size is unchanged. Four
// components, so that an opaque pixel is copied whole and OpenGL takes the texels as they are.
// With `reduction` (a power of two r > 1) the image is first halved log2(r) times as the mip
// pyramid's levels are made (halve_image, core/image/mip_pyramid.h: each pixel the rounded
// mean of 2 x 2, premultiplied, a tap beyond an odd edge clamped; stopping at 1 pixel across),
// and that level is copied: about ceil(w / r) x ceil(h / r) texels.
void copy_frame_pixels(const Image& image, vtkImageData* pixels, const RgbF& backdrop,
                       int reduction = 1);
// Copies a QImage into `pixels` as RGBA, row 0 first.
void copy_texture_pixels(const QImage& image, vtkImageData* pixels);

// The colour as VTK's three doubles.
inline std::array<double, 3> vtk_colour(const RgbF& c) { return {c[0], c[1], c[2]}; }

}  // namespace oflab
