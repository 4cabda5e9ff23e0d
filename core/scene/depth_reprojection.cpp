// Per-pixel depth reprojection and the automatic stabilization plane
// (core/scene/depth_reprojection.h).
#include "scene/depth_reprojection.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "image/scan_conversion.h"
#include "scene/view_culling.h"

namespace oflab {
namespace {

// A footprint whose bounding box holds more pixel centres than this is dropped (its pixels
// stay holes): only a surface seen nearly edge-on after the step can magnify a pixel so far.
constexpr double kMaxSplatBoxPixels = 4096.0;

// The direction through top-left pixel position (u, v): (x/f, y/f, 1), x, y centred.
Vec3 pixel_direction(const Camera& camera, double u, double v) {
  return Vec3((u - camera.cx) / camera.focal_px, (v - camera.cy) / camera.focal_px, 1.0);
}

// Where the point seen at (u, v) with plane vector m lands after the step, top-left pixels,
// and its inverse depth there; false when it is behind the surface's horizon or reaches
// Z <= near. m = 0 (the background) moves as a direction.
bool move_point(const Camera& camera, const RigidStep3& step, const Vec3& m, double w, double u,
                double v, double near, Vec2& moved, double& moved_w) {
  const Vec3 d = pixel_direction(camera, u, v);
  Vec3 x;
  if (m == Vec3(0.0)) {
    x = step.rotation * d;
    if (!(x.z > 1e-9)) return false;
    moved_w = 0.0;
  } else {
    if (!(w > 0.0)) return false;
    x = step.rotation * (d / w) + step.translation;
    if (!(x.z > near)) return false;
    moved_w = 1.0 / x.z;
  }
  moved = Vec2(camera.cx + camera.focal_px * x.x / x.z, camera.cy + camera.focal_px * x.y / x.z);
  return true;
}

double cross(const Vec2& a, const Vec2& b, const Vec2& p) {
  return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

// What the splats of one reprojection keep per target pixel, and where each source pixel's
// centre lands.
struct SplatBuffers {
  explicit SplatBuffers(std::size_t n) : z(n, -1.0), dist(n, 0.0), exact(n) {}
  std::vector<double> z;     // inverse depth of what each pixel shows; -1: nothing yet
  std::vector<double> dist;  // distance from its splat's centre
  std::vector<Vec2> exact;   // where each source pixel centre lands now
};

// The target pixels whose centres a footprint's bounding box holds, inclusive.
struct PixelBox {
  int x_begin = 0, x_end = -1, y_begin = 0, y_end = -1;
};

// One source pixel's splat: its footprint after the step, the pixels it may cover, the source
// pixel and polygon (-1: background), its centre's inverse depth after the step and colour.
struct Splat {
  std::array<Vec2, 4> corners;
  PixelBox box;
  int source = 0;
  int polygon = -1;
  double centre_w = 0.0;
  Pixel colour;
};

// The footprint of source pixel (i, j), grown by kSplatMargin, after the step: each corner
// moved by the depth of its surface there (`surface`: m is the polygon's plane; else the
// background, moved as a direction). False when a corner cannot be moved (move_point).
bool move_footprint(const Camera& camera, const RigidStep3& step, const Vec3& m, bool surface,
                    int i, int j, double near, std::array<Vec2, 4>& q) {
  const double lo = -kSplatMargin, hi = 1.0 + kSplatMargin;
  const std::array<Vec2, 4> corners{Vec2(i + lo, j + lo), Vec2(i + hi, j + lo),
                                    Vec2(i + hi, j + hi), Vec2(i + lo, j + hi)};
  bool ok = true;
  for (int c = 0; c < 4 && ok; ++c) {
    double w_unused = 0.0;
    const double w =
        surface ? glm::dot(m, pixel_direction(camera, corners[c].x, corners[c].y)) : 0.0;
    ok = move_point(camera, step, m, w, corners[c].x, corners[c].y, near, q[c], w_unused);
  }
  return ok;
}

// The pixels of a width x height frame whose centres the bounding box of footprint `q` holds;
// false when there are none or more than kMaxSplatBoxPixels.
bool footprint_box(const std::array<Vec2, 4>& q, int width, int height, PixelBox& box) {
  double x0 = q[0].x, x1 = q[0].x, y0 = q[0].y, y1 = q[0].y;
  for (const Vec2& c : q) {
    x0 = std::min(x0, c.x), x1 = std::max(x1, c.x);
    y0 = std::min(y0, c.y), y1 = std::max(y1, c.y);
  }
  box.x_begin = std::max(0, static_cast<int>(std::ceil(x0 - 0.5)));
  box.x_end = std::min(width - 1, static_cast<int>(std::floor(x1 - 0.5)));
  box.y_begin = std::max(0, static_cast<int>(std::ceil(y0 - 0.5)));
  box.y_end = std::min(height - 1, static_cast<int>(std::floor(y1 - 0.5)));
  if (box.x_end < box.x_begin || box.y_end < box.y_begin) return false;
  const double pixels =
      static_cast<double>(box.x_end - box.x_begin + 1) * (box.y_end - box.y_begin + 1);
  return !(pixels > kMaxSplatBoxPixels);
}

// True when point c lies inside the convex footprint q, edges included, whichever its
// orientation.
bool inside_footprint(const std::array<Vec2, 4>& q, const Vec2& c) {
  bool positive = true, negative = true;
  for (int e = 0; e < 4; ++e) {
    const double k = cross(q[e], q[(e + 1) % 4], c);
    positive = positive && k >= -1e-9;
    negative = negative && k <= 1e-9;
  }
  return positive || negative;
}

// Paints `splat` into r.image at every pixel centre inside its footprint where it wins: the
// nearest surface, and among the splats of one polygon the one whose centre lands nearest.
void paint_splat(const Splat& splat, const DepthFrame& depth, int width, SplatBuffers& buffers,
                 Reprojection& r) {
  const Vec2 landed = buffers.exact[static_cast<std::size_t>(splat.source)];
  for (int y = splat.box.y_begin; y <= splat.box.y_end; ++y) {
    for (int x = splat.box.x_begin; x <= splat.box.x_end; ++x) {
      const Vec2 c(x + 0.5, y + 0.5);
      if (!inside_footprint(splat.corners, c)) continue;
      const std::size_t d = static_cast<std::size_t>(y) * width + x;
      const double e = glm::length(c - landed);
      if (r.source[d] >= 0 && depth.polygon[r.source[d]] == splat.polygon) {
        if (e >= buffers.dist[d]) continue;  // a splat of the same surface lands nearer
      } else if (splat.centre_w <= buffers.z[d]) {
        continue;  // something nearer (or the same) is there
      }
      buffers.z[d] = splat.centre_w;
      buffers.dist[d] = e;
      r.image.at(x, y) = splat.colour;
      r.source[d] = splat.source;
      ++r.pixels_written;
    }
  }
}

// The unreached pixels and holes of r (see reproject_by_depth's `now`) and the per-pixel
// displacement error of the pixels showing a surface.
void measure_unreached(const DepthFrame& depth, const SplatBuffers& buffers, const DepthFrame* now,
                       int width, Reprojection& r) {
  const std::size_t n = r.source.size();
  r.unreached.assign(n, 0);
  r.hole.assign(n, 0);
  double error_sum = 0.0;
  std::int64_t surfaces = 0;
  for (std::size_t d = 0; d < n; ++d) {
    if (r.source[d] < 0) {
      r.unreached[d] = 1;
      if (!now || now->polygon[d] >= 0) {
        r.hole[d] = 1;
        ++r.hole_pixels;
      }
      continue;
    }
    if (depth.polygon[r.source[d]] < 0) continue;  // the background has no position error
    const Vec2 centre(static_cast<double>(d % width) + 0.5, static_cast<double>(d / width) + 0.5);
    const double e = glm::length(centre - buffers.exact[r.source[d]]);
    r.max_error_px = std::max(r.max_error_px, e);
    error_sum += e;
    ++surfaces;
  }
  if (surfaces > 0) r.mean_error_px = error_sum / static_cast<double>(surfaces);
}

// HoleFill::kStretch: each unreached pixel takes the farther (smaller inverse depth z) of the
// nearest reached pixels left and right of it on its row, or the one there is.
void stretch_into_holes(const std::vector<double>& z, int width, int height, Reprojection& r) {
  for (int y = 0; y < height; ++y) {
    const std::size_t row = static_cast<std::size_t>(y) * width;
    for (int x = 0; x < width; ++x) {
      if (!r.unreached[row + x]) continue;
      int left = x - 1, right = x + 1;
      while (left >= 0 && r.unreached[row + left]) --left;
      while (right < width && r.unreached[row + right]) ++right;
      int from = -1;
      if (left >= 0 && right < width) {
        from = z[row + left] <= z[row + right] ? left : right;  // the farther one
      } else if (left >= 0) {
        from = left;
      } else if (right < width) {
        from = right;
      }
      if (from >= 0) r.image.pixels()[row + x] = r.image.pixels()[row + from];
    }
  }
}
}  // namespace

int DepthFrame::covered() const {
  return static_cast<int>(
      std::count_if(polygon.begin(), polygon.end(), [](int p) { return p >= 0; }));
}

DepthFrame render_depth(const Scene& scene, const Camera& camera, const ViewerPose& view,
                        double near) {
  DepthFrame depth;
  depth.width = camera.width;
  depth.height = camera.height;
  const std::size_t n = static_cast<std::size_t>(camera.width) * camera.height;
  depth.inverse_depth.assign(n, 0.0);
  depth.polygon.assign(n, -1);
  depth.planes.assign(scene.polygons.size(), Vec3(0.0));
  const ViewFrustum frustum = view_frustum(camera, near, 1.0);
  for (std::size_t i = 0; i < scene.polygons.size(); ++i) {
    const ScenePolygon& polygon = scene.polygons[i];
    const Vec3 front = direction_to_view(view, polygon.front);
    const Vec3 centre = to_view(view, polygon.centre);
    if (is_back_facing(front, centre)) continue;
    ViewPolygon clipped;
    for (const Vec3& v : polygon_vertices(polygon)) clipped.points.push_back(to_view(view, v));
    clipped.uv = polygon_outline(polygon);
    clipped = clip_to_frustum(clipped, frustum);
    if (clipped.empty()) continue;
    const Vec3 m = plane_vector_of(centre, front);
    depth.planes[i] = m;
    const ConvexPolygon region = project_to_pixels(camera, clipped);
    ScanConverter rows(region, camera.width, camera.height);
    PixelSpan span;
    while (rows.next(span)) {
      for (int x = span.x_begin; x < span.x_end; ++x) {
        const std::size_t k = static_cast<std::size_t>(span.y) * camera.width + x;
        const double w = glm::dot(m, pixel_direction(camera, x + 0.5, span.y + 0.5));
        if (w > depth.inverse_depth[k]) {
          depth.inverse_depth[k] = w;
          depth.polygon[k] = static_cast<int>(i);
        }
      }
    }
  }
  return depth;
}

RigidStep3 viewer_step(const ViewerPose& from, const ViewerPose& to) {
  RigidStep3 step;
  step.rotation = to.rotation * glm::transpose(from.rotation);
  step.translation = to.translation - step.rotation * from.translation;
  return step;
}

bool fit_inverse_depth_plane(const DepthFrame& depth, const Camera& camera, Vec3& m) {
  // Normal equations of the least-squares fit, accumulated in double.
  Mat3 a(0.0);
  Vec3 b(0.0);
  int count = 0;
  for (int y = 0; y < depth.height; ++y) {
    for (int x = 0; x < depth.width; ++x) {
      const std::size_t k = static_cast<std::size_t>(y) * depth.width + x;
      if (depth.polygon[k] < 0) continue;
      const Vec3 d = pixel_direction(camera, x + 0.5, y + 0.5);
      a += glm::outerProduct(d, d);
      b += d * depth.inverse_depth[k];
      ++count;
    }
  }
  if (count < 3) return false;
  // Singular when the covered pixels lie on one line of the image.
  const double scale = (a[0][0] + a[1][1] + a[2][2]) / 3.0;
  if (!(std::abs(glm::determinant(a)) > 1e-12 * scale * scale * scale)) return false;
  m = glm::inverse(a) * b;
  return true;
}

const char* hole_fill_name(HoleFill fill) {
  switch (fill) {
    case HoleFill::kNone:
      return "none";
    case HoleFill::kStretch:
      return "stretch";
    case HoleFill::kBackground:
      return "background";
  }
  return "none";
}

bool parse_hole_fill(const std::string& name, HoleFill& fill) {
  for (int i = 0; i < kHoleFillCount; ++i) {
    if (name == hole_fill_name(static_cast<HoleFill>(i))) {
      fill = static_cast<HoleFill>(i);
      return true;
    }
  }
  return false;
}

std::string hole_fill_name_list(const std::string& separator) {
  std::string names;
  for (int i = 0; i < kHoleFillCount; ++i) {
    names += (i ? separator : "") + std::string(hole_fill_name(static_cast<HoleFill>(i)));
  }
  return names;
}

Reprojection reproject_by_depth(const Image& rendered, const DepthFrame& depth,
                                const Camera& camera, const RigidStep3& step, HoleFill fill,
                                double near, const DepthFrame* now) {
  const int width = camera.width, height = camera.height;
  const std::size_t n = static_cast<std::size_t>(width) * height;
  Reprojection r;
  r.image = Image(width, height);
  r.source.assign(n, -1);
  SplatBuffers buffers(n);
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      const std::size_t s = static_cast<std::size_t>(j) * width + i;
      ++r.source_pixels;
      const int p = depth.polygon[s];
      const Vec3 m = p >= 0 ? depth.planes[p] : Vec3(0.0);
      // The centre moves by the pixel's own depth; the footprint's corners by the depth of
      // its surface there.
      double centre_w = 0.0;
      if (!move_point(camera, step, m, depth.inverse_depth[s], i + 0.5, j + 0.5, near,
                      buffers.exact[s], centre_w)) {
        continue;
      }
      std::array<Vec2, 4> q;
      PixelBox box;
      if (!move_footprint(camera, step, m, p >= 0, i, j, near, q) ||
          !footprint_box(q, width, height, box)) {
        continue;
      }
      const Splat splat{q, box, static_cast<int>(s), p, centre_w, rendered.at(i, j)};
      paint_splat(splat, depth, width, buffers, r);
    }
  }
  measure_unreached(depth, buffers, now, width, r);
  if (fill == HoleFill::kBackground) {
    for (std::size_t d = 0; d < n; ++d) {
      if (r.unreached[d]) r.image.pixels()[d] = kHoleBackground;
    }
  } else if (fill == HoleFill::kStretch) {
    stretch_into_holes(buffers.z, width, height, r);
  }
  return r;
}

}  // namespace oflab
