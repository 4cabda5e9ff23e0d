// Data ParaView opens: the flow field of a plane and the frames of an animation written with
// VTK's XML writers (vtkXMLImageDataWriter, vtkXMLPolyDataWriter), and time series of them as
// ParaView data collections (.pvd). `oflab-cli flow --vtk`, `oflab-cli animate --vtk-series`
// and the window's File > Export > ParaView data all write through this file
// (manual/paraview.md says which ParaView readers and filters show what).
//
// Frame: every point is in centred pixels, x right, y down, origin at the principal point
// (core/flow/camera.h), the convention of `oflab-cli flow --json`, with z = 0; so a probe in
// ParaView reads the coordinates the CLI uses. Flows are in pixels per unit time (per second
// in the window).
#pragma once

#include <string>
#include <vector>

#include "engine/animator.h"
#include "flow/camera.h"
#include "flow/flow_field.h"
#include "image/image.h"

namespace oflab {

// The flow grid's spacing unless told otherwise, pixels.
constexpr int kDefaultVtkGridStep = 4;

// The grid of a flow field: the centred points (i * step, j * step) for whole i, j, from the
// first multiple of `step` at or right of (below) the image's left (top) edge to the last at
// or left of (above) its right (bottom) edge; the principal point is one of them when it is
// inside the image. Sizes in points.
struct FlowGrid {
  double x0 = 0.0, y0 = 0.0;  // the first point, centred pixels
  int step = 1;               // pixels between neighbours
  int columns = 0, rows = 0;  // points along x and y
  long points() const { return static_cast<long>(columns) * rows; }
};
// The grid of `camera`'s image at `step` pixels. Precondition: a valid camera, step >= 1.
FlowGrid flow_grid(const Camera& camera, int step);

// "" when `step` is a grid step of limits::kVtkGridStep whose grid over `camera`'s image has
// at most limits::kVtkGridPoints points; otherwise one phrase naming the figure and the limit
// ("1 gives 8193 x 8193 = 67125249 grid points, more than 1048576; a step of 8 or more
// fits").
std::string flow_grid_problem(const Camera& camera, double step);

// The bytes of a .vti file (VTK XML image data, appended raw binary, zlib-compressed) of the
// planar flow `c` on flow_grid(camera, step). Point arrays, each a 3-vector (z = 0) in
// pixels per unit time unless said: "flow" (flow_at, the whole quadratic flow), "magnitude"
// (its length, a scalar), "translation", "first_order" and "second_order" (the flows of
// taylor_order_terms 0, 1 and 2 of taylor_terms(c), which add up to "flow"). The flow is the
// plane's wherever its image covers the point; the polynomial is written on the whole grid.
// Precondition: flow_grid_problem(camera, step) is empty. Coefficients about the principal
// point (c.origin = (0, 0)); throws std::invalid_argument otherwise.
std::string flow_field_vti(const Camera& camera, const PlanarFlowCoefficients& c, int step);

// What one frame of an animation shows, for the series: the frame's number, its camera, the
// displayed (engine's) image, the exact projection of the same frame (both camera-sized,
// premultiplied RGBA) and the outlines of the drawn layers (top-left pixels).
struct VtkFrame {
  int frame = 0;
  const Camera* camera = nullptr;
  const Image* shown = nullptr;
  const Image* exact = nullptr;
  std::vector<LayerOutline> layers;
};

// The bytes of a .vti of an image, one point per pixel centre (pixel (i, j) at centred
// (i + 0.5 - cx, j + 0.5 - cy)), with the point array "rgba" (4 unsigned bytes, straight
// alpha: ParaView shows them as colours with Map Scalars off). Precondition: the image has
// the camera's size (else std::invalid_argument).
std::string image_vti(const Camera& camera, const Image& image);

// The bytes of a .vti of the difference of two same-sized premultiplied images on the grid
// of image_vti: the point array "difference" (one unsigned byte, the largest of the four
// channels' absolute differences, 8-bit levels). Throws std::invalid_argument for images of
// different sizes or not the camera's.
std::string difference_vti(const Camera& camera, const Image& shown, const Image& exact);

// The bytes of a .vtp (VTK XML poly data) of the layers' outlines as polygons in centred
// pixels (z = 0), one cell per layer with the cell arrays "level" (the Level as a number,
// 0 none, 1 translate, 2 affine, 3 perspective, 4 re-render), "polygon" (the scene polygon)
// and "error_px" (the measured error, NaN where not measured).
std::string layers_vtp(const Camera& camera, const std::vector<LayerOutline>& layers);

// The bytes of a ParaView data collection (.pvd) of `files` (names relative to the .pvd)
// at the time steps `times` (same length; std::invalid_argument otherwise).
std::string pvd_collection(const std::vector<double>& times, const std::vector<std::string>& files);

// A time series for ParaView in a directory: each added frame writes
// frame_NNNNN_shown.vti, frame_NNNNN_exact.vti, frame_NNNNN_difference.vti and
// frame_NNNNN_layers.vtp into `dir`, and finish() writes shown.pvd, exact.pvd,
// difference.pvd and layers.pvd, one series each with the frame number as its time.
// Files are written with write_file_inside (formats/atomic_file.h): `dir` is an AtomicDir's
// path and `shown_dir` the directory as the user will find it, for messages. Keeps only the
// frame numbers between frames.
class VtkSeriesWriter {
 public:
  VtkSeriesWriter(std::string dir, std::string shown_dir);
  // Writes the frame's four files. Throws FileWriteError naming the file,
  // std::invalid_argument for images not of the camera's size.
  void add_frame(const VtkFrame& frame);
  // Writes the four .pvd files. Throws FileWriteError naming the file.
  void finish();
  int frames() const { return static_cast<int>(frames_.size()); }

 private:
  std::string dir_, shown_dir_;
  std::vector<int> frames_;
};

}  // namespace oflab
