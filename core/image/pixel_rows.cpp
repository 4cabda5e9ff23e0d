// Pixel sets row by row (core/image/pixel_rows.h): runs of columns cut by a convex
// polygon's pixel centres, and the set operations a partial warp's bookkeeping needs.
#include "image/pixel_rows.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

#include "flow/named_values.h"

namespace oflab {
namespace {

const std::vector<ColumnRun>& no_runs() {
  static const std::vector<ColumnRun> none;
  return none;
}

// Runs sorted by begin, merged where they touch or overlap.
std::vector<ColumnRun> merged(std::vector<ColumnRun> runs) {
  std::sort(runs.begin(), runs.end(),
            [](const ColumnRun& a, const ColumnRun& b) { return a.begin < b.begin; });
  std::vector<ColumnRun> out;
  for (const ColumnRun& r : runs) {
    if (r.begin >= r.end) continue;
    if (!out.empty() && r.begin <= out.back().end) {
      out.back().end = std::max(out.back().end, r.end);
    } else {
      out.push_back(r);
    }
  }
  return out;
}

// Removes columns [cut_begin, cut_end) from `runs` (sorted, disjoint) in place: the runs the
// cut meets are replaced by what is left of the first and of the last, so the vector's memory
// serves again (a cut inside one run is the only one that adds a run).
void cut(std::vector<ColumnRun>& runs, int cut_begin, int cut_end) {
  if (cut_begin >= cut_end) return;
  const auto first =
      std::find_if(runs.begin(), runs.end(), [&](const ColumnRun& r) { return r.end > cut_begin; });
  const auto last =
      std::find_if(first, runs.end(), [&](const ColumnRun& r) { return r.begin >= cut_end; });
  if (first == last) return;
  ColumnRun pieces[2];
  int n = 0;
  if (first->begin < cut_begin) pieces[n++] = {first->begin, cut_begin};
  if (std::prev(last)->end > cut_end) pieces[n++] = {cut_end, std::prev(last)->end};
  const auto met = static_cast<int>(last - first);
  const auto at = static_cast<std::size_t>(first - runs.begin());
  if (n <= met) {
    std::copy(pieces, pieces + n, runs.begin() + static_cast<std::ptrdiff_t>(at));
    runs.erase(runs.begin() + static_cast<std::ptrdiff_t>(at) + n,
               runs.begin() + static_cast<std::ptrdiff_t>(at) + met);
  } else {  // one run split in two
    runs[at] = pieces[0];
    runs.insert(runs.begin() + static_cast<std::ptrdiff_t>(at) + 1, pieces[1]);
  }
}

// The open interval of x where the horizontal line at `y` lies inside the convex polygon
// (every edge's inner side); false when it misses the polygon.
bool line_inside(const std::vector<Vec2>& v, double y, double& x_min, double& x_max) {
  x_min = -std::numeric_limits<double>::infinity();
  x_max = std::numeric_limits<double>::infinity();
  const std::size_t n = v.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2& a = v[k];
    const Vec2& b = v[next_vertex(k, n)];
    // Inside (clockwise on screen, non-negative shoelace area): cross(b - a, p - a) >= 0.
    const double ex = b.x - a.x, ey = b.y - a.y;
    const double c = -ey;                           // coefficient of p.x
    const double rest = ex * (y - a.y) + ey * a.x;  // c * p.x + rest > 0 inside
    if (c == 0.0) {
      if (!(rest > 0.0)) return false;
    } else if (c > 0.0) {
      x_min = std::max(x_min, -rest / c);
    } else {
      x_max = std::min(x_max, -rest / c);
    }
  }
  return x_min < x_max;
}

}  // namespace

// Every warp area with its name, in the order of the enum.
constexpr NamedValue<WarpArea> kWarpAreaNames[] = {{WarpArea::kWhole, "whole"},
                                                   {WarpArea::kVisible, "visible"}};
static_assert(std::size(kWarpAreaNames) == kWarpAreaCount);

const char* warp_area_name(WarpArea area) { return name_of_value(kWarpAreaNames, area, "whole"); }

bool parse_warp_area(const std::string& text, WarpArea* area) {
  return parse_named_value(kWarpAreaNames, text, area);
}

std::string warp_area_name_list(const std::string& separator) {
  return named_value_list(kWarpAreaNames, separator);
}

PixelRows PixelRows::full(int width, int height) {
  PixelRows set;
  set.fill(width, height);
  return set;
}

void PixelRows::fill(int width, int height) {
  top_ = 0;
  rows_.resize(static_cast<std::size_t>(std::max(height, 0)));
  for (auto& runs : rows_) {
    runs.clear();
    if (width > 0) runs.push_back({0, width});
  }
}

const std::vector<ColumnRun>& PixelRows::row(int y) const {
  if (y < top_ || y >= top_ + rows()) return no_runs();
  return rows_[static_cast<std::size_t>(y - top_)];
}

bool PixelRows::any(int y, int x0, int x1) const {
  for (const ColumnRun& r : row(y)) {
    if (r.begin >= x1) return false;
    if (r.end > x0) return true;
  }
  return false;
}

bool PixelRows::empty() const { return count() == 0; }

std::int64_t PixelRows::count() const {
  std::int64_t n = 0;
  for (const auto& runs : rows_) {
    for (const ColumnRun& r : runs) n += r.end - r.begin;
  }
  return n;
}

void PixelRows::remove_centres_inside(const ConvexPolygon& polygon) {
  if (polygon.empty() || rows_.empty()) return;
  const BoundingBox box = polygon.bounds();
  const double y_min = std::floor(box.y_min - 0.5), y_max = std::ceil(box.y_max - 0.5);
  const int first = static_cast<int>(std::max<double>(top_, y_min));
  const int last = static_cast<int>(std::min<double>(top_ + rows() - 1, y_max));
  // A centre within this distance of the polygon's boundary is kept (rounding).
  constexpr double kRoom = 1e-6;
  for (int y = first; y <= last; ++y) {
    double x_min = 0.0, x_max = 0.0;
    if (!line_inside(polygon.vertices(), y + 0.5, x_min, x_max)) continue;
    // Columns x with x_min < x + 0.5 < x_max, by kRoom.
    const double lo = std::floor(x_min + kRoom - 0.5) + 1.0;
    const double hi = std::ceil(x_max - kRoom - 0.5);  // exclusive
    if (!(lo < hi)) continue;
    const double limit = 1e9;
    cut(at(y), static_cast<int>(std::max(lo, -limit)), static_cast<int>(std::min(hi, limit)));
  }
}

PixelRows PixelRows::minus(const PixelRows& other) const {
  PixelRows out = *this;
  for (int y = top_; y < top_ + rows(); ++y) {
    auto& runs = out.at(y);
    for (const ColumnRun& r : other.row(y)) cut(runs, r.begin, r.end);
  }
  return out;
}

PixelRows PixelRows::from_runs(int top, std::vector<std::vector<ColumnRun>> runs) {
  PixelRows out;
  out.top_ = top;
  out.rows_ = std::move(runs);
  for (std::vector<ColumnRun>& row : out.rows_) row = merged(std::move(row));
  return out;
}

void PixelRows::add(const PixelRows& other) {
  if (other.rows() == 0) return;
  if (rows() == 0) {
    *this = other;
    return;
  }
  const int first = std::min(top_, other.top_);
  const int end = std::max(top_ + rows(), other.top_ + other.rows());
  std::vector<std::vector<ColumnRun>> all(static_cast<std::size_t>(end - first));
  for (int y = first; y < end; ++y) {
    auto& runs = all[static_cast<std::size_t>(y - first)];
    runs = row(y);
    const auto& more = other.row(y);
    if (more.empty()) continue;
    runs.insert(runs.end(), more.begin(), more.end());
    runs = merged(std::move(runs));
  }
  top_ = first;
  rows_ = std::move(all);
}

PixelRows PixelRows::within(int x0, int y0, int width, int height) const {
  PixelRows out;
  out.top_ = y0;
  out.rows_.resize(static_cast<std::size_t>(std::max(height, 0)));
  for (int y = y0; y < y0 + height; ++y) {
    auto& runs = out.at(y);
    for (const ColumnRun& r : row(y)) {
      const int begin = std::max(r.begin, x0), end = std::min(r.end, x0 + width);
      if (begin < end) runs.push_back({begin, end});
    }
  }
  return out;
}

PixelRows PixelRows::shifted(int dx, int dy) const {
  PixelRows out = *this;
  out.top_ += dy;
  for (auto& runs : out.rows_) {
    for (ColumnRun& r : runs) {
      r.begin += dx;
      r.end += dx;
    }
  }
  return out;
}

}  // namespace oflab
