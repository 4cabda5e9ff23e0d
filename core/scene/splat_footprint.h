// The footprints of forward splatting, shared by depth reprojection
// (core/scene/depth_reprojection.h) and frame generation (core/scene/frame_generation.h):
// a source pixel's footprint is its pixel square grown by kSplatMargin on every side, its
// corners moved with the surface the pixel shows, and the target pixel centres inside it take
// its colour. Internal to core/scene.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

#include "scene/depth_reprojection.h"

namespace oflab {
namespace splat {

// A footprint whose bounding box holds more pixel centres than this is dropped (its pixels stay
// unreached): only a surface seen nearly edge-on after the step can magnify a pixel so far.
constexpr double kMaxBoxPixels = 4096.0;

// The direction through top-left pixel position (u, v): (x/f, y/f, 1), x and y centred.
inline Vec3 pixel_direction(const Camera& camera, double u, double v) {
  return Vec3((u - camera.cx) / camera.focal_px, (v - camera.cy) / camera.focal_px, 1.0);
}

// Camera-frame point x (x.z > 0) projected to top-left pixels.
inline Vec2 project(const Camera& camera, const Vec3& x) {
  return Vec2(camera.cx + camera.focal_px * x.x / x.z, camera.cy + camera.focal_px * x.y / x.z);
}

// The plane vector of polygon p's surface; p < 0 (the background): 0, moved as a direction.
inline Vec3 surface_of(const DepthFrame& depth, int p) {
  return p >= 0 ? depth.planes[p] : Vec3(0.0);
}

// Each source pixel's top-left footprint corner moved with its own surface. A footprint's
// other corners are the top-left corners of the pixels two to the right and two below (the
// margin is half a pixel), taken from here when that pixel shows the same surface: the same
// computation, so the same bits.
struct CornerLattice {
  std::vector<Vec2> moved;
  std::vector<char> ok;  // 0: the corner could not be moved
};

static_assert(kSplatMargin == 0.5, "the corner lattice needs a margin of half a pixel");

// Fills lattice rows [begin, end) of `depth` (lattice sized width x height):
// move(m, u, v, q) moves top-left pixel position (u, v) with plane vector m (0: the
// background) into q, false when it cannot.
template <class Move>
void move_lattice_rows(const DepthFrame& depth, int begin, int end, const Move& move,
                       CornerLattice& lattice) {
  for (int j = begin; j < end; ++j) {
    for (int i = 0; i < depth.width; ++i) {
      const std::size_t k = static_cast<std::size_t>(j) * depth.width + i;
      lattice.ok[k] = move(surface_of(depth, depth.polygon[k]), i - 0.5, j - 0.5, lattice.moved[k]);
    }
  }
}

// The top-left footprint corner of pixel (i, j), i <= width + 1, j <= height + 1, moved with
// polygon p's surface (-1: the background): the lattice's when pixel (i, j) shows polygon p,
// else moved by `move` (as for move_lattice_rows). False when it cannot be moved.
template <class Move>
bool lattice_corner(const CornerLattice& lattice, const DepthFrame& depth, int i, int j, int p,
                    const Move& move, Vec2& q) {
  if (i < depth.width && j < depth.height) {
    const std::size_t k = static_cast<std::size_t>(j) * depth.width + i;
    if (depth.polygon[k] == p) {
      q = lattice.moved[k];
      return lattice.ok[k] != 0;
    }
  }
  return move(surface_of(depth, p), i - 0.5, j - 0.5, q);
}

// The footprint of source pixel (i, j) showing polygon p, grown by kSplatMargin, moved:
// corners at (i - 0.5, j - 0.5), (i + 1.5, j - 0.5), (i + 1.5, j + 1.5), (i - 0.5, j + 1.5).
// False when a corner cannot be moved.
template <class Move>
bool move_footprint(const CornerLattice& lattice, const DepthFrame& depth, int i, int j, int p,
                    const Move& move, std::array<Vec2, 4>& q) {
  static constexpr int di[4] = {0, 2, 2, 0}, dj[4] = {0, 0, 2, 2};
  for (int c = 0; c < 4; ++c) {
    if (!lattice_corner(lattice, depth, i + di[c], j + dj[c], p, move, q[c])) return false;
  }
  return true;
}

// The target pixels whose centres a footprint's bounding box holds, inclusive.
struct PixelBox {
  int x_begin = 0, x_end = -1, y_begin = 0, y_end = -1;
};

// The pixels of a width x height frame whose centres the bounding box of footprint q holds;
// false when there are none or more than kMaxBoxPixels.
inline bool footprint_box(const std::array<Vec2, 4>& q, int width, int height, PixelBox& box) {
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
  return !(pixels > kMaxBoxPixels);
}

// The edge vectors of footprint q, edge[e] = q[e + 1] - q[e] (cyclic).
inline std::array<Vec2, 4> footprint_edges(const std::array<Vec2, 4>& q) {
  std::array<Vec2, 4> edge;
  for (int e = 0; e < 4; ++e) edge[e] = q[(e + 1) % 4] - q[e];
  return edge;
}

// Whether point c lies in footprint q (edges `edge`, footprint_edges), its edges included
// (1e-9 px): c on the same side of all four edges, for either orientation.
inline bool inside_footprint(const std::array<Vec2, 4>& q, const std::array<Vec2, 4>& edge,
                             const Vec2& c) {
  bool positive = true, negative = true;
  for (int e = 0; e < 4; ++e) {
    const double k = edge[e].x * (c.y - q[e].y) - edge[e].y * (c.x - q[e].x);
    positive = positive && k >= -1e-9;
    negative = negative && k <= 1e-9;
  }
  return positive || negative;
}

}  // namespace splat
}  // namespace oflab
