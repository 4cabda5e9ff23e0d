// Textured depth meshes (core/scene/depth_mesh.h; after Sillion, Drettakis and Bodelet,
// Eurographics 97).
#include "scene/depth_mesh.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "flow/limits.h"
#include "image/composite.h"
#include "image/thread_pool.h"
#include "scene/splat_footprint.h"

namespace oflab {
namespace {

using splat::pixel_direction;

// The vertex at pixel corner (x, y): the nearest surface among the pixels touching it.
void lift_vertex(const DepthFrame& depth, const Camera& camera, int x, int y, DepthMesh& mesh) {
  const Vec3 direction = pixel_direction(camera, x, y);
  double best = 0.0;
  for (int j = y - 1; j <= y; ++j) {
    for (int i = x - 1; i <= x; ++i) {
      if (i < 0 || j < 0 || i >= depth.width || j >= depth.height) continue;
      const int p = depth.polygon[static_cast<std::size_t>(j) * depth.width + i];
      if (p < 0) continue;
      best = std::max(best, glm::dot(depth.planes[static_cast<std::size_t>(p)], direction));
    }
  }
  mesh.positions.emplace_back(x, y);
  mesh.background.push_back(best <= 1e-12);
  mesh.points.push_back(best > 1e-12 ? direction / best : Vec3(0.0));
}

// The triangle's fate: 0 not drawn (all background), 1 drawn, 2 a rubber sheet.
int classify_triangle(const DepthMesh& mesh, const std::array<int, 3>& t, double max_jump) {
  int background = 0;
  double z_min = 0.0, z_max = 0.0;
  for (int k = 0; k < 3; ++k) {
    if (mesh.background[static_cast<std::size_t>(t[k])]) {
      ++background;
      continue;
    }
    const double z = mesh.points[static_cast<std::size_t>(t[k])].z;
    z_min = z_min == 0.0 ? z : std::min(z_min, z);
    z_max = std::max(z_max, z);
  }
  if (background == 3) return 0;
  if (background > 0) return 2;
  return z_max / z_min - 1.0 > max_jump ? 2 : 1;
}

// The draw's buffers and the inputs every triangle reads.
struct Raster {
  const Image& rendered;
  const DepthFrame& depth;
  const Camera& camera;
  MeshDraw& out;
};

// Rasterises one projected triangle (see the header's "draw") over target rows [row_begin,
// row_end). Returns the pixels written; `any` tells whether a pixel centre there is inside.
std::int64_t draw_triangle(const std::array<Vec2, 3>& q, const std::array<double, 3>& w,
                           const std::array<Vec2, 3>& s, int row_begin, int row_end, Raster& r,
                           bool& any) {
  const double area = cross(q[1] - q[0], q[2] - q[0]);
  any = false;
  if (!(std::abs(area) > 1e-12)) return 0;
  const int width = r.camera.width, height = r.camera.height;
  const double x0 = std::min({q[0].x, q[1].x, q[2].x}), x1 = std::max({q[0].x, q[1].x, q[2].x});
  const double y0 = std::min({q[0].y, q[1].y, q[2].y}), y1 = std::max({q[0].y, q[1].y, q[2].y});
  // Clamped as doubles first: a triangle near the eye may project far beyond any int.
  const auto pixel = [](double v, int last) {
    return static_cast<int>(std::clamp(v, -1.0, static_cast<double>(last) + 1.0));
  };
  const int i0 = std::max(0, pixel(std::floor(x0 - 0.5), width - 1));
  const int i1 = std::min(width - 1, pixel(std::ceil(x1 - 0.5), width - 1));
  const int j0 = std::max(row_begin, pixel(std::floor(y0 - 0.5), height - 1));
  const int j1 = std::min(row_end - 1, pixel(std::ceil(y1 - 0.5), height - 1));
  constexpr double kEdge = -1e-9;  // edges inclusive: neighbours share their edge's pixels
  std::int64_t written = 0;
  for (int j = j0; j <= j1; ++j) {
    for (int i = i0; i <= i1; ++i) {
      const Vec2 c(i + 0.5, j + 0.5);
      const double b0 = cross(q[2] - q[1], c - q[1]) / area;
      const double b1 = cross(q[0] - q[2], c - q[2]) / area;
      const double b2 = 1.0 - b0 - b1;
      if (b0 < kEdge || b1 < kEdge || b2 < kEdge) continue;
      any = true;
      const double inverse = b0 * w[0] + b1 * w[1] + b2 * w[2];
      const std::size_t d = static_cast<std::size_t>(j) * width + i;
      if (!(inverse > r.out.inverse_depth[d])) continue;
      // Perspective-correct: the render position is affine in the triangle's 3D points.
      const Vec2 src = (b0 * w[0] * s[0] + b1 * w[1] * s[1] + b2 * w[2] * s[2]) / inverse;
      const int si = std::clamp(static_cast<int>(std::floor(src.x)), 0, width - 1);
      const int sj = std::clamp(static_cast<int>(std::floor(src.y)), 0, height - 1);
      const int source = sj * width + si;
      if (r.depth.polygon[static_cast<std::size_t>(source)] < 0) continue;  // background
      r.out.inverse_depth[d] = inverse;
      r.out.source[d] = source;
      r.out.image.pixels()[d] = r.rendered.pixels()[static_cast<std::size_t>(source)];
      ++written;
    }
  }
  return written;
}

// A triangle of the mesh moved to the view now: its projected corners, their inverse depths
// and render positions; in_front false when a corner reaches Z <= near (not drawn).
struct Projected {
  std::array<Vec2, 3> q, s;
  std::array<double, 3> w;
  bool in_front = true;
};

Projected project_triangle(const DepthMesh& mesh, const std::vector<Vec3>& now,
                           const std::array<int, 3>& t, const Camera& camera, double near) {
  Projected p;
  for (int k = 0; k < 3; ++k) {
    const Vec3& x = now[static_cast<std::size_t>(t[k])];
    p.in_front = p.in_front && x.z > near;
    if (!p.in_front) break;
    p.q[k] = splat::project(camera, x);
    p.w[k] = 1.0 / x.z;
    p.s[k] = mesh.positions[static_cast<std::size_t>(t[k])];
  }
  return p;
}

// Pixels [begin, end) of merge_near_and_mesh's frame f (as depth_mesh.h says it merges).
void merge_pixels(const std::vector<Pixel>& near, const DepthFrame& near_depth,
                  const MeshDraw& mesh, std::size_t begin, std::size_t end, MeshFrame& f) {
  std::vector<Pixel>& out = f.image.pixels();
  for (std::size_t d = begin; d < end; ++d) {
    const bool has_near = near_depth.polygon[d] >= 0;
    const bool has_mesh = mesh.source[d] >= 0;
    if (!has_near && !has_mesh) {
      f.unreached[d] = 1;
      continue;
    }
    if (!has_mesh) {
      out[d] = near[d];
      f.source[d] = static_cast<int>(d);
      continue;
    }
    const Pixel m = mesh.image.pixels()[d];
    f.source[d] = mesh.source[d];
    const bool near_in_front = has_near && near_depth.inverse_depth[d] >= mesh.inverse_depth[d];
    out[d] = !has_near ? m : near_in_front ? over(near[d], m) : over(m, near[d]);
    f.mesh_shown[d] = !(near_in_front && near[d].a == 255);
    if (!f.mesh_shown[d]) f.source[d] = static_cast<int>(d);
  }
}

}  // namespace

std::string depth_mesh_settings_problem(const DepthMeshSettings& s) {
  const std::pair<const Limit*, double> settings[] = {{&limits::kMeshGrid, s.grid_px},
                                                      {&limits::kMeshSplit, s.split},
                                                      {&limits::kMeshRebuild, s.rebuild_distance},
                                                      {&limits::kMeshJump, s.max_depth_jump}};
  for (const auto& [limit, value] : settings) {
    if (std::string p = limit->problem(value); !p.empty())
      return std::string(limit->what) + ": " + p;
  }
  return "";
}

double automatic_split(const DepthFrame& depth) {
  double w_min = 0.0, w_max = 0.0;
  for (std::size_t k = 0; k < depth.polygon.size(); ++k) {
    if (depth.polygon[k] < 0 || !(depth.inverse_depth[k] > 0.0)) continue;
    const double w = depth.inverse_depth[k];
    w_min = w_min == 0.0 ? w : std::min(w_min, w);
    w_max = std::max(w_max, w);
  }
  return w_max > 0.0 ? 0.5 * (1.0 / w_max + 1.0 / w_min) : 0.0;
}

std::vector<char> far_polygons(const Scene& scene, const ViewerPose& view, double split) {
  std::vector<char> far(scene.polygons.size(), 1);
  for (std::size_t i = 0; i < far.size(); ++i) {
    for (const Vec3& v : polygon_vertices(scene.polygons[i])) {
      if (!(to_view(view, v).z >= split)) far[i] = 0;
    }
  }
  return far;
}

DepthMesh build_depth_mesh(const DepthFrame& depth, const Camera& camera, int grid_px,
                           double max_depth_jump, bool drop_rubber_sheets) {
  DepthMesh mesh;
  std::vector<int> xs, ys;
  for (int x = 0; x < depth.width; x += grid_px) xs.push_back(x);
  xs.push_back(depth.width);
  for (int y = 0; y < depth.height; y += grid_px) ys.push_back(y);
  ys.push_back(depth.height);
  mesh.columns = static_cast<int>(xs.size());
  mesh.rows = static_cast<int>(ys.size());
  for (int y : ys) {
    for (int x : xs) lift_vertex(depth, camera, x, y, mesh);
  }
  double far_z = 0.0;
  for (std::size_t v = 0; v < mesh.points.size(); ++v) {
    if (!mesh.background[v]) far_z = std::max(far_z, mesh.points[v].z);
  }
  std::vector<char> lifted(mesh.points.size(), 0);  // background vertices of drawn sheets
  for (int r = 0; r + 1 < mesh.rows; ++r) {
    for (int c = 0; c + 1 < mesh.columns; ++c) {
      const int v00 = r * mesh.columns + c, v10 = v00 + 1;
      const int v01 = v00 + mesh.columns, v11 = v01 + 1;
      for (const std::array<int, 3>& t : {std::array<int, 3>{v00, v10, v11}, {v00, v11, v01}}) {
        const int fate = classify_triangle(mesh, t, max_depth_jump);
        if (fate == 0) continue;
        if (fate == 2) {
          ++mesh.rubber_sheets;
          if (drop_rubber_sheets) {
            ++mesh.dropped;
            continue;
          }
          for (int k : t) lifted[static_cast<std::size_t>(k)] |= mesh.background[k];
        }
        mesh.triangles.push_back(t);
      }
    }
  }
  // A drawn sheet's background vertex lies on the farthest surface's depth (a far plane).
  for (std::size_t v = 0; v < lifted.size(); ++v) {
    if (lifted[v]) {
      mesh.points[v] = pixel_direction(camera, mesh.positions[v].x, mesh.positions[v].y) * far_z;
    }
  }
  return mesh;
}

MeshDraw draw_depth_mesh(const DepthMesh& mesh, const Image& rendered, const DepthFrame& depth,
                         const Camera& camera, const RigidStep3& step, double near) {
  MeshDraw out;
  out.image = Image(camera.width, camera.height);
  const std::size_t n = static_cast<std::size_t>(camera.width) * camera.height;
  out.inverse_depth.assign(n, 0.0);
  out.source.assign(n, -1);
  // Each vertex moved once: its point now, projection and inverse depth.
  std::vector<Vec3> now(mesh.points.size());
  for (std::size_t v = 0; v < now.size(); ++v) {
    now[v] = step.rotation * mesh.points[v] + step.translation;
  }
  std::vector<Projected> projected(mesh.triangles.size());
  for (std::size_t k = 0; k < projected.size(); ++k) {
    projected[k] = project_triangle(mesh, now, mesh.triangles[k], camera, near);
  }
  // Bands of target rows, each drawing every triangle in order over its rows: every pixel
  // sees the triangles in the same order on any number of threads; tallies summed in band
  // order, a triangle counted when a band found a pixel centre inside it.
  Raster raster{rendered, depth, camera, out};
  const int min_rows = std::max(4, 16384 / std::max(camera.width, 1));
  const std::size_t bands = static_cast<std::size_t>(band_count(camera.height, min_rows));
  std::vector<std::int64_t> written(bands, 0);
  std::vector<std::vector<char>> drawn(bands);
  for_each_band(camera.height, min_rows, [&](int band, int begin, int end) {
    drawn[band].assign(projected.size(), 0);
    std::int64_t pixels = 0;  // summed here: the bands' slots share cache lines
    for (std::size_t k = 0; k < projected.size(); ++k) {
      const Projected& t = projected[k];
      if (!t.in_front) continue;
      bool any = false;
      pixels += draw_triangle(t.q, t.w, t.s, begin, end, raster, any);
      drawn[band][k] = any;
    }
    written[band] = pixels;
  });
  for (std::size_t b = 0; b < bands; ++b) out.pixels_written += written[b];
  for (std::size_t k = 0; k < projected.size(); ++k) {
    bool any = false;
    for (std::size_t b = 0; b < bands && !any; ++b) any = drawn[b][k];
    out.triangles_drawn += any;
  }
  return out;
}

double mesh_pixel_error(const DepthFrame& depth, const Camera& camera, const RigidStep3& step,
                        int source, int pixel) {
  const int width = camera.width;
  const double w = depth.inverse_depth[static_cast<std::size_t>(source)];
  if (!(w > 0.0)) return 0.0;
  const Vec3 x =
      step.rotation * (pixel_direction(camera, source % width + 0.5, source / width + 0.5) / w) +
      step.translation;
  if (!(x.z > 0.0)) return 0.0;
  const Vec2 centre(pixel % width + 0.5, pixel / width + 0.5);
  return glm::length(centre - splat::project(camera, x));
}

MeshFrame merge_near_and_mesh(const Image& near_image, const DepthFrame& near_depth,
                              const MeshDraw& mesh) {
  MeshFrame f;
  const std::size_t n = near_image.pixels().size();
  f.image = Image(near_image.width(), near_image.height());
  f.unreached.assign(n, 0);
  f.source.assign(n, -1);
  f.mesh_shown.assign(n, 0);
  const int width = near_image.width();
  // Bands of rows, each pixel on its own: the same frame on any number of threads.
  for_each_band(
      near_image.height(), std::max(8, 65536 / std::max(width, 1)), [&](int, int begin, int end) {
        merge_pixels(near_image.pixels(), near_depth, mesh, static_cast<std::size_t>(begin) * width,
                     static_cast<std::size_t>(end) * width, f);
      });
  return f;
}

}  // namespace oflab
