// Frame generation by extrapolation along motion vectors (core/scene/frame_generation.h).
#include "scene/frame_generation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "image/push_pull.h"
#include "image/thread_pool.h"
#include "scene/splat_footprint.h"

namespace oflab {
namespace {

using splat::pixel_direction;
using splat::PixelBox;
using splat::PixelDirections;
using splat::project;

// extrapolate_point with the direction through (u, v) given (pixel_direction's, or a
// PixelDirections entry: the same bits).
bool extrapolate_along(const Camera& camera, const RigidStep3& back, const Vec3& m, const Vec3& d,
                       double u, double v, int frames_ahead, double near, Vec2& moved,
                       double& moved_w) {
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

// The background's splats when the step has no rotation (R the identity, to the bit): it
// moves as a direction and R d = d, so its motion vector is 0 and the point along direction
// (x[k], y[l], 1) (PixelDirections) stays at (x[k]', y[l]'), with x[k]' = p + k (p - p),
// p = cx + f x[k] / 1: extrapolate_along's arithmetic, so the same bits, once per column and
// row instead of once per pixel. Background pixel (i, j)'s footprint is then the rectangle of
// (x[i]', y[j]') .. (x[i + 2]', y[j + 2]') whatever its neighbours show, its centre lands at
// (x[i + 1]', y[j + 1]'), and its box's columns (rows) are those of column i (row j):
// splat::footprint_box's arithmetic over the same corners.
struct StillBackground {
  bool holds = false;
  std::vector<double> x, y;
  std::vector<int> x_begin, x_end, y_begin, y_end;  // per source column, per source row
  void prepare(const Camera& camera, const PixelDirections& directions, const RigidStep3& back,
               int frames_ahead) {
    holds = back.rotation == Mat3(1.0);
    if (!holds) return;
    const double k = frames_ahead;
    const auto fill = [&](std::vector<double>& to, const std::vector<double>& from, double c) {
      to.resize(from.size());
      for (std::size_t n = 0; n < from.size(); ++n) {
        const double p = c + camera.focal_px * from[n] / 1.0;
        to[n] = p + k * (p - p);
      }
    };
    fill(x, directions.x, camera.cx);
    fill(y, directions.y, camera.cy);
    box_lines(x, camera.width, x_begin, x_end);
    box_lines(y, camera.height, y_begin, y_end);
    near_own = within_one(x_begin, x_end) && within_one(y_begin, y_end);
  }
  // Whether every background splat's box lies within one pixel of its own pixel (columns
  // i - 1 .. i + 1, rows j - 1 .. j + 1; set by prepare): then a target pixel's background
  // splats are those of the 3 x 3 source pixels around it (paint_still_background_rows).
  bool near_own = false;
  // The corners of background pixel (i, j)'s footprint, as splat::move_footprint orders them.
  std::array<Vec2, 4> corners(int i, int j) const {
    return {Vec2(x[i], y[j]), Vec2(x[i + 2], y[j]), Vec2(x[i + 2], y[j + 2]), Vec2(x[i], y[j + 2])};
  }
  // Background pixel (i, j)'s box; false when it is empty or too large (footprint_box).
  bool box(int i, int j, PixelBox& b) const {
    b = PixelBox{x_begin[i], x_end[i], y_begin[j], y_end[j]};
    if (b.x_end < b.x_begin || b.y_end < b.y_begin) return false;
    return !(static_cast<double>(b.x_end - b.x_begin + 1) * (b.y_end - b.y_begin + 1) >
             splat::kMaxBoxPixels);
  }

 private:
  static void box_lines(const std::vector<double>& at, int size, std::vector<int>& begin,
                        std::vector<int>& end) {
    begin.resize(static_cast<std::size_t>(size));
    end.resize(static_cast<std::size_t>(size));
    for (int k = 0; k < size; ++k) {
      const double lo = std::min(at[k], at[k + 2]), hi = std::max(at[k], at[k + 2]);
      begin[k] = std::max(0, static_cast<int>(std::ceil(lo - 0.5)));
      end[k] = std::min(size - 1, static_cast<int>(std::floor(hi - 0.5)));
    }
  }
  static bool within_one(const std::vector<int>& begin, const std::vector<int>& end) {
    for (std::size_t k = 0; k < begin.size(); ++k) {
      if (begin[k] < static_cast<int>(k) - 1 || end[k] > static_cast<int>(k) + 1) return false;
    }
    return true;
  }
};

// The target rows' and columns' views of the still background's splats around them
// (splat::grid_lines, as depth reprojection's BackgroundGrid), where StillBackground holds and
// is near its own pixels.
struct StillLines {
  std::vector<splat::GridLine> rows, columns;  // per target row (column) 3 entries
  // Fills the lines and returns this where the still background holds and is near its own
  // pixels; else null (its splats are painted with the surfaces').
  const StillLines* prepare(const StillBackground& still) {
    if (!still.holds || !still.near_own) return nullptr;
    splat::grid_lines(still.y, still.x, true, rows);
    splat::grid_lines(still.x, still.y, false, columns);
    return this;
  }
};

// Moves the point along direction (x[k], y[l], 1) (PixelDirections), at top-left pixel
// position (u, v), with the surface of plane vector m (0: the background) along its motion
// extrapolated `frames_ahead` frames (extrapolate_point); as a corner lattice point (k, l)
// = (i, j), the top-left footprint corner of pixel (i, j): splat::move_lattice_rows' `move`.
struct CornerMove {
  const Camera& camera;
  const PixelDirections& directions;
  const StillBackground& still;
  const RigidStep3& back;
  int frames_ahead;
  double near;
  bool along(const Vec3& m, int k, int l, double u, double v, Vec2& q, double& w) const {
    if (still.holds && m == Vec3(0.0)) {
      q = Vec2(still.x[k], still.y[l]);
      w = 0.0;
      return true;
    }
    return extrapolate_along(camera, back, m, directions.at(k, l), u, v, frames_ahead, near, q, w);
  }
  bool operator()(const Vec3& m, int i, int j, Vec2& q) const {
    double unused = 0.0;
    return along(m, i, j, i - 0.5, j - 0.5, q, unused);
  }
};

// What each target pixel keeps while the splats are painted: the inverse depth of what it
// shows (-1: nothing yet), the distance of that splat's centre from it and its square, that
// splat's polygon (kNoSplat before any splat reached it), and the source index of the first
// surface splat (polygon >= 0) that won it (kNoSurface while none has).
struct TargetCell {
  double w;
  double dist;   // px
  double dist2;  // px^2, the square dist is the rounded square root of
  int polygon;
  int first;
};
constexpr int kNoSplat = -2;  // no polygon index, nor the background's -1
constexpr int kNoSurface = std::numeric_limits<int>::max();
constexpr TargetCell kFreshCell{-1.0, 0.0, 0.0, kNoSplat, kNoSurface};

// Every source pixel's splat, planned before any is painted: its moved centre and
// extrapolated inverse depth, the pixels its footprint may cover (an empty box: no splat),
// where its corners are (corners_from: the lattice's, its own kept here, or the still
// background's), and per source row the target rows its splats may reach.
enum CornersFrom : char { kLatticeCorners, kOwnCorners, kStillCorners };
struct SplatPlan {
  std::vector<Vec2> centre;
  std::vector<double> w;
  std::vector<PixelBox> boxes;
  std::vector<char> corners_from;  // CornersFrom
  std::vector<std::array<Vec2, 4>> corners;
  std::vector<int> row_first, row_last;  // last < first: the row reaches no target row
};

// The working memory of one generated frame, kept by each thread that generates: a frame's
// buffers are tens of megabytes, and fresh ones cost a page fault per page every frame.
struct GenerationScratch {
  PixelDirections directions;
  StillBackground still;
  StillLines lines;  // prepared where the still background is near its own pixels
  splat::CornerLattice lattice;
  SplatPlan plan;
  std::vector<TargetCell> cells;  // reset by the first pass, band by band
  void prepare(const Camera& camera) {
    const std::size_t n = static_cast<std::size_t>(camera.width) * camera.height;
    directions.prepare(camera);
    lattice.moved.resize(n);
    lattice.ok.resize(n);
    plan.centre.resize(n);
    plan.w.resize(n);
    plan.boxes.resize(n);
    plan.corners_from.resize(n);
    plan.corners.resize(n);  // written only where kOwnCorners
    plan.row_first.assign(static_cast<std::size_t>(camera.height), 0);
    plan.row_last.assign(static_cast<std::size_t>(camera.height), -1);
    cells.resize(n);
  }
};

// Rows per band of the passes over a frame `width` pixels wide.
int min_band_rows(int width) { return std::max(4, 16384 / std::max(width, 1)); }

// The corners of source pixel s = (i, j)'s footprint: where they are the lattice's, the
// lattice points of pixels (i, j), (i + 2, j), (i + 2, j + 2) and (i, j + 2).
std::array<Vec2, 4> planned_corners(const SplatPlan& plan, const splat::CornerLattice& lattice,
                                    const StillBackground& still, int i, int j, std::size_t s,
                                    int width) {
  if (plan.corners_from[s] == kOwnCorners) return plan.corners[s];
  if (plan.corners_from[s] == kStillCorners) return still.corners(i, j);
  const std::size_t below = s + 2 * static_cast<std::size_t>(width);
  return {lattice.moved[s], lattice.moved[s + 2], lattice.moved[below + 2], lattice.moved[below]};
}

// Whether every corner of source pixel s = (i, j)'s footprint (polygon p) is a lattice point
// of polygon p (so splat::move_footprint takes all four from the lattice), and in `moved`
// whether they all moved.
bool lattice_footprint(const DepthFrame& depth, const splat::CornerLattice& lattice, int i, int j,
                       std::size_t s, int p, bool& moved) {
  if (i + 2 >= depth.width || j + 2 >= depth.height) return false;
  const std::size_t below = s + 2 * static_cast<std::size_t>(depth.width);
  if (depth.polygon[s + 2] != p || depth.polygon[below] != p || depth.polygon[below + 2] != p) {
    return false;
  }
  moved = lattice.ok[s] && lattice.ok[s + 2] && lattice.ok[below] && lattice.ok[below + 2];
  return true;
}

// The corner lattice's rows [begin, end) (splat::move_lattice_rows), but the background's
// points under a still background (its splats take their corners from StillBackground, and
// no other splat reads them).
void move_lattice(const DepthFrame& depth, const CornerMove& move, int begin, int end,
                  splat::CornerLattice& lattice) {
  if (!move.still.holds) {
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

// The splats of source rows [begin, end): each centre extrapolated with the pixel's own
// surface, each footprint's corners with the surface of its pixel.
void plan_splat_rows(const DepthFrame& depth, const CornerMove& move, int begin, int end,
                     SplatPlan& plan, const splat::CornerLattice& lattice) {
  for (int j = begin; j < end; ++j) {
    for (int i = 0; i < depth.width; ++i) {
      const std::size_t s = static_cast<std::size_t>(j) * depth.width + i;
      const int p = depth.polygon[s];
      PixelBox& box = plan.boxes[s];
      bool moved = false;
      std::array<Vec2, 4> q{};
      if (move.still.holds && p < 0) {  // see StillBackground
        plan.corners_from[s] = kStillCorners;
        plan.centre[s] = Vec2(move.still.x[i + 1], move.still.y[j + 1]);
        plan.w[s] = 0.0;
        if (!move.still.box(i, j, box)) {
          box = PixelBox{};
          continue;
        }
        splat::reach_rows(box, plan.row_first[j], plan.row_last[j]);
        continue;
      }
      const bool shared = lattice_footprint(depth, lattice, i, j, s, p, moved);
      plan.corners_from[s] = shared ? kLatticeCorners : kOwnCorners;
      if (shared) {
        q = planned_corners(plan, lattice, move.still, i, j, s, depth.width);
      } else {
        moved = splat::move_footprint(lattice, depth, i, j, p, move, q);
        plan.corners[s] = q;
      }
      if (!moved ||
          !move.along(splat::surface_of(depth, p), i + 1, j + 1, i + 0.5, j + 0.5, plan.centre[s],
                      plan.w[s]) ||
          !splat::footprint_box(q, depth.width, depth.height, box)) {
        box = PixelBox{};
        continue;
      }
      splat::reach_rows(box, plan.row_first[j], plan.row_last[j]);
    }
  }
}

// One planned splat being painted: what it gives the pixels it wins, and the rule it wins
// by: the nearest surface, and among one polygon's splats the one whose centre lands nearest.
struct SplatPainter {
  Vec2 centre;
  double w;
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
    if (!same && w <= t.w) return 0;
    // The distance is glm::length's, sqrt(dot): a rounded square root never decreases as its
    // argument grows, so a square at least t.dist2 gives a distance at least t.dist, and the
    // root is taken only where the square is smaller (equal roots then still lose).
    const Vec2 offset = Vec2(cx, cy) - centre;
    const double e2 = glm::dot(offset, offset);
    if (same && e2 >= t.dist2) return 0;
    const double e = std::sqrt(e2);
    if (same && e >= t.dist) return 0;
    t = TargetCell{w, e, e2, polygon, polygon >= 0 && t.polygon < 0 ? source : t.first};
    image[d] = colour;
    shown[d] = source;
    return 1;
  }
};

// The widest box painted by the axis-aligned path (wider ones take the general).
constexpr int kAlignedColumns = 16;

// Paints source pixel s's planned splat over target rows [y0, y1] of its box (SplatPainter);
// an axis-aligned footprint (splat::axis_aligned: the background's under a step without
// rotation) with its inside test split into each row's and each column's, the same answers.
// Returns the pixels written.
std::int64_t paint_splat(const SplatPlan& plan, const splat::CornerLattice& lattice,
                         const StillBackground& still, int i, int j, int polygon, Pixel colour,
                         int y0, int y1, int width, TargetCell* cells, GeneratedFrame& g) {
  const std::size_t s = static_cast<std::size_t>(j) * width + i;
  const PixelBox& box = plan.boxes[s];
  const std::array<Vec2, 4> q = planned_corners(plan, lattice, still, i, j, s, width);
  const std::array<Vec2, 4> edge = splat::footprint_edges(q);
  const SplatPainter splat{plan.centre[s],          plan.w[s],      polygon,
                           static_cast<int>(s),     colour,         cells,
                           g.image.pixels().data(), g.source.data()};
  std::int64_t written = 0;
  if (splat::axis_aligned(edge) && box.x_end - box.x_begin < kAlignedColumns) {
    int columns[kAlignedColumns];
    for (int x = box.x_begin; x <= box.x_end; ++x) {
      columns[x - box.x_begin] = splat::column_sides(q, edge, x + 0.5);
    }
    for (int y = y0; y <= y1; ++y) {
      const double cy = y + 0.5;
      const int row = splat::row_sides(q, edge, cy);
      const std::size_t first = static_cast<std::size_t>(y) * width;
      for (int x = box.x_begin; x <= box.x_end && row; ++x) {
        if (row & columns[x - box.x_begin]) written += splat.paint(first + x, x + 0.5, cy);
      }
    }
    return written;
  }
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

// What the still background's splats of the 3 x 3 source pixels around one target pixel do
// (pick_still): the cell they leave, the one that shows (3 n + m: source pixel
// (x - 1 + m, y - 1 + n); -1: none) and the writes.
struct StillPick {
  TargetCell best = kFreshCell;
  int shown = -1;
  int written = 0;
};

// What usable(m, n) says of a still-background splat around a target pixel.
enum class StillSplat { kSkipped, kUsable, kHeld };

// The still background's splats around a target pixel met in source order, each tested and
// compared as paint_splat's aligned path and SplatPainter::paint do from a fresh cell: splat
// (m, n) (source pixel (x - 1 + m, y - 1 + n)) counts where its lines (StillLines) reach the
// pixel, usable(m, n) says so (kHeld: a surface holds the pixel from this splat on, which
// ends the search) and it covers the pixel centre (inside(m, n) decides where the lines leave
// that undecided).
template <typename Usable, typename Inside>
StillPick pick_still(const splat::GridLine* rows3, const splat::GridLine* columns3,
                     const Usable& usable, const Inside& inside) {
  StillPick pick;
  splat::for_each_reaching_splat(
      rows3, columns3,
      [&](int m, int n, const splat::GridLine& row, const splat::GridLine& column) {
        const StillSplat use = usable(m, n);
        if (use == StillSplat::kHeld) return false;
        if (use == StillSplat::kSkipped ||
            !splat::covers(row, column, [&] { return inside(m, n); })) {
          return true;
        }
        // SplatPainter::paint from a fresh cell; glm::dot of the offset with itself is the two
        // squares' sum.
        const bool same = pick.best.polygon == -1;  // background after background
        if (!same && 0.0 <= pick.best.w) return true;
        const double e2 = column.offset2 + row.offset2;
        if (same && e2 >= pick.best.dist2) return true;
        const double e = std::sqrt(e2);
        if (same && e >= pick.best.dist) return true;
        pick.best = TargetCell{0.0, e, e2, -1, kNoSurface};
        pick.shown = 3 * n + m;
        ++pick.written;
        return true;
      });
  return pick;
}

// Paints the still background's splats over target rows [y_begin, y_end) (StillBackground
// holds, near_own), pixel by pixel, after the surfaces' splats (paint_target_rows leaves them
// out): a surface splat always wins over the background (its inverse depth is above 0) and
// the background never over a surface, so a pixel's background splats count only before the
// first surface splat that won it (TargetCell::first), and they are those of the 3 x 3 source
// pixels around it, met in source order (pick_still; made once per run of columns with the
// same lines where they are all the background's: splat::paint_grid_pixels). The same frame,
// sources and count as painting them in source order among the surfaces' (the test's
// one-pass reference). Returns the pixels written.
std::int64_t paint_still_background_rows(const StillBackground& still, const StillLines& lines,
                                         const DepthFrame& depth, const Image& rendered,
                                         int y_begin, int y_end, TargetCell* cells,
                                         GeneratedFrame& g) {
  using Line = splat::GridLine;
  const int width = depth.width;
  const auto free = [cells](std::size_t d) { return cells[d].first == kNoSurface; };
  const auto pick = [&](int x, int y, const Line* rows3, const Line* columns3,
                        bool all_background) -> StillPick {
    if (all_background) {
      return pick_still(
          rows3, columns3, [](int, int) { return StillSplat::kUsable; },
          [](int, int) { return false; });
    }
    const int first = cells[static_cast<std::size_t>(y) * width + x].first;
    return pick_still(
        rows3, columns3,
        [&](int m, int n) {
          const int s = splat::around(x, y, width, m, n);
          if (s >= first) return StillSplat::kHeld;
          return depth.polygon[s] >= 0 ? StillSplat::kSkipped : StillSplat::kUsable;
        },
        [&](int m, int n) {
          const std::array<Vec2, 4> q = still.corners(x - 1 + m, y - 1 + n);
          const std::array<Vec2, 4> edge = splat::footprint_edges(q);
          return (splat::row_sides(q, edge, y + 0.5) & splat::column_sides(q, edge, x + 0.5)) != 0;
        });
  };
  std::int64_t written = 0;
  const auto paint = [&](std::size_t d, int x, int y, const StillPick& picked) {
    written += picked.written;
    if (!free(d) || picked.shown < 0) return;  // a surface shows, or nothing
    const int shown = splat::around(x, y, width, picked.shown);
    cells[d] = picked.best;
    g.image.pixels()[d] = rendered.pixels()[static_cast<std::size_t>(shown)];
    g.source[d] = shown;
  };
  splat::paint_grid_pixels(lines.rows, lines.columns, depth.polygon, width, depth.height, y_begin,
                           y_end, free, pick, paint);
  return written;
}

// Paints every planned splat into target rows [y_begin, y_end), in source order (so each
// pixel sees its splats in the order one pass over the source paints them); with `lines`
// (StillLines::prepare), the still background's after the surfaces' instead
// (paint_still_background_rows). Returns the pixels written.
std::int64_t paint_target_rows(const SplatPlan& plan, const splat::CornerLattice& lattice,
                               const StillBackground& still, const StillLines* lines,
                               const Image& rendered, const DepthFrame& depth, int y_begin,
                               int y_end, TargetCell* cells, GeneratedFrame& g) {
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
      if (lines && plan.corners_from[s] == kStillCorners) continue;
      written += paint_splat(plan, lattice, still, i, j, depth.polygon[s], rendered.pixels()[s],
                             std::max(box.y_begin, y_begin), std::min(box.y_end, y_end - 1),
                             depth.width, cells, g);
    }
  }
  if (lines) {
    written +=
        paint_still_background_rows(still, *lines, depth, rendered, y_begin, y_end, cells, g);
  }
  return written;
}

// The mask of target rows [begin, end): the unreached pixels (already marked on every row)
// grown by one pixel (3 x 3), as the rows' columns ORed over the three rows, then over the
// three columns. Returns the mask's pixels in those rows.
std::int64_t mask_rows(int width, int height, int begin, int end, GeneratedFrame& g) {
  thread_local std::vector<char> column;  // per column: unreached in rows y - 1 .. y + 1
  column.resize(static_cast<std::size_t>(width));
  std::int64_t masked = 0;
  for (int y = begin; y < end; ++y) {
    const char* above = g.unreached.data() + static_cast<std::size_t>(std::max(0, y - 1)) * width;
    const char* row = g.unreached.data() + static_cast<std::size_t>(y) * width;
    const char* below =
        g.unreached.data() + static_cast<std::size_t>(std::min(height - 1, y + 1)) * width;
    for (int x = 0; x < width; ++x) column[x] = above[x] | row[x] | below[x];
    char* out = g.mask.data() + static_cast<std::size_t>(y) * width;
    for (int x = 0; x < width; ++x) {
      out[x] = column[std::max(0, x - 1)] | column[x] | column[std::min(width - 1, x + 1)];
      masked += out[x];
    }
  }
  return masked;
}

// The largest, the sum and the count of the displacement errors of some pixels.
// The displacement error (against the true step) of the pixels of target rows [begin, end)
// that show a surface: their largest, sum and count.
splat::ErrorTally measure_error_rows(const DepthFrame& depth, const PixelDirections& directions,
                                     const Camera& camera, const RigidStep3& truth,
                                     const GeneratedFrame& g, int begin, int end) {
  const int width = depth.width;
  splat::ErrorTally t;  // kept here, not in the caller's per-band slots: those share cache lines
  for (int y = begin; y < end; ++y) {
    for (int x = 0; x < width; ++x) {
      const int s = g.source[static_cast<std::size_t>(y) * width + x];
      if (s < 0 || depth.polygon[s] < 0) continue;  // the background has no position error
      const int i = s % width, j = s / width;
      const Vec3 p = truth.rotation * (directions.at(i + 1, j + 1) / depth.inverse_depth[s]) +
                     truth.translation;
      if (!(p.z > 0.0)) continue;
      const double e = glm::length(Vec2(x + 0.5, y + 0.5) - project(camera, p));
      t.max = std::max(t.max, e);
      t.sum += e;
      ++t.surfaces;
    }
  }
  return t;
}

}  // namespace

bool extrapolate_point(const Camera& camera, const RigidStep3& back, const Vec3& m, double u,
                       double v, int frames_ahead, double near, Vec2& moved, double& moved_w) {
  return extrapolate_along(camera, back, m, pixel_direction(camera, u, v), u, v, frames_ahead, near,
                           moved, moved_w);
}

GeneratedFrame extrapolate_by_motion(const Image& rendered, const DepthFrame& depth,
                                     const Camera& camera, const RigidStep3& back, int frames_ahead,
                                     bool inpaint, double near) {
  const int width = camera.width, height = camera.height;
  const std::size_t n = static_cast<std::size_t>(width) * height;
  GeneratedFrame g;
  g.image = Image(width, height);
  g.source.assign(n, -1);
  g.unreached.resize(n);
  g.mask.resize(n);
  g.source_pixels = static_cast<std::int64_t>(n);
  thread_local GenerationScratch scratch;
  scratch.prepare(camera);
  // (The bands reach the scratch through these references: on a worker thread the name
  // `scratch` is that thread's own.)
  splat::CornerLattice& lattice = scratch.lattice;
  SplatPlan& plan = scratch.plan;
  TargetCell* cells = scratch.cells.data();
  const int k = std::max(1, frames_ahead);
  scratch.still.prepare(camera, scratch.directions, back, k);
  const StillBackground& scratch_still = scratch.still;
  const StillLines* still_lines = scratch.lines.prepare(scratch.still);
  const CornerMove move{camera, scratch.directions, scratch_still, back, k, near};
  // Passes over bands of rows cut by the frame's size alone, each band writing only its own
  // rows, every tally summed in band order: the same frame on any number of threads.
  const int min_rows = min_band_rows(width);
  const std::size_t bands = static_cast<std::size_t>(band_count(height, min_rows));
  for_each_band(height, min_rows, [&](int, int begin, int end) {
    std::fill(cells + static_cast<std::ptrdiff_t>(begin) * width,
              cells + static_cast<std::ptrdiff_t>(end) * width, kFreshCell);
    move_lattice(depth, move, begin, end, lattice);
  });
  for_each_band(height, min_rows, [&](int, int begin, int end) {
    plan_splat_rows(depth, move, begin, end, plan, lattice);
  });
  std::vector<std::int64_t> written(bands, 0), holes(bands, 0), masked(bands, 0);
  for_each_band(height, min_rows, [&](int band, int begin, int end) {
    written[band] = paint_target_rows(plan, lattice, scratch_still, still_lines, rendered, depth,
                                      begin, end, cells, g);
    std::int64_t unreached = 0;
    for (std::size_t d = static_cast<std::size_t>(begin) * width;
         d < static_cast<std::size_t>(end) * width; ++d) {
      g.unreached[d] = g.source[d] < 0;
      unreached += g.unreached[d];
    }
    holes[band] = unreached;  // once: the bands' slots share cache lines
  });
  for_each_band(height, min_rows, [&](int band, int begin, int end) {
    masked[band] = mask_rows(width, height, begin, end, g);
  });
  for (std::size_t b = 0; b < bands; ++b) {
    g.pixels_written += written[b];
    g.hole_pixels += holes[b];
    g.mask_pixels += masked[b];
  }
  if (inpaint) g.inpainted_pixels = push_pull_inpaint(g.image, g.unreached);
  return g;
}

void measure_generated_frame(const DepthFrame& depth, const Camera& camera, const RigidStep3& truth,
                             const DepthFrame& now, GeneratedFrame& g) {
  thread_local PixelDirections directions;
  directions.prepare(camera);
  const PixelDirections& table = directions;  // this thread's, for the bands
  const int min_rows = min_band_rows(depth.width);
  const std::size_t bands = static_cast<std::size_t>(band_count(depth.height, min_rows));
  std::vector<std::int64_t> holes(bands, 0);
  std::vector<splat::ErrorTally> errors(bands);
  for_each_band(depth.height, min_rows, [&](int band, int begin, int end) {
    std::int64_t seen = 0;  // summed here: the bands' slots share cache lines
    for (std::size_t d = static_cast<std::size_t>(begin) * depth.width;
         d < static_cast<std::size_t>(end) * depth.width; ++d) {
      seen += g.unreached[d] && now.polygon[d] >= 0;
    }
    holes[band] = seen;
    errors[band] = measure_error_rows(depth, table, camera, truth, g, begin, end);
  });
  g.hole_pixels = 0;
  g.max_error_px = 0.0;
  g.mean_error_px = 0.0;
  for (std::size_t b = 0; b < bands; ++b) g.hole_pixels += holes[b];
  splat::add_error_bands(errors, &g.max_error_px, &g.mean_error_px);
}

}  // namespace oflab
