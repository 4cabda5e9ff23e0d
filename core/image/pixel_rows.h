// A set of image pixels kept row by row as sorted, disjoint runs of columns: what a frame
// will show of a layer (the scene engine's visible-only warp, core/scene/scene_animator.h),
// and which pixels of a layer a warp has computed (core/engine/engine.h).
//
// Coordinates are whole pixels (x right, y down, pixel (x, y) covers [x, x+1) x [y, y+1),
// core/image/image.h) of whatever image the caller means: the scene engine's are top-left
// frame pixels, and a set may reach beyond the frame (negative rows and columns too).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "image/layer.h"
#include "image/polygon.h"

namespace oflab {

// Columns [begin, end) of one row.
struct ColumnRun {
  int begin = 0;
  int end = 0;
};

// What of a layer the scene engine warps (dissertation section 7.5.3, manual/animation.md,
// EngineSettings::warp_area in core/engine/engine.h):
// kWhole, the whole layer; kVisible, only the pixels the frame will show (inside the frame,
// not under opaque layers drawn in front), the frames staying the same bytes. The words of
// options, session files and JSON are warp_area_name's: "whole", "visible"; parse_warp_area
// accepts exactly those (false, *area unchanged, for anything else); warp_area_name_list
// joins them with `separator`.
enum class WarpArea { kWhole, kVisible };
constexpr int kWarpAreaCount = 2;
const char* warp_area_name(WarpArea area);
bool parse_warp_area(const std::string& text, WarpArea* area);
std::string warp_area_name_list(const std::string& separator = ", ");

class PixelRows {
 public:
  PixelRows() = default;
  // Every pixel of a width x height image. Precondition: width, height >= 0.
  static PixelRows full(int width, int height);
  // The set of runs[k] (any order, overlapping or touching runs allowed) in row top + k.
  static PixelRows from_runs(int top, std::vector<std::vector<ColumnRun>> runs);
  // Makes this set every pixel of a width x height image, its rows' memory kept (a set filled
  // again each frame allocates nothing). Precondition: width, height >= 0.
  void fill(int width, int height);

  // The rows that may hold pixels: [top(), top() + rows()).
  int top() const { return top_; }
  int rows() const { return static_cast<int>(rows_.size()); }
  // The runs of row y, sorted and disjoint; empty outside the rows above.
  const std::vector<ColumnRun>& row(int y) const;
  // True when the set holds a pixel of columns [x0, x1) of row y.
  bool any(int y, int x0, int x1) const;
  bool empty() const;
  std::int64_t count() const;

  // Drops the pixels whose centres (x + 0.5, y + 0.5) lie inside `polygon` (a centre on
  // its boundary may stay): after this, a pixel of the set is never one whose centre the
  // polygon holds with any room to spare.
  void remove_centres_inside(const ConvexPolygon& polygon);
  // The pixels of this set that are not in `other`.
  PixelRows minus(const PixelRows& other) const;
  // Adds the pixels of `other`.
  void add(const PixelRows& other);
  // The pixels of this set inside the box [x0, x0 + width) x [y0, y0 + height).
  PixelRows within(int x0, int y0, int width, int height) const;
  // The set moved by (dx, dy) whole pixels.
  PixelRows shifted(int dx, int dy) const;

 private:
  std::vector<ColumnRun>& at(int y) { return rows_[static_cast<std::size_t>(y - top_)]; }
  int top_ = 0;
  std::vector<std::vector<ColumnRun>> rows_;
};

// A layer warped partly (the plane engine's display under a visible-only warp,
// core/engine/engine.h set_shown_pixels): the source and the warp that made it, unchanged
// while it is shown (the texture, or the perspective cache), and the image pixels computed,
// as placed then. A reused layer (no update, a translation) warps, with them, the pixels it
// comes to show that were left out, and the whole layer is completed before it becomes the
// perspective cache: it then shows what a whole warp would, to the byte.
struct PartialWarp {
  bool active = false;
  const Layer* source = nullptr;
  Mat3 warp{1.0};
  PixelRows done;
};

}  // namespace oflab
