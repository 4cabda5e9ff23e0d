// Covering test by convex subtraction (see core/scene/occlusion.h).
#include "scene/occlusion.h"

#include <algorithm>
#include <cmath>

namespace oflab {
namespace {

constexpr double kNegligibleArea = 1e-6;  // square pixels
constexpr std::size_t kMaxPieces = 256;

// The line of edge a -> b of a polygon with positive signed area (core/image/polygon.h), as
// (l.x, l.y, l.z) with l.x x + l.y y + l.z >= 0 inside and |(l.x, l.y)| = 1.
Vec3 inside_line(const Vec2& a, const Vec2& b) {
  const Vec2 e = b - a;
  const double length = glm::length(e);
  return Vec3(-e.y, e.x, e.y * a.x - e.x * a.y) / length;
}

bool boxes_overlap(const BoundingBox& a, const BoundingBox& b) {
  return a.x_min < b.x_max && b.x_min < a.x_max && a.y_min < b.y_max && b.y_min < a.y_max;
}

double cross(const Vec2& o, const Vec2& a, const Vec2& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

}  // namespace

ConvexPolygon eroded(const ConvexPolygon& polygon, double margin) {
  if (polygon.empty()) return ConvexPolygon();
  const std::vector<Vec2>& v = polygon.vertices();
  const std::size_t n = v.size();
  std::vector<Vec3> lines;  // every edge's inside line, moved inwards by the margin
  lines.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2& a = v[k];
    const Vec2& b = v[next_vertex(k, n)];
    if (glm::length(b - a) <= 0.0) continue;
    const Vec3 line = inside_line(a, b);
    lines.emplace_back(line.x, line.y, line.z - margin);
  }
  // Usually every edge survives: each new vertex is where neighbouring moved lines meet.
  // Accepted only if it satisfies every moved line; otherwise (an edge vanished) clip.
  std::vector<Vec2> out;
  out.reserve(lines.size());
  bool valid = lines.size() >= 3;
  for (std::size_t k = 0; k < lines.size() && valid; ++k) {
    const Vec3& p = lines[(k + lines.size() - 1) % lines.size()];
    const Vec3& q = lines[k];
    const double det = p.x * q.y - p.y * q.x;
    if (std::abs(det) < 1e-12) {
      valid = false;
      break;
    }
    const Vec2 x((p.y * q.z - q.y * p.z) / det, (q.x * p.z - p.x * q.z) / det);
    for (const Vec3& l : lines) valid = valid && l.x * x.x + l.y * x.y + l.z >= -1e-9;
    out.push_back(x);
  }
  if (valid) {
    ConvexPolygon result = make_polygon_unchecked(std::move(out));
    if (!result.empty()) return result;
  }
  ConvexPolygon result = polygon;
  for (const Vec3& line : lines) {
    result = clip_to_half_plane(result, line);
    if (result.empty()) return ConvexPolygon();
  }
  return result;
}

ConvexPolygon dilated(const ConvexPolygon& polygon, double margin) {
  if (polygon.empty()) return ConvexPolygon();
  std::vector<Vec2> points;
  for (const Vec2& p : polygon.vertices()) {
    for (double dx : {-margin, margin}) {
      for (double dy : {-margin, margin}) points.emplace_back(p.x + dx, p.y + dy);
    }
  }
  // Andrew's monotone chain.
  std::sort(points.begin(), points.end(),
            [](const Vec2& a, const Vec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  std::vector<Vec2> hull(2 * points.size());
  std::size_t k = 0;
  for (const Vec2& p : points) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p) <= 0.0) --k;
    hull[k++] = p;
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0.0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return make_polygon_unchecked(std::move(hull));
}

struct CellRange {
  int x0, y0, x1, y1;
  bool in_grid;
  long count() const { return static_cast<long>(x1 - x0 + 1) * (y1 - y0 + 1); }
};

CellRange cell_range(const BoundingBox& box, const Vec2& origin, const Vec2& cell, int cells) {
  auto index = [](double v, double o, double c) {
    return static_cast<long>(std::floor((std::clamp(v, -1e9, 1e9) - o) / c));
  };
  const long x0 = index(box.x_min, origin.x, cell.x), y0 = index(box.y_min, origin.y, cell.y);
  const long x1 = index(box.x_max, origin.x, cell.x), y1 = index(box.y_max, origin.y, cell.y);
  const bool in_grid = x0 >= 0 && y0 >= 0 && x1 < cells && y1 < cells;
  auto clamp = [cells](long i) { return static_cast<int>(std::clamp(i, 0L, cells - 1L)); };
  return {clamp(x0), clamp(y0), clamp(x1), clamp(y1), in_grid};
}

void OcclusionTest::clear(int width, int height) {
  occluders_.clear();
  for (int c : touched_) cells_[c].clear();
  touched_.clear();
  wide_.clear();
  const Vec2 size(std::max(width, 1), std::max(height, 1));
  grid_.origin = -size;
  grid_.cell = 3.0 * size / static_cast<double>(kGridCells);
}

bool OcclusionTest::make_occluder(const ConvexPolygon& region, double inset, Vec2 offset,
                                  Occluder& o) {
  if (region.empty()) return false;
  const std::vector<Vec2>& v = region.vertices();
  o.lines.reserve(v.size());
  for (std::size_t k = 0; k < v.size(); ++k) {
    const Vec2 a = v[k] + offset;
    const Vec2 b = v[next_vertex(k, v.size())] + offset;
    if (glm::length(b - a) <= 0.0) continue;
    const Vec3 line = inside_line(a, b);
    o.lines.emplace_back(line.x, line.y, line.z - inset);
  }
  const BoundingBox b = region.bounds();
  o.box = {b.x_min + offset.x + inset, b.y_min + offset.y + inset, b.x_max + offset.x - inset,
           b.y_max + offset.y - inset};
  return o.box.x_min < o.box.x_max && o.box.y_min < o.box.y_max;  // else eroded away
}

void OcclusionTest::add_occluder(const ConvexPolygon& region, double inset, Vec2 offset) {
  Occluder o;
  if (!make_occluder(region, inset, offset, o)) return;
  const int index = static_cast<int>(occluders_.size());
  occluders_.push_back(std::move(o));
  const CellRange r = cell_range(occluders_.back().box, grid_.origin, grid_.cell, kGridCells);
  if (!r.in_grid || r.count() > kMaxCellsPerOccluder) {
    wide_.push_back(index);
    return;
  }
  if (cells_.empty()) cells_.resize(static_cast<std::size_t>(kGridCells) * kGridCells);
  for (int y = r.y0; y <= r.y1; ++y) {
    for (int x = r.x0; x <= r.x1; ++x) {
      std::vector<int>& cell = cells_[static_cast<std::size_t>(y) * kGridCells + x];
      if (cell.empty()) touched_.push_back(y * kGridCells + x);
      cell.push_back(index);
    }
  }
}

bool OcclusionTest::inside(const Occluder& o, const Vec2& p) const {
  for (const Vec3& l : o.lines) {
    if (l.x * p.x + l.y * p.y + l.z < 0.0) return false;
  }
  return true;
}

void OcclusionTest::nearby(const BoundingBox& box, std::vector<int>& out) const {
  out.clear();
  stamp_.resize(occluders_.size(), -1);
  ++query_;
  auto collect = [&](int i) {
    if (stamp_[i] == query_ || !boxes_overlap(box, occluders_[i].box)) return;
    stamp_[i] = query_;
    out.push_back(i);
  };
  for (int i : wide_) collect(i);
  if (!cells_.empty()) {
    const CellRange r = cell_range(box, grid_.origin, grid_.cell, kGridCells);
    for (int y = r.y0; y <= r.y1; ++y) {
      for (int x = r.x0; x <= r.x1; ++x) {
        for (int i : cells_[static_cast<std::size_t>(y) * kGridCells + x]) collect(i);
      }
    }
  }
  // Nearest occluders were added first and tend to cover the most.
  std::sort(out.begin(), out.end());
}

bool OcclusionTest::covers(const ConvexPolygon& region_in, double margin) const {
  return covers(region_in, margin, {}, nullptr);
}

bool OcclusionTest::covers(const ConvexPolygon& region_in, double margin,
                           const std::vector<ConvexPolygon>& extra, bool* gave_up) const {
  if (gave_up) *gave_up = false;
  if (region_in.empty()) return true;
  BoundingBox box = region_in.bounds();
  box = {box.x_min - margin, box.y_min - margin, box.x_max + margin, box.y_max + margin};
  std::vector<int> near;
  if (!occluders_.empty()) nearby(box, near);
  std::vector<Occluder> extras;
  for (const ConvexPolygon& e : extra) {
    Occluder o;
    if (make_occluder(e, 0.0, Vec2(0.0), o) && boxes_overlap(box, o.box)) {
      extras.push_back(std::move(o));
    }
  }
  std::vector<const Occluder*> candidates;
  for (int index : near) candidates.push_back(&occluders_[index]);
  for (const Occluder& o : extras) candidates.push_back(&o);
  if (candidates.empty()) return false;
  // A cheap necessary condition first, before any polygon is built: the grown region's
  // extreme points (each vertex moved by +-margin in x and y) lie in some occluder.
  for (const Vec2& v : region_in.vertices()) {
    for (const Vec2& d : {Vec2(-1, -1), Vec2(1, -1), Vec2(1, 1), Vec2(-1, 1)}) {
      const Vec2 p = v + margin * d;
      bool inside = false;
      for (std::size_t i = 0; i < candidates.size() && !inside; ++i) {
        inside = this->inside(*candidates[i], p);
      }
      if (!inside) return false;
      if (margin <= 0.0) break;
    }
  }
  const ConvexPolygon region = margin > 0.0 ? dilated(region_in, margin) : region_in;
  std::vector<ConvexPolygon> pieces{region}, next;
  for (const Occluder* o : candidates) {
    next.clear();
    for (ConvexPolygon& piece : pieces) {
      if (!boxes_overlap(piece.bounds(), o->box)) {
        next.push_back(std::move(piece));
        continue;
      }
      // The part outside each moved edge line survives as a piece; what is inside them all
      // is covered.
      ConvexPolygon inside = std::move(piece);
      for (std::size_t k = 0; k < o->lines.size() && !inside.empty(); ++k) {
        ConvexPolygon outside = clip_to_half_plane(inside, -o->lines[k]);
        if (outside.area() > kNegligibleArea) next.push_back(std::move(outside));
        inside = clip_to_half_plane(inside, o->lines[k]);
      }
      if (next.size() > kMaxPieces) {
        if (gave_up) *gave_up = true;
        return false;
      }
    }
    pieces.swap(next);
    if (pieces.empty()) return true;
  }
  return false;
}

}  // namespace oflab
