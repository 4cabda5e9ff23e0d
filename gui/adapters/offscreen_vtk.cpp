#include "adapters/offscreen_vtk.h"

#include <vtkRenderWindow.h>
#include <vtkUnsignedCharArray.h>

#include <cstdint>
#include <cstring>

#include "report/charts.h"

namespace oflab {

std::string offscreen_vtk_problem() { return chart_display_problem(); }

vtkSmartPointer<vtkRenderWindow> make_offscreen_window() {
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  // The shared connection: a window that opened its own would abort the process if a busy X
  // server refused it.
  window->SetDisplayId(shared_x_display());
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  // The picture is read from the framebuffer VTK renders into (read_window_pixels reads the
  // back buffer), so the copy into the display framebuffer that swapping makes is not needed.
  window->SetSwapBuffers(0);
  return window;
}

void read_window_pixels(vtkRenderWindow* window, vtkUnsignedCharArray* scratch, QImage* into) {
  const int* size = window->GetSize();
  const int w = size[0], h = size[1];
  if (w <= 0 || h <= 0) {
    *into = QImage();
    return;
  }
  if (into->size() != QSize(w, h) || into->format() != QImage::Format_RGB32) {
    *into = QImage(w, h, QImage::Format_RGB32);
  }
  window->GetRGBACharPixelData(0, 0, w - 1, h - 1, 0, scratch);
  const unsigned char* in = scratch->GetPointer(0);
  // OpenGL's rows run bottom to top; RGB32 is 0xffRRGGBB per pixel.
  for (int y = 0; y < h; ++y) {
    const unsigned char* p = in + 4 * size_t(h - 1 - y) * size_t(w);
    auto* row = reinterpret_cast<QRgb*>(into->scanLine(y));
    for (int x = 0; x < w; ++x, p += 4) {
      // RGBA bytes as a little-endian word 0xAABBGGRR to 0xffRRGGBB (qRgb), a loop the
      // compiler vectorises.
      std::uint32_t rgba;
      std::memcpy(&rgba, p, sizeof(rgba));
      row[x] = 0xff000000u | ((rgba & 0xffu) << 16) | (rgba & 0xff00u) | ((rgba >> 16) & 0xffu);
    }
  }
}

}  // namespace oflab
