// Per-pixel depth reprojection and the automatic stabilization plane
// (core/scene/depth_reprojection.h).
#include "scene/depth_reprojection.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>

#include "flow/named_values.h"
#include "image/scan_conversion.h"
#include "image/thread_pool.h"
#include "scene/splat_footprint.h"
#include "scene/view_culling.h"

namespace oflab {
namespace {

using splat::CornerLattice;
using splat::pixel_direction;
using splat::PixelBox;
using splat::PixelDirections;

// Where the point seen along direction d (pixel_direction) with plane vector m and inverse
// depth w lands after the step, top-left pixels, and its inverse depth there; false when it
// is behind the surface's horizon or reaches Z <= near. m = 0 (the background) moves as a
// direction.
bool move_point(const Camera& camera, const RigidStep3& step, const Vec3& m, double w,
                const Vec3& d, double near, Vec2& moved, double& moved_w) {
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

// What each target pixel keeps while the splats are painted: the inverse depth and the
// squared distance from its centre of the splat it shows, and that splat's polygon
// (kNoSplat before any splat reached the pixel).
struct TargetCell {
  double z;
  double dist;  // px^2
  int polygon;
  int first;  // the source pixel of the first splat that wrote the pixel
};
constexpr int kNoSplat = -2;  // no polygon index, nor the background's -1

// Every source pixel's splat, planned before any is painted: where its centre lands and its
// inverse depth there, the pixels its footprint may cover (an empty box: no splat), its
// corners (kept here only where they are not the lattice's: own_corners), and per source row
// the target rows its splats may reach.
struct SplatPlan {
  std::vector<Vec2> exact;  // where each source pixel centre lands now
  std::vector<double> centre_w;
  std::vector<PixelBox> boxes;
  std::vector<char> own_corners;  // 1: corners[s] holds them; 0: the lattice holds them
  std::vector<std::array<Vec2, 4>> corners;
  std::vector<int> row_first, row_last;  // per source row; last < first: reaches no row
};

// The background under a step without rotation (R the identity, to the bit): it moves as a
// direction, and R d = d exactly, so the corner of pixel (k, l) lands at (x[k], y[l]) whatever
// the other index (move_point's arithmetic), background splat (i, j)'s footprint is the
// rectangle of corners (x[i], y[j]) .. (x[i + 2], y[j + 2]) and its centre lands at
// (x[i + 1], y[j + 1]). Those splats are painted pixel by pixel (paint_background_rows)
// instead of planned and painted splat by splat.
struct BackgroundGrid {
  // The target lines' views of the splat lines around them (splat::grid_lines).
  using Line = splat::GridLine;
  static constexpr int kUndecided = splat::kUndecidedSides;

  std::vector<double> x, y;         // k = 0 .. width + 1, l = 0 .. height + 1
  std::vector<Line> columns, rows;  // per target column (row) 3 entries, splat column k - 1 ..

  // Whether the grid holds for this reprojection: no rotation, near > 0, every landed corner
  // within a quarter pixel of its own place (so a splat's box holds at most the 3 x 3 pixels
  // around it) and every surface shown with a plane (so a surface splat always lands nearer
  // than the background). Fills the grid when it holds.
  bool prepare(const Camera& camera, const PixelDirections& directions, const RigidStep3& step,
               double near, const DepthFrame& depth) {
    if (!(step.rotation == Mat3(1.0)) || !(near > 0.0)) return false;
    for (const int p : depth.polygon) {
      if (p >= 0 && depth.planes[p] == Vec3(0.0)) return false;
    }
    if (!land(camera, directions, step, near, camera.width, true, x) ||
        !land(camera, directions, step, near, camera.height, false, y)) {
      return false;
    }
    splat::grid_lines(x, y, false, columns);
    splat::grid_lines(y, x, true, rows);
    return true;
  }

 private:
  static bool land(const Camera& camera, const PixelDirections& directions, const RigidStep3& step,
                   double near, int size, bool columns, std::vector<double>& at) {
    at.resize(static_cast<std::size_t>(size) + 2);
    for (int k = 0; k < size + 2; ++k) {
      Vec2 q;
      double w = 0.0;
      const Vec3 d = columns ? directions.at(k, 0) : directions.at(0, k);
      if (!move_point(camera, step, Vec3(0.0), 0.0, d, near, q, w)) return false;
      at[k] = columns ? q.x : q.y;
      if (!(std::abs(at[k] - (k - 0.5)) < 0.25)) return false;
    }
    return true;
  }
};

// The working memory of one reprojection, kept by each thread that reprojects: a frame's
// buffers are tens of megabytes, and fresh ones cost a page fault per page every frame.
// Sized for `n` pixels and `rows` rows; what a pass reads before it writes is reset here, but
// the target cells, which the first pass resets band by band.
struct ReprojectionScratch {
  std::vector<TargetCell> cells;
  PixelDirections directions;
  BackgroundGrid grid;
  CornerLattice lattice;
  SplatPlan plan;
  void prepare(const Camera& camera) {
    const std::size_t n = static_cast<std::size_t>(camera.width) * camera.height;
    cells.resize(n);  // reset by the first pass, band by band
    directions.prepare(camera);
    lattice.moved.resize(n);
    lattice.ok.resize(n);
    plan.exact.resize(n);
    plan.centre_w.resize(n);
    plan.boxes.resize(n);
    plan.own_corners.resize(n);
    plan.corners.resize(n);  // written only where own_corners
    plan.row_first.assign(static_cast<std::size_t>(camera.height), 0);
    plan.row_last.assign(static_cast<std::size_t>(camera.height), -1);
  }
};

// Moves the top-left footprint corner of pixel (i, j) with the surface of plane vector m (0:
// the background) by the step: splat::move_lattice_rows' `move`.
struct CornerMove {
  const Camera& camera;
  const PixelDirections& directions;
  const RigidStep3& step;
  double near;
  bool operator()(const Vec3& m, int i, int j, Vec2& q) const {
    double w_unused = 0.0;
    const Vec3 d = directions.at(i, j);
    return move_point(camera, step, m, glm::dot(m, d), d, near, q, w_unused);
  }
};

// The corners of source pixel s = (i, j)'s footprint, as plan_splat_rows planned them:
// where they are the lattice's, the lattice points of pixels (i, j), (i + 2, j),
// (i + 2, j + 2) and (i, j + 2) (splat::move_footprint).
std::array<Vec2, 4> planned_corners(const SplatPlan& plan, const CornerLattice& lattice,
                                    std::size_t s, int width) {
  if (plan.own_corners[s]) return plan.corners[s];
  const std::size_t below = s + 2 * static_cast<std::size_t>(width);
  return {lattice.moved[s], lattice.moved[s + 2], lattice.moved[below + 2], lattice.moved[below]};
}

// Whether footprint corners (i + 2, j), (i + 2, j + 2) and (i, j + 2) of source pixel s =
// (i, j), polygon p, are lattice points of polygon p (so splat::move_footprint takes all four
// from the lattice), and whether they all moved.
bool lattice_footprint(const DepthFrame& depth, const CornerLattice& lattice, int i, int j,
                       std::size_t s, int p, bool& moved) {
  const int width = depth.width;
  if (i + 2 >= width || j + 2 >= depth.height) return false;
  const std::size_t below = s + 2 * static_cast<std::size_t>(width);
  if (depth.polygon[s + 2] != p || depth.polygon[below] != p || depth.polygon[below + 2] != p) {
    return false;
  }
  moved = lattice.ok[s] && lattice.ok[s + 2] && lattice.ok[below] && lattice.ok[below + 2];
  return true;
}

// One planned splat being painted: what it gives the pixels it wins, and the rule it wins
// by: the nearest surface, and among the splats of one polygon the one whose centre lands
// nearest.
struct SplatPainter {
  Vec2 landed;
  double centre_w;
  int polygon;
  int source;
  Pixel colour;
  TargetCell* cells;
  Pixel* image;
  int* shown;

  // Paints pixel d, centre (cx, cy), inside the footprint, where the splat wins; returns 1
  // when it wrote the pixel, else 0.
  int paint(std::size_t d, double cx, double cy) const {
    TargetCell& t = cells[d];
    const bool same = t.polygon == polygon;
    if (!same && centre_w <= t.z) return 0;  // something nearer (or the same)
    // Squared: the nearer of two landings without a square root per pixel.
    const Vec2 c(cx, cy);
    const double e = glm::dot(c - landed, c - landed);
    if (same && e >= t.dist) return 0;  // a splat of the same surface lands nearer
    t = TargetCell{centre_w, e, polygon, t.polygon == kNoSplat ? source : t.first};
    image[d] = colour;
    shown[d] = source;
    return 1;
  }
};

// The widest box painted by SplatPainter's axis-aligned path (wider ones take the general).
constexpr int kAlignedColumns = 16;

// Paints an axis-aligned footprint (splat::axis_aligned) over target rows [y0, y1] of `box`:
// inside_footprint's tests split into each row's and each column's. Returns the pixels written.
std::int64_t paint_aligned(const SplatPainter& splat, const std::array<Vec2, 4>& q,
                           const std::array<Vec2, 4>& edge, const PixelBox& box, int y0, int y1,
                           int width) {
  int columns[kAlignedColumns];
  for (int x = box.x_begin; x <= box.x_end; ++x) {
    columns[x - box.x_begin] = splat::column_sides(q, edge, x + 0.5);
  }
  std::int64_t written = 0;
  for (int y = y0; y <= y1; ++y) {
    const double cy = y + 0.5;
    const int row = splat::row_sides(q, edge, cy);
    const std::size_t first = static_cast<std::size_t>(y) * width;
    for (int x = box.x_begin; x <= box.x_end; ++x) {
      if (row & columns[x - box.x_begin]) written += splat.paint(first + x, x + 0.5, cy);
    }
  }
  return written;
}

// Paints source pixel s's planned splat into r.image at every pixel centre of target rows
// [y_begin, y_end] inside its footprint where it wins (SplatPainter). Returns the pixels
// written.
std::int64_t paint_splat(const SplatPlan& plan, const CornerLattice& lattice, std::size_t s,
                         int y_begin, int y_end, const Image& rendered, const DepthFrame& depth,
                         TargetCell* cells, Reprojection& r) {
  const int width = depth.width;
  const PixelBox& box = plan.boxes[s];
  const std::array<Vec2, 4> q = planned_corners(plan, lattice, s, width);
  const std::array<Vec2, 4> edge = splat::footprint_edges(q);  // computed once
  const SplatPainter splat{plan.exact[s],           plan.centre_w[s],     depth.polygon[s],
                           static_cast<int>(s),     rendered.pixels()[s], cells,
                           r.image.pixels().data(), r.source.data()};
  const int y0 = std::max(box.y_begin, y_begin), y1 = std::min(box.y_end, y_end);
  if (splat::axis_aligned(edge) && box.x_end - box.x_begin < kAlignedColumns) {
    return paint_aligned(splat, q, edge, box, y0, y1, width);
  }
  std::int64_t written = 0;
  for (int y = y0; y <= y1; ++y) {
    const double cy = y + 0.5;
    const splat::FootprintRow row(q, edge, cy);
    const std::size_t first = static_cast<std::size_t>(y) * width;
    for (int x = box.x_begin; x <= box.x_end; ++x) {
      const double cx = x + 0.5;
      if (row.holds(cx)) written += splat.paint(first + x, cx, cy);
    }
  }
  return written;
}

// Whether the centre of pixel (x, y) is inside background splat (i, j)'s footprint
// (BackgroundGrid), as paint_aligned decides it.
bool background_inside(const BackgroundGrid& grid, int i, int j, int x, int y) {
  const std::array<Vec2, 4> q = {Vec2(grid.x[i], grid.y[j]), Vec2(grid.x[i + 2], grid.y[j]),
                                 Vec2(grid.x[i + 2], grid.y[j + 2]),
                                 Vec2(grid.x[i], grid.y[j + 2])};
  const std::array<Vec2, 4> edge = splat::footprint_edges(q);
  return (splat::row_sides(q, edge, y + 0.5) & splat::column_sides(q, edge, x + 0.5)) != 0;
}

// What the background's splats of the 3 x 3 source pixels around one target pixel do
// (pick_background): the one that shows and the first that reached the pixel, each as
// 3 n + m (source pixel (x - 1 + m, y - 1 + n); -1: none), the squared distance of the one
// that shows and the writes.
struct BackgroundPick {
  int shown = -1, first = -1;
  double dist = 0.0;
  int written = 0;
};

// The background splats around a target pixel met in source order, as paint_aligned paints
// them: splat (m, n) (source pixel (x - 1 + m, y - 1 + n)) counts where its lines
// (BackgroundGrid) reach the pixel, usable(m, n) holds, and it covers the pixel centre
// (inside(m, n) decides where the lines leave that undecided); it shows where its centre
// lands nearer than the one shown so far.
template <typename Usable, typename Inside>
BackgroundPick pick_background(const splat::GridLine* rows3, const splat::GridLine* columns3,
                               const Usable& usable, const Inside& inside) {
  BackgroundPick pick;
  splat::for_each_reaching_splat(
      rows3, columns3,
      [&](int m, int n, const splat::GridLine& row, const splat::GridLine& column) {
        if (!usable(m, n) || !splat::covers(row, column, [&] { return inside(m, n); })) {
          return true;
        }
        // glm::dot of the offset with itself: the two squares' sum.
        const double e = column.offset2 + row.offset2;
        if (pick.shown >= 0 && e >= pick.dist) return true;  // a background splat lands nearer
        pick.first = pick.shown < 0 ? 3 * n + m : pick.first;
        pick.shown = 3 * n + m, pick.dist = e;
        ++pick.written;
        return true;
      });
  return pick;
}

// Paints the background's splats (BackgroundGrid) over target rows [y_begin, y_end), pixel by
// pixel, after the surfaces' splats: a surface splat always wins over the background and the
// background never over a surface (its inverse depth is 0), so a pixel's background splats
// count only before the first surface splat that reached it (TargetCell::first), and they
// are those of the 3 x 3 source pixels around it, met in source order, tested as
// paint_aligned tests them (pick_background; made once per run of columns with the same
// lines where they are all the background's: splat::paint_grid_pixels). Returns the pixels
// written.
std::int64_t paint_background_rows(const BackgroundGrid& grid, const Image& rendered,
                                   const DepthFrame& depth, int y_begin, int y_end,
                                   TargetCell* cells, Reprojection& r) {
  using Line = splat::GridLine;
  const int width = depth.width;
  const auto free = [cells](std::size_t d) { return cells[d].polygon == kNoSplat; };
  const auto pick = [&](int x, int y, const Line* rows3, const Line* columns3,
                        bool all_background) -> BackgroundPick {
    if (all_background) {
      return pick_background(
          rows3, columns3, [](int, int) { return true; }, [](int, int) { return false; });
    }
    const std::size_t d = static_cast<std::size_t>(y) * width + x;
    const int before = free(d) ? -1 : cells[d].first;
    return pick_background(
        rows3, columns3,
        [&](int m, int n) {
          const int s = splat::around(x, y, width, m, n);
          return !(before >= 0 && s >= before) && depth.polygon[s] == -1;
        },
        [&](int m, int n) { return background_inside(grid, x - 1 + m, y - 1 + n, x, y); });
  };
  std::int64_t written = 0;
  const auto paint = [&](std::size_t d, int x, int y, const BackgroundPick& picked) {
    written += picked.written;
    if (!free(d) || picked.shown < 0) return;  // a surface shows, or nothing
    const int shown = splat::around(x, y, width, picked.shown);
    const int first = splat::around(x, y, width, picked.first);
    cells[d] = TargetCell{0.0, picked.dist, -1, first};
    r.image.pixels()[d] = rendered.pixels()[shown];
    r.source[d] = shown;
  };
  splat::paint_grid_pixels(grid.rows, grid.columns, depth.polygon, width, depth.height, y_begin,
                           y_end, free, pick, paint);
  return written;
}

// The corner lattice's rows [begin, end) (splat::move_lattice_rows), but the background's
// points where `grid` holds (BackgroundGrid: the background's splats do not read them, and
// no other splat does).
void move_lattice(const DepthFrame& depth, int begin, int end, const CornerMove& move, bool grid,
                  CornerLattice& lattice) {
  if (!grid) {
    splat::move_lattice_rows(depth, begin, end, move, lattice);
    return;
  }
  for (int j = begin; j < end; ++j) {
    for (int i = 0; i < depth.width; ++i) {
      const std::size_t k = static_cast<std::size_t>(j) * depth.width + i;
      const int p = depth.polygon[k];
      if (p >= 0) lattice.ok[k] = move(depth.planes[p], i, j, lattice.moved[k]);
    }
  }
}

// The splats of source rows [begin, end): each centre moved by the pixel's own depth, each
// footprint's corners by the depth of its surface there.
void plan_splat_rows(const DepthFrame& depth, const Camera& camera, const RigidStep3& step,
                     double near, const PixelDirections& directions, const CornerLattice& lattice,
                     bool grid, int begin, int end, SplatPlan& plan) {
  const CornerMove move{camera, directions, step, near};
  for (int j = begin; j < end; ++j) {
    for (int i = 0; i < depth.width; ++i) {
      const std::size_t s = static_cast<std::size_t>(j) * depth.width + i;
      const int p = depth.polygon[s];
      const Vec3 m = splat::surface_of(depth, p);
      PixelBox& box = plan.boxes[s];
      if (grid && p < 0) {  // painted by paint_background_rows
        box = PixelBox{};
        continue;
      }
      bool moved = false;
      const bool shared = lattice_footprint(depth, lattice, i, j, s, p, moved);
      plan.own_corners[s] = !shared;
      std::array<Vec2, 4> q{};
      if (shared) {
        q = planned_corners(plan, lattice, s, depth.width);
      } else {
        moved = splat::move_footprint(lattice, depth, i, j, p, move, q);
        plan.corners[s] = q;
      }
      if (!moved ||
          !move_point(camera, step, m, depth.inverse_depth[s], directions.at(i + 1, j + 1), near,
                      plan.exact[s], plan.centre_w[s]) ||
          !splat::footprint_box(q, depth.width, depth.height, box)) {
        box = PixelBox{};
        continue;
      }
      splat::reach_rows(box, plan.row_first[j], plan.row_last[j]);
    }
  }
}

// Paints every planned splat into target rows [y_begin, y_end), in source order (so each
// pixel sees its splats in the order one pass over the source would paint them). Returns the
// pixels written.
std::int64_t paint_target_rows(const SplatPlan& plan, const CornerLattice& lattice,
                               const Image& rendered, const DepthFrame& depth, int y_begin,
                               int y_end, TargetCell* cells, Reprojection& r) {
  std::int64_t written = 0;
  for (int j = 0; j < depth.height; ++j) {
    if (plan.row_last[j] < plan.row_first[j] || plan.row_last[j] < y_begin ||
        plan.row_first[j] >= y_end) {
      continue;
    }
    for (int i = 0; i < depth.width; ++i) {
      const std::size_t s = static_cast<std::size_t>(j) * depth.width + i;
      const PixelBox& box = plan.boxes[s];
      if (box.y_end < box.y_begin || box.y_end < y_begin || box.y_begin >= y_end) continue;
      written += paint_splat(plan, lattice, s, y_begin, y_end - 1, rendered, depth, cells, r);
    }
  }
  return written;
}

// The unreached pixels and holes of r (see reproject_by_depth's `now`) and the per-pixel
// displacement error of the pixels showing a surface.
void measure_unreached(const DepthFrame& depth, const std::vector<Vec2>& exact,
                       const DepthFrame* now, int width, Reprojection& r) {
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
    const double e = glm::length(centre - exact[r.source[d]]);
    r.max_error_px = std::max(r.max_error_px, e);
    error_sum += e;
    ++surfaces;
  }
  if (surfaces > 0) r.mean_error_px = error_sum / static_cast<double>(surfaces);
}

// HoleFill::kStretch: each unreached pixel takes the farther (smaller inverse depth z) of the
// nearest reached pixels left and right of it on its row, or the one there is.
void stretch_into_holes(const std::vector<TargetCell>& cells, int width, int height,
                        Reprojection& r) {
  for (int y = 0; y < height; ++y) {
    const std::size_t row = static_cast<std::size_t>(y) * width;
    for (int x = 0; x < width; ++x) {
      if (!r.unreached[row + x]) continue;
      int left = x - 1, right = x + 1;
      while (left >= 0 && r.unreached[row + left]) --left;
      while (right < width && r.unreached[row + right]) ++right;
      int from = -1;
      if (left >= 0 && right < width) {
        from = cells[row + left].z <= cells[row + right].z ? left : right;  // the farther one
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
                        double near, const std::vector<char>* only) {
  DepthFrame depth;
  depth.width = camera.width;
  depth.height = camera.height;
  const std::size_t n = static_cast<std::size_t>(camera.width) * camera.height;
  depth.inverse_depth.assign(n, 0.0);
  depth.polygon.assign(n, -1);
  depth.planes.assign(scene.polygons.size(), Vec3(0.0));
  const ViewFrustum frustum = view_frustum(camera, near, 1.0);
  // The visible polygons' image regions, in polygon order.
  std::vector<int> drawn;
  std::vector<ConvexPolygon> regions;
  for (std::size_t i = 0; i < scene.polygons.size(); ++i) {
    if (only && !(*only)[i]) continue;
    const ScenePolygon& polygon = scene.polygons[i];
    const Vec3 front = direction_to_view(view, polygon.front);
    const Vec3 centre = to_view(view, polygon.centre);
    if (is_back_facing(front, centre)) continue;
    ViewPolygon clipped;
    for (const Vec3& v : polygon_vertices(polygon)) clipped.points.push_back(to_view(view, v));
    clipped.uv = polygon_outline(polygon);
    clipped = clip_to_frustum(clipped, frustum);
    if (clipped.empty()) continue;
    depth.planes[i] = plane_vector_of(centre, front);
    drawn.push_back(static_cast<int>(i));
    regions.push_back(project_to_pixels(camera, clipped));
  }
  // Bands of rows on the worker threads, each drawing every polygon in order over its rows:
  // every pixel sees the polygons in the same order on any number of threads.
  const int min_rows = std::max(4, 16384 / std::max(camera.width, 1));
  for_each_band(camera.height, min_rows, [&](int, int begin, int end) {
    for (std::size_t k = 0; k < drawn.size(); ++k) {
      const Vec3 m = depth.planes[static_cast<std::size_t>(drawn[k])];
      ScanConverter rows(regions[k], camera.width, camera.height);
      rows.clip_rows(begin, end);
      PixelSpan span;
      while (rows.next(span)) {
        for (int x = span.x_begin; x < span.x_end; ++x) {
          const std::size_t p = static_cast<std::size_t>(span.y) * camera.width + x;
          const double w = glm::dot(m, pixel_direction(camera, x + 0.5, span.y + 0.5));
          if (w > depth.inverse_depth[p]) {
            depth.inverse_depth[p] = w;
            depth.polygon[p] = drawn[k];
          }
        }
      }
    }
  });
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

// Every fill with its name, in the order of the enum.
constexpr NamedValue<HoleFill> kHoleFillNames[] = {{HoleFill::kNone, "none"},
                                                   {HoleFill::kStretch, "stretch"},
                                                   {HoleFill::kBackground, "background"}};
static_assert(std::size(kHoleFillNames) == kHoleFillCount);

const char* hole_fill_name(HoleFill fill) { return name_of_value(kHoleFillNames, fill, "none"); }

bool parse_hole_fill(const std::string& name, HoleFill& fill) {
  return parse_named_value(kHoleFillNames, name, &fill);
}

std::string hole_fill_name_list(const std::string& separator) {
  return named_value_list(kHoleFillNames, separator);
}

Reprojection reproject_by_depth(const Image& rendered, const DepthFrame& depth,
                                const Camera& camera, const RigidStep3& step, HoleFill fill,
                                double near, const DepthFrame* now) {
  const int width = camera.width, height = camera.height;
  const std::size_t n = static_cast<std::size_t>(width) * height;
  Reprojection r;
  r.image = Image(width, height);
  r.source.assign(n, -1);
  r.source_pixels = static_cast<std::int64_t>(n);
  thread_local ReprojectionScratch scratch;
  scratch.prepare(camera);
  const PixelDirections& directions = scratch.directions;
  CornerLattice& lattice = scratch.lattice;
  SplatPlan& plan = scratch.plan;
  TargetCell* cells = scratch.cells.data();
  // (The bands below reach the scratch through these references: on a worker thread the
  // name `scratch` is that thread's own.)
  const BackgroundGrid& background = scratch.grid;
  const bool grid = scratch.grid.prepare(camera, directions, step, near, depth);
  // Three passes over bands of rows, each band writing only its own rows: the moved corners,
  // the splats of the source rows, then the target rows painted. The bands are cut by the
  // frame's size alone, so the frame is the same with any number of threads.
  const int min_rows = std::max(4, 16384 / std::max(width, 1));
  for_each_band(height, min_rows, [&](int, int begin, int end) {
    std::fill(cells + static_cast<std::ptrdiff_t>(begin) * width,
              cells + static_cast<std::ptrdiff_t>(end) * width,
              TargetCell{-1.0, 0.0, kNoSplat, -1});
    move_lattice(depth, begin, end, CornerMove{camera, directions, step, near}, grid, lattice);
  });
  for_each_band(height, min_rows, [&](int, int begin, int end) {
    plan_splat_rows(depth, camera, step, near, directions, lattice, grid, begin, end, plan);
  });
  std::vector<std::int64_t> written(static_cast<std::size_t>(band_count(height, min_rows)), 0);
  for_each_band(height, min_rows, [&](int band, int begin, int end) {
    written[band] = paint_target_rows(plan, lattice, rendered, depth, begin, end, cells, r);
    if (grid) {
      written[band] += paint_background_rows(background, rendered, depth, begin, end, cells, r);
    }
  });
  for (const std::int64_t w : written) r.pixels_written += w;
  measure_unreached(depth, plan.exact, now, width, r);
  if (fill == HoleFill::kBackground) {
    for (std::size_t d = 0; d < n; ++d) {
      if (r.unreached[d]) r.image.pixels()[d] = kHoleBackground;
    }
  } else if (fill == HoleFill::kStretch) {
    stretch_into_holes(scratch.cells, width, height, r);
  }
  return r;
}

}  // namespace oflab
