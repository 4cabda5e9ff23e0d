// View interpolation between two renders (core/scene/view_interpolation.h; Chen and Williams,
// SIGGRAPH 93).
#include "scene/view_interpolation.h"

#include <algorithm>

#include "image/thread_pool.h"
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

// Rows per band of the passes over a frame `width` pixels wide.
int min_band_rows(int width) { return std::max(4, 16384 / std::max(width, 1)); }

// The largest, the sum and the count of the displacement errors of some pixels.
// The per-pixel error of f (see the header) over the pixels of rows [begin, end) showing a
// surface.
splat::ErrorTally measure_error_rows(const RenderedView& earlier, const RenderedView& later,
                                     const splat::PixelDirections& directions, const Camera& camera,
                                     const InterpolatedFrame& f, int begin, int end) {
  const int width = camera.width;
  splat::ErrorTally t;  // kept here, not in the caller's per-band slots: those share cache lines
  for (int y = begin; y < end; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::size_t d = static_cast<std::size_t>(y) * width + x;
      const int s = f.source[d];
      if (s < 0) continue;
      const RenderedView& view = f.from_later[d] ? later : earlier;
      if (view.depth.polygon[s] < 0) continue;  // the background has no position error
      const Vec3 p = view.step.rotation * (directions.at(s % width + 1, s / width + 1) /
                                           view.depth.inverse_depth[s]) +
                     view.step.translation;
      if (!(p.z > 0.0)) continue;
      const double e = glm::length(Vec2(x + 0.5, y + 0.5) - splat::project(camera, p));
      t.max = std::max(t.max, e);
      t.sum += e;
      ++t.surfaces;
    }
  }
  return t;
}

// Rows [begin, end) of the merge of a and b into f (see the header); returns the holes there.
std::int64_t merge_rows(const Reprojection& a, const Reprojection& b, const RenderedView& earlier,
                        const RenderedView& later, const std::vector<Vec3>& planes_a,
                        const std::vector<Vec3>& planes_b, const splat::PixelDirections& directions,
                        bool prefer_later, const DepthFrame* now, int width, int begin, int end,
                        InterpolatedFrame& f) {
  std::int64_t holes = 0;
  for (int y = begin; y < end; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::size_t d = static_cast<std::size_t>(y) * width + x;
      const int choice =
          merged_choice(a.source[d], b.source[d], earlier.depth, later.depth, planes_a, planes_b,
                        directions.at(x + 1, y + 1), prefer_later);
      if (choice == 0) {
        f.unreached[d] = 1;
        holes += !now || now->polygon[d] >= 0;
        continue;
      }
      const Reprojection& from = choice == 1 ? a : b;
      f.image.pixels()[d] = from.image.pixels()[d];
      f.source[d] = from.source[d];
      f.from_later[d] = choice == 2;
    }
  }
  return holes;
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
  thread_local splat::PixelDirections directions;
  directions.prepare(camera);
  const splat::PixelDirections& table = directions;  // this thread's, for the bands
  // Bands of rows cut by the frame's size alone, every tally summed in band order: the same
  // frame on any number of threads.
  const int min_rows = min_band_rows(width);
  const std::size_t bands = static_cast<std::size_t>(band_count(height, min_rows));
  std::vector<std::int64_t> holes(bands, 0);
  std::vector<splat::ErrorTally> errors(bands);
  for_each_band(height, min_rows, [&](int band, int begin, int end) {
    holes[band] = merge_rows(a, b, earlier, later, planes_a, planes_b, table, t > 0.5, now, width,
                             begin, end, f);
    errors[band] = measure_error_rows(earlier, later, table, camera, f, begin, end);
  });
  for (std::size_t k = 0; k < bands; ++k) f.hole_pixels += holes[k];
  splat::add_error_bands(errors, &f.max_error_px, &f.mean_error_px);
  return f;
}

}  // namespace oflab
