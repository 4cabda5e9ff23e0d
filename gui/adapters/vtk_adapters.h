// Small adapters from core and Qt types to VTK objects, shared by the views.
//
// The flow view draws in the viewer frame of core/flow/camera.h (X right, Y down, Z forward,
// eye at the origin). Image-plane overlays lie on the plane Z = 1, where the centred pixel
// (x, y) is the point (x / f, y / f, 1): a VTK camera at the eye with the focal length's
// view angle shows them exactly where core's projection puts them.
#pragma once

#include <vtkImageData.h>
#include <vtkLookupTable.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <QImage>
#include <functional>
#include <vector>

#include "flow/camera.h"
#include "views/palette.h"
#include "views/view_theme.h"

class vtkProperty;
class vtkRenderWindow;
class vtkTextProperty;

namespace oflab {

// The point of the image plane Z = 1 at centred pixel p.
Vec3 image_plane_point(const Camera& camera, const Vec2& p);

// An RGBA vtkImageData holding the image, rows flipped so that VTK's row 0 (bottom) is
// the image's last row. Texture coordinate (0, 1) is then the image's top-left corner.
vtkSmartPointer<vtkImageData> image_data_from_qimage(const QImage& image);

// Polylines (each at least two points) as one vtkPolyData.
vtkSmartPointer<vtkPolyData> polylines(const std::vector<std::vector<Vec3>>& lines);

// A closed polygon outline through the points.
vtkSmartPointer<vtkPolyData> closed_outline(const std::vector<Vec3>& points);

// A filled disc of radius `radius` about the origin of the plane Z = 0 whose vertices
// (x, y, 0) are coloured by colour_at((x, y)): used for the colour-wheel legend.
vtkSmartPointer<vtkPolyData> coloured_disc(double radius,
                                           const std::function<Rgb8(const Vec2&)>& colour_at);

// A 256-entry lookup table over [0, max_value] (max_value > 0) using magnitude_colour from
// 0 to `top` (<= 1; below 1 drops the palest yellows, for light backgrounds).
vtkSmartPointer<vtkLookupTable> magnitude_lookup_table(double max_value, double top = 1.0);

RgbF rgb(const Rgb8& colour);
void set_line_style(vtkProperty* property, const RgbF& colour, double width);
void set_text_style(vtkTextProperty* property, const RgbF& colour, int font_size);
// Screen pixels of a VTK font size: VTK draws `points` points at the window's DPI (72 DPI
// makes a point one pixel).
double font_points_to_px(int points, vtkRenderWindow* window);

}  // namespace oflab
