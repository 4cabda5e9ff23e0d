// View interpolation between two renders (core/scene/view_interpolation.h; Chen and Williams,
// SIGGRAPH 93).
#include "scene/view_interpolation.h"

#include <algorithm>

#include "scene/splat_footprint.h"

namespace oflab {
namespace {

using splat::pixel_direction;

// The plane vector m moved by the step x' = R x + t: m.x = 1 becomes (R m).x' = 1 + (R m).t.
// 0 (never nearer than anything) for the background and for a plane the eye has crossed.
Vec3 moved_plane(const Vec3& m, const RigidStep3& step) {
  if (m == Vec3(0.0)) return Vec3(0.0);
  const Vec3 rm = step.rotation * m;
  const double scale = 1.0 + glm::dot(rm, step.translation);
  return scale > 1e-12 ? rm / scale : Vec3(0.0);
}

// Each polygon's plane vector of `depth` moved by the step.
std::vector<Vec3> moved_planes(const DepthFrame& depth, const RigidStep3& step) {
  std::vector<Vec3> planes(depth.planes.size());
  for (std::size_t p = 0; p < planes.size(); ++p) planes[p] = moved_plane(depth.planes[p], step);
  return planes;
}

// Which render pixel d takes: 0 neither, 1 the earlier, 2 the later (see the header's merge).
int merged_choice(int sa, int sb, const DepthFrame& da, const DepthFrame& db,
                  const std::vector<Vec3>& planes_a, const std::vector<Vec3>& planes_b,
                  const Vec3& direction, bool prefer_later) {
  if (sa < 0 && sb < 0) return 0;
  if (sb < 0) return 1;
  if (sa < 0) return 2;
  const int pa = da.polygon[sa], pb = db.polygon[sb];
  const int nearer_in_time = prefer_later ? 2 : 1;
  if (pa == pb) return nearer_in_time;
  const double wa = pa >= 0 ? std::max(0.0, glm::dot(planes_a[pa], direction)) : 0.0;
  const double wb = pb >= 0 ? std::max(0.0, glm::dot(planes_b[pb], direction)) : 0.0;
  if (wa == wb) return nearer_in_time;
  return wa > wb ? 1 : 2;
}

// The per-pixel error of f (see the header) over the pixels showing a surface.
void measure_error(const RenderedView& earlier, const RenderedView& later, const Camera& camera,
                   InterpolatedFrame& f) {
  double sum = 0.0;
  std::int64_t surfaces = 0;
  const int width = camera.width;
  for (std::size_t d = 0; d < f.source.size(); ++d) {
    const int s = f.source[d];
    if (s < 0) continue;
    const RenderedView& view = f.from_later[d] ? later : earlier;
    if (view.depth.polygon[s] < 0) continue;  // the background has no position error
    const Vec3 x = view.step.rotation * (pixel_direction(camera, s % width + 0.5, s / width + 0.5) /
                                         view.depth.inverse_depth[s]) +
                   view.step.translation;
    if (!(x.z > 0.0)) continue;
    const Vec2 centre(static_cast<double>(d % width) + 0.5, static_cast<double>(d / width) + 0.5);
    const double e = glm::length(centre - splat::project(camera, x));
    f.max_error_px = std::max(f.max_error_px, e);
    sum += e;
    ++surfaces;
  }
  if (surfaces > 0) f.mean_error_px = sum / static_cast<double>(surfaces);
}

}  // namespace

double moved_plane_inverse_depth(const Camera& camera, const Vec3& m, const RigidStep3& step,
                                 double u, double v) {
  return std::max(0.0, glm::dot(moved_plane(m, step), pixel_direction(camera, u, v)));
}

InterpolatedFrame interpolate_views(const RenderedView& earlier, const RenderedView& later,
                                    double t, const Camera& camera, double near,
                                    const DepthFrame* now) {
  const Reprojection a = reproject_by_depth(earlier.image, earlier.depth, camera, earlier.step,
                                            HoleFill::kNone, near, now);
  const Reprojection b =
      reproject_by_depth(later.image, later.depth, camera, later.step, HoleFill::kNone, near, now);
  const int width = camera.width, height = camera.height;
  const std::size_t n = static_cast<std::size_t>(width) * height;
  InterpolatedFrame f;
  f.image = Image(width, height);
  f.unreached.assign(n, 0);
  f.from_later.assign(n, 0);
  f.source.assign(n, -1);
  f.earlier_hole_pixels = a.hole_pixels;
  f.later_hole_pixels = b.hole_pixels;
  f.pixels_written = a.pixels_written + b.pixels_written;
  f.source_pixels = a.source_pixels + b.source_pixels;
  const std::vector<Vec3> planes_a = moved_planes(earlier.depth, earlier.step);
  const std::vector<Vec3> planes_b = moved_planes(later.depth, later.step);
  const bool prefer_later = t > 0.5;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::size_t d = static_cast<std::size_t>(y) * width + x;
      const int choice =
          merged_choice(a.source[d], b.source[d], earlier.depth, later.depth, planes_a, planes_b,
                        pixel_direction(camera, x + 0.5, y + 0.5), prefer_later);
      if (choice == 0) {
        f.unreached[d] = 1;
        f.hole_pixels += !now || now->polygon[d] >= 0;
        continue;
      }
      const Reprojection& from = choice == 1 ? a : b;
      f.image.pixels()[d] = from.image.pixels()[d];
      f.source[d] = from.source[d];
      f.from_later[d] = choice == 2;
    }
  }
  measure_error(earlier, later, camera, f);
  return f;
}

}  // namespace oflab
