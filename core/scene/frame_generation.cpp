// Frame generation by extrapolation along motion vectors (core/scene/frame_generation.h).
#include "scene/frame_generation.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "image/push_pull.h"

namespace oflab {
namespace {

// A footprint whose bounding box holds more pixel centres than this is dropped (its pixels
// stay unreached), as in depth reprojection.
constexpr double kMaxSplatBoxPixels = 4096.0;

Vec3 pixel_direction(const Camera& camera, double u, double v) {
  return Vec3((u - camera.cx) / camera.focal_px, (v - camera.cy) / camera.focal_px, 1.0);
}

Vec2 project(const Camera& camera, const Vec3& x) {
  return Vec2(camera.cx + camera.focal_px * x.x / x.z, camera.cy + camera.focal_px * x.y / x.z);
}

// Every source pixel's splat: its moved footprint, its moved centre and extrapolated inverse
// depth; ok false when it has none.
struct Splat {
  std::array<Vec2, 4> corners;
  Vec2 centre;
  double w = 0.0;
  bool ok = false;
};

// The footprint corners of pixel (i, j) on polygon p (-1: background) moved, the top-left
// corner lattice shared with the pixels that show the same surface.
struct Lattice {
  std::vector<Vec2> moved;
  std::vector<char> ok;
};

bool move_corner(const Camera& camera, const RigidStep3& back, const DepthFrame& depth,
                 const Lattice& lattice, int i, int j, int p, int k, double near, Vec2& q) {
  if (i < depth.width && j < depth.height) {
    const std::size_t s = static_cast<std::size_t>(j) * depth.width + i;
    if (depth.polygon[s] == p) {
      q = lattice.moved[s];
      return lattice.ok[s] != 0;
    }
  }
  const Vec3 m = p >= 0 ? depth.planes[p] : Vec3(0.0);
  double w = 0.0;
  return extrapolate_point(camera, back, m, i - 0.5, j - 0.5, k, near, q, w);
}

// The moved top-left corner of every source pixel, on its own surface.
void move_lattice(const DepthFrame& depth, const Camera& camera, const RigidStep3& back, int k,
                  double near, Lattice& lattice) {
  const int width = depth.width, height = depth.height;
  const std::size_t n = static_cast<std::size_t>(width) * height;
  lattice.moved.resize(n);
  lattice.ok.resize(n);
  double unused = 0.0;
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      const std::size_t s = static_cast<std::size_t>(j) * width + i;
      const int p = depth.polygon[s];
      lattice.ok[s] = extrapolate_point(camera, back, p >= 0 ? depth.planes[p] : Vec3(0.0), i - 0.5,
                                        j - 0.5, k, near, lattice.moved[s], unused);
    }
  }
}

// Source pixel (i, j)'s splat: its moved centre, corners and extrapolated inverse depth.
Splat plan_splat(const DepthFrame& depth, const Camera& camera, const RigidStep3& back,
                 const Lattice& lattice, int i, int j, int k, double near) {
  static constexpr int di[4] = {0, 2, 2, 0}, dj[4] = {0, 0, 2, 2};
  const int p = depth.polygon[static_cast<std::size_t>(j) * depth.width + i];
  Splat splat;
  splat.ok = extrapolate_point(camera, back, p >= 0 ? depth.planes[p] : Vec3(0.0), i + 0.5, j + 0.5,
                               k, near, splat.centre, splat.w);
  for (int c = 0; c < 4 && splat.ok; ++c) {
    splat.ok = move_corner(camera, back, depth, lattice, i + di[c], j + dj[c], p, k, near,
                           splat.corners[c]);
  }
  return splat;
}

// What the painting keeps per target pixel.
struct Targets {
  std::vector<double> w;     // inverse depth of what each pixel shows; -1: nothing yet
  std::vector<double> dist;  // distance from its splat's centre
  std::vector<int> polygon;
};

bool inside(const std::array<Vec2, 4>& q, const Vec2& c) {
  bool positive = true, negative = true;
  for (int e = 0; e < 4; ++e) {
    const Vec2 edge = q[(e + 1) % 4] - q[e];
    const double k = edge.x * (c.y - q[e].y) - edge.y * (c.x - q[e].x);
    positive = positive && k >= -1e-9;
    negative = negative && k <= 1e-9;
  }
  return positive || negative;
}

// Paints source pixel s's splat: the nearest surface wins, and among one polygon's splats
// the one whose centre lands nearest. Returns the pixels written.
std::int64_t paint(const Splat& splat, std::size_t s, int polygon, Pixel colour, int width,
                   int height, Targets& t, GeneratedFrame& g) {
  double x0 = splat.corners[0].x, x1 = x0, y0 = splat.corners[0].y, y1 = y0;
  for (const Vec2& c : splat.corners) {
    x0 = std::min(x0, c.x), x1 = std::max(x1, c.x);
    y0 = std::min(y0, c.y), y1 = std::max(y1, c.y);
  }
  const int xb = std::max(0, static_cast<int>(std::ceil(x0 - 0.5)));
  const int xe = std::min(width - 1, static_cast<int>(std::floor(x1 - 0.5)));
  const int yb = std::max(0, static_cast<int>(std::ceil(y0 - 0.5)));
  const int ye = std::min(height - 1, static_cast<int>(std::floor(y1 - 0.5)));
  if (xe < xb || ye < yb) return 0;
  if (static_cast<double>(xe - xb + 1) * (ye - yb + 1) > kMaxSplatBoxPixels) return 0;
  std::int64_t written = 0;
  for (int y = yb; y <= ye; ++y) {
    for (int x = xb; x <= xe; ++x) {
      const Vec2 c(x + 0.5, y + 0.5);
      if (!inside(splat.corners, c)) continue;
      const std::size_t d = static_cast<std::size_t>(y) * width + x;
      const bool same = g.source[d] >= 0 && t.polygon[d] == polygon;
      if (!same && splat.w <= t.w[d]) continue;
      const double e = glm::length(c - splat.centre);
      if (same && e >= t.dist[d]) continue;
      t.w[d] = splat.w;
      t.dist[d] = e;
      t.polygon[d] = polygon;
      g.image.pixels()[d] = colour;
      g.source[d] = static_cast<int>(s);
      ++written;
    }
  }
  return written;
}

// The mask: the unreached pixels grown by one pixel (3 x 3).
void build_mask(int width, int height, GeneratedFrame& g) {
  g.mask.assign(g.unreached.size(), 0);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      if (!g.unreached[static_cast<std::size_t>(y) * width + x]) continue;
      for (int v = std::max(0, y - 1); v <= std::min(height - 1, y + 1); ++v) {
        for (int u = std::max(0, x - 1); u <= std::min(width - 1, x + 1); ++u) {
          g.mask[static_cast<std::size_t>(v) * width + u] = 1;
        }
      }
    }
  }
  g.mask_pixels = std::count(g.mask.begin(), g.mask.end(), 1);
}

// The per-pixel displacement error against the true step (a diagnostic).
void measure_error(const DepthFrame& depth, const Camera& camera, const RigidStep3& truth,
                   GeneratedFrame& g) {
  double sum = 0.0;
  std::int64_t surfaces = 0;
  for (std::size_t d = 0; d < g.source.size(); ++d) {
    const int s = g.source[d];
    if (s < 0 || depth.polygon[s] < 0) continue;  // the background has no position error
    const int i = s % depth.width, j = s / depth.width;
    const Vec3 x =
        truth.rotation * (pixel_direction(camera, i + 0.5, j + 0.5) / depth.inverse_depth[s]) +
        truth.translation;
    if (!(x.z > 0.0)) continue;
    const Vec2 centre(static_cast<double>(d % depth.width) + 0.5,
                      static_cast<double>(d / depth.width) + 0.5);
    const double e = glm::length(centre - project(camera, x));
    g.max_error_px = std::max(g.max_error_px, e);
    sum += e;
    ++surfaces;
  }
  if (surfaces > 0) g.mean_error_px = sum / static_cast<double>(surfaces);
}

}  // namespace

bool extrapolate_point(const Camera& camera, const RigidStep3& back, const Vec3& m, double u,
                       double v, int frames_ahead, double near, Vec2& moved, double& moved_w) {
  const Vec3 d = pixel_direction(camera, u, v);
  const double k = frames_ahead;
  if (m == Vec3(0.0)) {  // the background: a direction
    const Vec3 before = back.rotation * d;
    if (!(before.z > 1e-9)) return false;
    const Vec2 p = project(camera, d), p_prev = project(camera, before);
    moved = p + k * (p - p_prev);
    moved_w = 0.0;
    return true;
  }
  const double w = glm::dot(m, d);
  if (!(w > 0.0) || !(1.0 / w > near)) return false;
  const Vec3 before = back.rotation * (d / w) + back.translation;
  if (!(before.z > near)) return false;
  const Vec2 p(u, v), p_prev = project(camera, before);
  moved = p + k * (p - p_prev);
  moved_w = w + k * (w - 1.0 / before.z);
  return moved_w > 0.0 && 1.0 / moved_w > near;
}

GeneratedFrame extrapolate_by_motion(const Image& rendered, const DepthFrame& depth,
                                     const Camera& camera, const RigidStep3& back, int frames_ahead,
                                     bool inpaint, double near) {
  const int width = camera.width, height = camera.height;
  const std::size_t n = static_cast<std::size_t>(width) * height;
  GeneratedFrame g;
  g.image = Image(width, height);
  g.source.assign(n, -1);
  g.source_pixels = static_cast<std::int64_t>(n);
  const int k = std::max(1, frames_ahead);
  // Working memory kept by each thread: a frame's buffers are tens of megabytes, and fresh
  // ones cost a page fault per page every frame.
  thread_local Lattice lattice;
  thread_local Targets t;
  move_lattice(depth, camera, back, k, near, lattice);
  t.w.assign(n, -1.0);
  t.dist.assign(n, 0.0);
  t.polygon.assign(n, -1);
  // Each splat planned and painted in source order.
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      const Splat splat = plan_splat(depth, camera, back, lattice, i, j, k, near);
      if (!splat.ok) continue;
      const std::size_t s = static_cast<std::size_t>(j) * width + i;
      g.pixels_written +=
          paint(splat, s, depth.polygon[s], rendered.pixels()[s], width, height, t, g);
    }
  }
  g.unreached.assign(n, 0);
  for (std::size_t d = 0; d < n; ++d) {
    if (g.source[d] >= 0) continue;
    g.unreached[d] = 1;
    ++g.hole_pixels;
  }
  build_mask(width, height, g);
  if (inpaint) g.inpainted_pixels = push_pull_inpaint(g.image, g.unreached);
  return g;
}

void measure_generated_frame(const DepthFrame& depth, const Camera& camera, const RigidStep3& truth,
                             const DepthFrame& now, GeneratedFrame& g) {
  g.hole_pixels = 0;
  for (std::size_t d = 0; d < g.unreached.size(); ++d) {
    g.hole_pixels += g.unreached[d] && now.polygon[d] >= 0;
  }
  g.max_error_px = 0.0;
  g.mean_error_px = 0.0;
  measure_error(depth, camera, truth, g);
}

}  // namespace oflab
