// VTK drawn without an OpenGL widget: a render window that renders offscreen (into its own
// framebuffer object on the process's shared X connection, analysis/report/charts.h) and
// whose picture is read back into a QImage that a plain widget paints like any other view.
// A window that holds no OpenGL widget is composed by Qt without OpenGL, so the other views
// keep their speed, and VTK's frame costs only its own rasterising and one read-back.
#pragma once

#include <vtkSmartPointer.h>

#include <QImage>
#include <QSize>
#include <string>

class vtkRenderWindow;
class vtkUnsignedCharArray;

namespace oflab {

// Empty when offscreen VTK windows can be made here; otherwise why not (no X display).
std::string offscreen_vtk_problem();

// A render window that renders offscreen, without multisampling (on software OpenGL it
// would cost most of the frame), on the shared X connection. Precondition:
// offscreen_vtk_problem() is empty. No OpenGL context exists before the first Render.
vtkSmartPointer<vtkRenderWindow> make_offscreen_window();

// Copies what `window` rendered last (its whole size, device pixels) into `into` as opaque
// Format_RGB32, top row first, reusing `into`'s storage when its size and format already
// match and it is not shared. `scratch` holds the read-back between calls (any array).
void read_window_pixels(vtkRenderWindow* window, vtkUnsignedCharArray* scratch, QImage* into);

}  // namespace oflab
