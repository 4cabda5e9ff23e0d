#include "display/slice_diagram.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace oflab {

std::vector<double> depth_ticks(double max_depth) {
  std::vector<double> ticks;
  for (double decade = 1.0; decade <= max_depth; decade *= 10.0) {
    for (double step : {1.0, 2.0, 5.0}) {
      if (step * decade <= max_depth) ticks.push_back(step * decade);
    }
  }
  return ticks;
}

std::vector<DiagramPlane> diagram_planes(const Scene& scene, const ViewerPose& start) {
  std::vector<DiagramPlane> planes;
  for (const ScenePolygon& polygon : scene.polygons) {
    const Vec3 c = to_view(start, polygon.centre);
    planes.push_back({c.z, c.x - 0.5 * polygon.size.x, c.x + 0.5 * polygon.size.x});
  }
  return planes;
}

double diagram_max_depth(double asymptote) {
  return std::isfinite(asymptote) ? std::max(50.0, 1.25 * asymptote) : 50.0;
}

double diagram_depth_position(double z, double max_depth) {
  return std::sqrt(std::clamp(z, 0.0, max_depth) / max_depth);
}

SliceDiagram slice_diagram(const std::vector<Slice>& slices,
                           const std::vector<DiagramPlane>& planes, double focal_px,
                           double epsilon_px, double speed) {
  SliceDiagram d;
  d.slices = slices;
  d.planes = planes;
  d.focal_px = focal_px;
  d.epsilon_px = epsilon_px;
  d.speed = speed;
  SliceParameters p;
  p.speed = speed;
  p.focal_px = focal_px;
  p.epsilon_px = epsilon_px;
  // k|V|/epsilon (eq. 9 corrected); parameters core refuses have no asymptote to draw.
  try {
    d.asymptote = slice_asymptote(p);
  } catch (const std::invalid_argument&) {
    d.asymptote = std::nan("");
  }
  d.max_depth = diagram_max_depth(d.asymptote);
  d.ticks = depth_ticks(d.max_depth);
  return d;
}

std::string slice_diagram_title(const SliceDiagram& diagram) {
  const size_t n = diagram.slices.size();
  return std::to_string(n) + " slices (" + std::to_string(n == 0 ? 0 : n - 1) +
         " finite + background)";
}

std::string asymptote_label(const SliceDiagram& diagram) {
  char text[64];
  std::snprintf(text, sizeof text, "asymptote Z = %.2f", diagram.asymptote);
  return text;
}

}  // namespace oflab
