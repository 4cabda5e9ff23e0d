// Frame generation by extrapolation along motion vectors (core/scene/frame_generation.h).
#include "scene/frame_generation.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "image/push_pull.h"
#include "scene/splat_footprint.h"

namespace oflab {
namespace {

using splat::pixel_direction;
using splat::project;

// Every source pixel's splat: its moved footprint, its moved centre and extrapolated inverse
// depth; ok false when it has none.
struct Splat {
  std::array<Vec2, 4> corners;
  Vec2 centre;
  double w = 0.0;
  bool ok = false;
};

// Moves the top-left footprint corner of pixel (i, j) (top-left pixel position (i - 0.5,
// j - 0.5)) with the surface of plane vector m (0: the background) along its motion
// extrapolated `frames_ahead` frames: splat::move_lattice_rows' `move`.
struct CornerMove {
  const Camera& camera;
  const RigidStep3& back;
  int frames_ahead;
  double near;
  bool operator()(const Vec3& m, int i, int j, Vec2& q) const {
    double unused = 0.0;
    return extrapolate_point(camera, back, m, i - 0.5, j - 0.5, frames_ahead, near, q, unused);
  }
};

// Source pixel (i, j)'s splat: its moved centre, corners and extrapolated inverse depth.
Splat plan_splat(const DepthFrame& depth, const Camera& camera, const RigidStep3& back,
                 const splat::CornerLattice& lattice, int i, int j, int k, double near) {
  const int p = depth.polygon[static_cast<std::size_t>(j) * depth.width + i];
  Splat planned;
  planned.ok = extrapolate_point(camera, back, splat::surface_of(depth, p), i + 0.5, j + 0.5, k,
                                 near, planned.centre, planned.w) &&
               splat::move_footprint(lattice, depth, i, j, p, CornerMove{camera, back, k, near},
                                     planned.corners);
  return planned;
}

// What the painting keeps per target pixel.
struct Targets {
  std::vector<double> w;     // inverse depth of what each pixel shows; -1: nothing yet
  std::vector<double> dist;  // distance from its splat's centre
  std::vector<int> polygon;
};

// Paints source pixel s's splat: the nearest surface wins, and among one polygon's splats
// the one whose centre lands nearest. Returns the pixels written.
std::int64_t paint(const Splat& sp, std::size_t s, int polygon, Pixel colour, int width, int height,
                   Targets& t, GeneratedFrame& g) {
  splat::PixelBox box;
  if (!splat::footprint_box(sp.corners, width, height, box)) return 0;
  const std::array<Vec2, 4> edge = splat::footprint_edges(sp.corners);
  std::int64_t written = 0;
  for (int y = box.y_begin; y <= box.y_end; ++y) {
    for (int x = box.x_begin; x <= box.x_end; ++x) {
      const Vec2 c(x + 0.5, y + 0.5);
      if (!splat::inside_footprint(sp.corners, edge, c)) continue;
      const std::size_t d = static_cast<std::size_t>(y) * width + x;
      const bool same = g.source[d] >= 0 && t.polygon[d] == polygon;
      if (!same && sp.w <= t.w[d]) continue;
      const double e = glm::length(c - sp.centre);
      if (same && e >= t.dist[d]) continue;
      t.w[d] = sp.w;
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
  thread_local splat::CornerLattice lattice;
  thread_local Targets t;
  lattice.moved.resize(n);
  lattice.ok.resize(n);
  splat::move_lattice_rows(depth, 0, height, CornerMove{camera, back, k, near}, lattice);
  t.w.assign(n, -1.0);
  t.dist.assign(n, 0.0);
  t.polygon.assign(n, -1);
  // Each splat planned and painted in source order.
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      const Splat planned = plan_splat(depth, camera, back, lattice, i, j, k, near);
      if (!planned.ok) continue;
      const std::size_t s = static_cast<std::size_t>(j) * width + i;
      g.pixels_written +=
          paint(planned, s, depth.polygon[s], rendered.pixels()[s], width, height, t, g);
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
