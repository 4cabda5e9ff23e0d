// The geometry of the scene-shifting view's top-down diagram (manual/scene-shifting.md,
// dissertation chapter 3): what the desktop's view (gui/views/slices_view.h, painted with
// Qt) and the page's (web/slices_view.js, on a 2D canvas) draw, computed once here. No Qt.
//
// The diagram looks down on the viewer frame of the walk's first pose: depth Z (world
// units, along the viewing direction) runs left to right on a square-root scale from the eye
// to `max_depth`, lateral position X (world units) bottom to top within +-kDiagramHalfWidth.
// The slices and the asymptote k|V|/epsilon are core/scene_shifting/scene_shifting.h's.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"
#include "scene/viewer_script.h"
#include "scene_shifting/scene_shifting.h"

namespace oflab {

// Lateral extent of the diagram, world units either side of the viewing axis.
constexpr double kDiagramHalfWidth = 12.0;

// A scene plane seen from above: its depth and the lateral positions of its left and right
// edges (world units, viewer frame of the start pose).
struct DiagramPlane {
  double depth = 0.0, left = 0.0, right = 0.0;
};

// The depths the diagram's axis marks: 1, 2 and 5 times powers of ten from 1 up to
// `max_depth` (world units), increasing. Empty for max_depth < 1.
std::vector<double> depth_ticks(double max_depth);

// The scene's polygons seen from above from `start` (each polygon's centre in the viewer
// frame, its width along X), in the scene's order. The train-window scene's planes face the
// viewer, so their width runs along X.
std::vector<DiagramPlane> diagram_planes(const Scene& scene, const ViewerPose& start);

// The deepest depth the diagram shows: 50 world units, or 1.25 times the asymptote when that
// is deeper (so the asymptote and the background slice's start are always in the picture).
double diagram_max_depth(double asymptote);

// Where depth `z` lies across the diagram, 0 at the eye and 1 at `max_depth`: the square
// root of min(z, max_depth) / max_depth (z >= 0, max_depth > 0).
double diagram_depth_position(double z, double max_depth);

// Everything the diagram shows for one slicing: the slices (near before far, the last the
// background with far = +infinity), the asymptote, the planes, the depth range and ticks,
// and the slicing's inputs (focal length k in pixels, epsilon in pixels per frame, speed
// |V| in world units per frame).
struct SliceDiagram {
  std::vector<Slice> slices;
  double asymptote = 0.0;
  double max_depth = 50.0;
  std::vector<double> ticks;
  std::vector<DiagramPlane> planes;
  double focal_px = 0.0, epsilon_px = 0.0, speed = 0.0;
};
// The diagram of `slices` cut for k = focal_px, epsilon and speed over `planes`; the
// asymptote is core's slice_asymptote, k |V| / epsilon (NaN, and not drawn, for parameters
// core refuses: slice_parameters_problem).
SliceDiagram slice_diagram(const std::vector<Slice>& slices,
                           const std::vector<DiagramPlane>& planes, double focal_px,
                           double epsilon_px, double speed);

// The diagram's title: "N slices (N - 1 finite + background)".
std::string slice_diagram_title(const SliceDiagram& diagram);
// The asymptote's label: "asymptote Z = 12.34".
std::string asymptote_label(const SliceDiagram& diagram);

}  // namespace oflab
