// The panels' framing (panel_framing.h).
#include "display/panel_framing.h"

#include <algorithm>

#include "image/scan_conversion.h"
#include "scene/view_culling.h"
#include "state/window_state.h"  // kFramingFrames

namespace oflab {
namespace {

// `box` grown to hold `p`, or the point itself for none.
void include(std::optional<BoundingBox>& box, const Vec2& p) {
  if (!box) {
    box = BoundingBox{p.x, p.y, p.x, p.y};
    return;
  }
  box->x_min = std::min(box->x_min, p.x);
  box->y_min = std::min(box->y_min, p.y);
  box->x_max = std::max(box->x_max, p.x);
  box->y_max = std::max(box->y_max, p.y);
}

}  // namespace

FrameBounds script_frame_bounds(const MotionScript& script, double near) {
  FrameBounds bounds;
  for (const ScriptFrame& frame : script.frames) {
    const ConvexPolygon seen = plane_image_polygon(script.camera, frame.pose, near);
    bounds.push_back(seen.empty() ? std::nullopt : std::optional<BoundingBox>(seen.bounds()));
  }
  return bounds;
}

FrameBounds scene_frame_bounds(const Scene& scene, const ViewerScript& walk, double near) {
  FrameBounds bounds;
  for (const ViewerFrame& frame : walk.frames) {
    std::optional<BoundingBox> seen;
    for (const std::vector<Vec2>& outline : exact_outlines(scene, frame.pose, walk.camera, near)) {
      for (const Vec2& p : outline) include(seen, p);
    }
    bounds.push_back(seen);
  }
  return bounds;
}

std::optional<BoundingBox> bounds_around(const FrameBounds& bounds, int frame, int reach) {
  const int n = static_cast<int>(bounds.size());
  const int first = reach < 0 ? 0 : std::max(0, frame - reach);
  const int last = reach < 0 ? n - 1 : std::min(n - 1, frame + reach);
  std::optional<BoundingBox> around;
  for (int k = first; k <= last; ++k) {
    const std::optional<BoundingBox>& b = bounds[static_cast<std::size_t>(k)];
    if (!b) continue;
    include(around, {b->x_min, b->y_min});
    include(around, {b->x_max, b->y_max});
  }
  return around;
}

std::optional<BoundingBox> framed_content(const FrameBounds& bounds, int frame, bool around_frame) {
  if (around_frame) {
    const std::optional<BoundingBox> around = bounds_around(bounds, frame, kFramingFrames);
    if (around) return around;
  }
  return bounds_around(bounds, 0, -1);
}

BoundingBox panel_frame(const std::optional<BoundingBox>& content, double camera_width,
                        double camera_height, double aspect, double zoom) {
  BoundingBox frame = content ? *content : BoundingBox{0.0, 0.0, camera_width, camera_height};
  const double mx = kFitMargin * (frame.x_max - frame.x_min);
  const double my = kFitMargin * (frame.y_max - frame.y_min);
  frame = {frame.x_min - mx, frame.y_min - my, frame.x_max + mx, frame.y_max + my};
  const double cx = 0.5 * (frame.x_min + frame.x_max), cy = 0.5 * (frame.y_min + frame.y_max);
  double w = frame.x_max - frame.x_min, h = frame.y_max - frame.y_min;
  if (w / h < aspect) {
    w = h * aspect;
  } else {
    h = w / aspect;
  }
  w /= zoom;
  h /= zoom;
  return {cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2};
}

double hugging_aspect(double cell_aspect, const std::optional<BoundingBox>& content, double zoom) {
  if (!content || zoom > 1.0) return cell_aspect;
  const double w = content->x_max - content->x_min, h = content->y_max - content->y_min;
  if (!(w > 0.0 && h > 0.0)) return cell_aspect;
  return std::clamp(w / h, 1.0 / kHugAspect, kHugAspect);
}

double outline_fill(const std::vector<std::vector<Vec2>>& outlines, const BoundingBox& shown) {
  const double w = shown.x_max - shown.x_min, h = shown.y_max - shown.y_min;
  if (!(w > 0.0 && h > 0.0)) return 0.0;
  const int columns = kFillGrid;
  const int rows = std::max(1, static_cast<int>(kFillGrid * h / w));
  const double scale = columns / w;  // cells per camera pixel, the same both ways
  std::vector<char> covered(static_cast<std::size_t>(columns) * rows, 0);
  for (const std::vector<Vec2>& outline : outlines) {
    std::vector<Vec2> cells;
    for (const Vec2& p : outline)
      cells.push_back({(p.x - shown.x_min) * scale, (p.y - shown.y_min) * scale});
    const ConvexPolygon polygon = make_polygon_unchecked(std::move(cells));
    if (polygon.empty()) continue;
    ScanConverter scan(polygon, columns, rows);
    PixelSpan span;
    while (scan.next(span)) {
      char* row = covered.data() + static_cast<std::size_t>(span.y) * columns;
      for (int x = span.x_begin; x < span.x_end; ++x) row[x] = 1;
    }
  }
  std::size_t count = 0;
  for (const char c : covered) count += c;
  return static_cast<double>(count) / static_cast<double>(covered.size());
}

std::vector<std::vector<Vec2>> exact_outlines(const Scene& scene, const ViewerPose& view,
                                              const Camera& camera, double near) {
  std::vector<std::vector<Vec2>> outlines;
  const ViewFrustum frustum = view_frustum(camera, near, 0.0);
  for (const ScenePolygon& polygon : scene.polygons) {
    const Vec3 front = direction_to_view(view, polygon.front);
    const Vec3 centre = to_view(view, polygon.centre);
    // As the engines cull (core/scene/scene_animator.cpp): a two-sided sheet only edge-on.
    if (is_back_facing(front, centre) && (!polygon.two_sided || is_back_facing(-front, centre))) {
      continue;
    }
    ViewPolygon seen;
    seen.uv = polygon_outline(polygon);
    for (const Vec3& p : polygon_vertices(polygon)) seen.points.push_back(to_view(view, p));
    clip_to_frustum_in_place(seen, frustum);
    if (seen.empty()) continue;
    outlines.push_back(project_to_pixels(camera, seen).vertices());
  }
  return outlines;
}

}  // namespace oflab
