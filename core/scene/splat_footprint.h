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
#include <cstdint>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

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

// The directions through the pixel corners and centres of a camera, by column and by row:
// x[k] = ((k - 0.5) - cx) / f and y[k] = ((k - 0.5) - cy) / f, k = 0 .. size + 1, so that the
// top-left corner of pixel (i, j) looks along (x[i], y[j], 1) and its centre along
// (x[i + 1], y[j + 1], 1): pixel_direction's arithmetic, so the same bits, once per frame
// rather than once per pixel.
struct PixelDirections {
  std::vector<double> x, y;
  void prepare(const Camera& camera) {
    const auto fill = [&](std::vector<double>& to, int size, double centre) {
      to.resize(static_cast<std::size_t>(size) + 2);
      for (int k = 0; k < size + 2; ++k) to[k] = ((k - 0.5) - centre) / camera.focal_px;
    };
    fill(x, camera.width, camera.cx);
    fill(y, camera.height, camera.cy);
  }
  // The direction (x[k], y[l], 1): through the top-left corner of pixel (k, l), or the
  // centre of pixel (k - 1, l - 1).
  Vec3 at(int k, int l) const { return Vec3(x[k], y[l], 1.0); }
};

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
// move(m, i, j, q) moves the top-left corner of pixel (i, j) (top-left pixel position
// (i - 0.5, j - 0.5)) with plane vector m (0: the background) into q, false when it cannot.
template <class Move>
void move_lattice_rows(const DepthFrame& depth, int begin, int end, const Move& move,
                       CornerLattice& lattice) {
  for (int j = begin; j < end; ++j) {
    for (int i = 0; i < depth.width; ++i) {
      const std::size_t k = static_cast<std::size_t>(j) * depth.width + i;
      lattice.ok[k] = move(surface_of(depth, depth.polygon[k]), i, j, lattice.moved[k]);
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
  return move(surface_of(depth, p), i, j, q);
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

// Widens the target rows [first, last] a source row's splats reach (last < first: none yet)
// by `box`'s rows.
inline void reach_rows(const PixelBox& box, int& first, int& last) {
  first = last < first ? box.y_begin : std::min(first, box.y_begin);
  last = std::max(last, box.y_end);
}

// The per-pixel errors of one band of rows (pixels): the largest, their sum and how many.
struct ErrorTally {
  double max = 0.0, sum = 0.0;
  std::int64_t surfaces = 0;
};

// The bands' tallies taken in band order: *max_px becomes the largest of it and theirs, and
// *mean_px the mean over every pixel counted (left as it is when none was).
inline void add_error_bands(const std::vector<ErrorTally>& bands, double* max_px, double* mean_px) {
  double total = 0.0;
  std::int64_t count = 0;
  for (const ErrorTally& b : bands) {
    *max_px = std::max(*max_px, b.max);
    total += b.sum;
    count += b.surfaces;
  }
  if (count > 0) *mean_px = total / static_cast<double>(count);
}

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

// inside_footprint for the pixel centres of one target row: the same arithmetic, so the same
// answers to the bit, with each edge's term in c.y computed once for the row and, where SSE2
// is there, two edges at a time (IEEE double lanes: the same roundings as one at a time).
class FootprintRow {
 public:
  // Footprint q with edges `edge` (footprint_edges) on the row of pixel centres at y = cy.
  FootprintRow(const std::array<Vec2, 4>& q, const std::array<Vec2, 4>& edge, double cy) {
#if defined(__SSE2__)
    qx_[0] = _mm_set_pd(q[1].x, q[0].x), qx_[1] = _mm_set_pd(q[3].x, q[2].x);
    ey_[0] = _mm_set_pd(edge[1].y, edge[0].y), ey_[1] = _mm_set_pd(edge[3].y, edge[2].y);
    const __m128d c = _mm_set1_pd(cy);
    across_[0] =
        _mm_mul_pd(_mm_set_pd(edge[1].x, edge[0].x), _mm_sub_pd(c, _mm_set_pd(q[1].y, q[0].y)));
    across_[1] =
        _mm_mul_pd(_mm_set_pd(edge[3].x, edge[2].x), _mm_sub_pd(c, _mm_set_pd(q[3].y, q[2].y)));
#else
    for (int e = 0; e < 4; ++e) {
      qx_[e] = q[e].x, ey_[e] = edge[e].y, across_[e] = edge[e].x * (cy - q[e].y);
    }
#endif
  }
  // Whether the point (cx, cy) lies in the footprint, as inside_footprint says.
  bool holds(double cx) const {
#if defined(__SSE2__)
    const __m128d c = _mm_set1_pd(cx);
    const __m128d k0 = _mm_sub_pd(across_[0], _mm_mul_pd(ey_[0], _mm_sub_pd(c, qx_[0])));
    const __m128d k1 = _mm_sub_pd(across_[1], _mm_mul_pd(ey_[1], _mm_sub_pd(c, qx_[1])));
    const __m128d low = _mm_set1_pd(-1e-9), high = _mm_set1_pd(1e-9);
    const int positive = _mm_movemask_pd(_mm_and_pd(_mm_cmpge_pd(k0, low), _mm_cmpge_pd(k1, low)));
    const int negative =
        _mm_movemask_pd(_mm_and_pd(_mm_cmple_pd(k0, high), _mm_cmple_pd(k1, high)));
    return positive == 3 || negative == 3;
#else
    bool positive = true, negative = true;
    for (int e = 0; e < 4; ++e) {
      const double k = across_[e] - ey_[e] * (cx - qx_[e]);
      positive = positive && k >= -1e-9;
      negative = negative && k <= 1e-9;
    }
    return positive || negative;
#endif
  }

 private:
#if defined(__SSE2__)
  __m128d qx_[2], ey_[2], across_[2];  // edges 0 and 1, edges 2 and 3
#else
  double qx_[4], ey_[4], across_[4];
#endif
};

// Whether footprint edges `edge` (footprint_edges) run along the pixel axes exactly: 0 and 2
// horizontal, 1 and 3 vertical (the background's footprints under a step without rotation).
inline bool axis_aligned(const std::array<Vec2, 4>& edge) {
  return edge[0].y == 0.0 && edge[2].y == 0.0 && edge[1].x == 0.0 && edge[3].x == 0.0;
}

// inside_footprint of an axis_aligned footprint, split: the tests of its horizontal edges
// depend on c.y alone (their c.x term is an exact zero), those of its vertical edges on c.x
// alone, with the same arithmetic otherwise, so the same answers to the bit. Each gives bit
// 0 when its two edges' k >= -1e-9, bit 1 when both k <= 1e-9; c is inside where
// row_sides(c.y) & column_sides(c.x) is not 0.
inline int row_sides(const std::array<Vec2, 4>& q, const std::array<Vec2, 4>& edge, double cy) {
  const double k0 = edge[0].x * (cy - q[0].y), k2 = edge[2].x * (cy - q[2].y);
  return static_cast<int>((k0 >= -1e-9) & (k2 >= -1e-9)) |
         static_cast<int>((k0 <= 1e-9) & (k2 <= 1e-9)) << 1;
}
inline int column_sides(const std::array<Vec2, 4>& q, const std::array<Vec2, 4>& edge, double cx) {
  const double k1 = -(edge[1].y * (cx - q[1].x)), k3 = -(edge[3].y * (cx - q[3].x));
  return static_cast<int>((k1 >= -1e-9) & (k3 >= -1e-9)) |
         static_cast<int>((k1 <= 1e-9) & (k3 <= 1e-9)) << 1;
}

// A target line's (row's or column's) view of one neighbouring splat line (k - 1, k, k + 1)
// of a grid of axis-aligned footprints (the background's under a step without rotation:
// depth reprojection's BackgroundGrid, frame generation's still background): the sides bits
// of the footprint's two edges across it (row_sides, column_sides), 0 where the splat's box
// misses the line, kUndecidedSides where they depend on the splat's extent along the other
// axis; and the square of the centre's offset along it.
struct GridLine {
  int sides = 0;
  double offset2 = 0.0;
};
constexpr int kUndecidedSides = 4;

// The GridLines of every target line along `at` (the grid's corner lines, k = 0 .. size + 1;
// the other axis `across`), 3 per target line, splat line k - 1 first. Rows (horizontal edges
// 0 and 2): k = edge.x * (c - q.y), anchors at[j] and at[j + 2], edge.x over every splat
// column; columns (vertical edges 1 and 3): k = -(edge.y * (c - q.x)), anchors at[i + 2] and
// at[i]. A product rounds monotonically in each factor, so where the tests agree at both ends
// of an edge's range they hold for every splat of the line. The boxes are footprint_box's.
inline void grid_lines(const std::vector<double>& at, const std::vector<double>& across, bool rows,
                       std::vector<GridLine>& out) {
  const int size = static_cast<int>(at.size()) - 2, other = static_cast<int>(across.size()) - 2;
  double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
  for (int k = 0; k < other; ++k) {
    const double slope[2] = {across[k + 2] - across[k], across[k] - across[k + 2]};
    for (int e = 0; e < 2; ++e)
      lo[e] = std::min(lo[e], slope[e]), hi[e] = std::max(hi[e], slope[e]);
  }
  out.assign(static_cast<std::size_t>(size) * 3, GridLine{});
  for (int t = 0; t < size; ++t) {
    const double c = t + 0.5;
    for (int n = 0; n < 3; ++n) {
      const int k = t - 1 + n;
      if (k < 0 || k >= size) continue;
      const double lo_box = std::min(at[k], at[k + 2]), hi_box = std::max(at[k], at[k + 2]);
      if (t < std::max(0, static_cast<int>(std::ceil(lo_box - 0.5))) ||  // as footprint_box
          t > std::min(size - 1, static_cast<int>(std::floor(hi_box - 0.5)))) {
        continue;
      }
      const double anchor[2] = {rows ? at[k] : at[k + 2], rows ? at[k + 2] : at[k]};
      int both[2] = {0, 0};  // the sides bits at each end of the slopes' ranges
      for (int end = 0; end < 2; ++end) {
        double kk[2];
        for (int e = 0; e < 2; ++e) {
          const double v = (end ? hi[e] : lo[e]) * (c - anchor[e]);
          kk[e] = rows ? v : -v;
        }
        both[end] = static_cast<int>((kk[0] >= -1e-9) & (kk[1] >= -1e-9)) |
                    static_cast<int>((kk[0] <= 1e-9) & (kk[1] <= 1e-9)) << 1 |
                    static_cast<int>(kk[0] >= -1e-9) << 2 | static_cast<int>(kk[1] >= -1e-9) << 3 |
                    static_cast<int>(kk[0] <= 1e-9) << 4 | static_cast<int>(kk[1] <= 1e-9) << 5;
      }
      GridLine& line = out[static_cast<std::size_t>(t) * 3 + n];
      line.sides = both[0] == both[1] ? both[0] & 3 : kUndecidedSides;
      const double offset = c - at[k + 1];
      line.offset2 = offset * offset;
    }
  }
}

// Whether three lines (a target line's view of its three splat lines) all decide their sides.
inline bool lines_decide(const GridLine* lines) {
  for (int k = 0; k < 3; ++k) {
    if (lines[k].sides == kUndecidedSides) return false;
  }
  return true;
}

// Whether two targets' three lines are the same, sides and offsets.
inline bool same_lines(const GridLine* a, const GridLine* b) {
  for (int k = 0; k < 3; ++k) {
    if (a[k].sides != b[k].sides || !(a[k].offset2 == b[k].offset2)) return false;
  }
  return true;
}

// Per target column x (1 .. width - 2) whose three lines (`columns`, grid_lines') decide: the
// first column of its run of neighbouring columns with the same lines; -1 elsewhere. Where a
// target pixel's splats are all the background's, what they paint depends on its six lines
// alone, so it is the same along such a run (under a translation, every column's lines are
// the same).
inline void column_runs(const std::vector<GridLine>& columns, int width, std::vector<int>& run_of) {
  run_of.assign(static_cast<std::size_t>(width), -1);
  for (int x = 1; x + 1 < width; ++x) {
    const GridLine* lines = &columns[static_cast<std::size_t>(x) * 3];
    if (!lines_decide(lines)) continue;
    const int previous = run_of[static_cast<std::size_t>(x) - 1];
    run_of[static_cast<std::size_t>(x)] =
        previous >= 0 && same_lines(lines - 3, lines) ? previous : x;
  }
}

// Per source row j of [top, bottom] and column x (1 .. width - 2) of `polygon` (row-major,
// `width` a row; -1 the background): 1 where source pixels x - 1 .. x + 1 of row j are all
// background, into out[(j - top) * width + x] (0 in columns 0 and width - 1).
inline void background_threes(const std::vector<int>& polygon, int width, int top, int bottom,
                              std::vector<unsigned char>& out) {
  out.assign(static_cast<std::size_t>(std::max(bottom - top + 1, 0)) * width, 0);
  for (int j = top; j <= bottom; ++j) {
    const int* p = polygon.data() + static_cast<std::size_t>(j) * width;
    unsigned char* t = out.data() + static_cast<std::size_t>(j - top) * width;
    for (int x = 1; x + 1 < width; ++x) t[x] = (p[x - 1] == -1) & (p[x] == -1) & (p[x + 1] == -1);
  }
}

// The index (row-major, `width` a row) of source pixel (x - 1 + m, y - 1 + n), splat (m, n) of
// the 3 x 3 around target pixel (x, y); around(x, y, width, k) takes k = 3 n + m.
inline int around(int x, int y, int width, int m, int n) { return (y - 1 + n) * width + x - 1 + m; }
inline int around(int x, int y, int width, int k) { return around(x, y, width, k % 3, k / 3); }

// Calls visit(m, n, row, column) for the splats of the 3 x 3 source pixels around a target
// pixel whose lines both reach it (row line rows3[n] and column line columns3[m] with sides),
// in source order (n, then m), until visit returns false.
template <typename Visit>
void for_each_reaching_splat(const GridLine* rows3, const GridLine* columns3, const Visit& visit) {
  for (int n = 0; n < 3; ++n) {
    if (!rows3[n].sides) continue;
    for (int m = 0; m < 3; ++m) {
      if (!columns3[m].sides) continue;
      if (!visit(m, n, rows3[n], columns3[m])) return;
    }
  }
}

// Whether a splat reaching a target pixel (its lines `row` and `column`) covers the pixel's
// centre: the lines' sides where they decide, inside() where they leave it undecided.
template <typename Inside>
bool covers(const GridLine& row, const GridLine& column, const Inside& inside) {
  return ((row.sides | column.sides) & kUndecidedSides) ? inside()
                                                        : (row.sides & column.sides) != 0;
}

// The grid's splats painted pixel by pixel over target rows [y_begin, y_end) (depth
// reprojection's background, frame generation's still background): for each target pixel
// (x, y), d = y * width + x, pick(x, y, rows3, columns3, all_background) says what its splats
// do, and paint(d, x, y, picked) applies it. all_background is true where the pixel is away
// from the frame's edge, free(d) holds (no surface splat reached it), the 3 x 3 source pixels
// around it are all background in `polygon` and its six lines decide: there the pick may
// depend on the lines alone, and it is made once for each run of columns with the same lines
// (column_runs) and reused along the row.
template <typename Free, typename Pick, typename Paint>
void paint_grid_pixels(const std::vector<GridLine>& rows, const std::vector<GridLine>& columns,
                       const std::vector<int>& polygon, int width, int height, int y_begin,
                       int y_end, const Free& free, const Pick& pick, const Paint& paint) {
  thread_local std::vector<unsigned char> three;
  const int top = std::max(y_begin - 1, 0), bottom = std::min(y_end, height - 1);
  background_threes(polygon, width, top, bottom, three);
  thread_local std::vector<int> run_of;
  column_runs(columns, width, run_of);
  for (int y = y_begin; y < y_end; ++y) {
    const GridLine* rows3 = &rows[static_cast<std::size_t>(y) * 3];
    const bool inner_row = y >= 1 && y + 1 < height && lines_decide(rows3);
    const unsigned char* above =
        inner_row ? &three[static_cast<std::size_t>(y - 1 - top) * width] : nullptr;
    int picked_run = -1;  // the run of columns `picked` was made for
    decltype(pick(0, 0, rows3, rows3, true)) picked{};
    for (int x = 0; x < width; ++x) {
      const std::size_t d = static_cast<std::size_t>(y) * width + x;
      const GridLine* columns3 = &columns[static_cast<std::size_t>(x) * 3];
      const int run = run_of[static_cast<std::size_t>(x)];
      if (inner_row && run >= 0 && above[x] && above[x + width] && above[x + 2 * width] &&
          free(d)) {
        if (run != picked_run) picked = pick(x, y, rows3, columns3, true), picked_run = run;
        paint(d, x, y, picked);
      } else {
        paint(d, x, y, pick(x, y, rows3, columns3, false));
      }
    }
  }
}

}  // namespace splat
}  // namespace oflab
