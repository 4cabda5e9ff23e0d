// Porter-Duff "over" compositing of premultiplied layers into a frame.
#pragma once

#include <cstdint>
#include <vector>

#include "image/image.h"
#include "image/layer.h"
#include "image/polygon.h"

namespace oflab {

// "Over" for one premultiplied pixel, per channel:
//     out = src + round(dst * (255 - src.a) / 255)
// (exact integer rounding, halves up). The result is well formed when both inputs are.
Pixel over(Pixel src, Pixel dst);

// A frame cleared to transparent black (Pixel{}) as it is composited, instead of by a pass
// over every pixel first: per row, the one interval of pixels [begin, end) already holding
// their value (cleared, or composited over cleared pixels); the other pixels of the frame
// are not yet cleared. A composite over a pixel not yet cleared writes the layer pixel
// (over(s, transparent black) = s), fills any gap between its span and the row's interval
// with transparent black, and blends inside the interval; finish clears what no layer
// reached. The frame then holds exactly the bytes of a fill followed by the same composites,
// with each pixel stored about once (a camera-sized frame is megabytes of stores).
class LazyClear {
 public:
  // Starts a frame of `height` rows (>= 0): no pixel is cleared yet.
  void start(int height);

  // Clears every pixel of `frame` no composite reached since start (in bands of rows on the
  // worker threads); `frame` has the height given to start. Afterwards, until the next
  // start, every pixel counts as cleared.
  void finish(Image& frame);

  // The row's interval of pixels holding their value (begin >= end: none). Row y in
  // [0, height); a composite's band may change only its own rows' intervals.
  int& begin(int y) { return begin_[static_cast<std::size_t>(y)]; }
  int& end(int y) { return end_[static_cast<std::size_t>(y)]; }

 private:
  std::vector<int> begin_;
  std::vector<int> end_;
};

// Composites `layer` over `frame`, with layer pixel (0, 0) placed on frame pixel
// (offset_x, offset_y). Only layer pixels whose centre lies inside layer.polygon (the
// half-open rule of core/image/scan_conversion.h) take part, clipped to the frame; no other
// frame pixel changes. Offsets may be negative or put the layer wholly outside the frame.
// Returns the number of frame pixels composited. With `lazy` (started for this frame's
// height), the frame's pixels not yet cleared count as transparent black (see LazyClear).
std::int64_t composite_over(Image& frame, const Layer& layer, int offset_x, int offset_y,
                            LazyClear* lazy = nullptr);

// Like composite_over, but only the frame pixels whose centre lies in both the layer's
// polygon (placed at the offset) and `region` (frame pixel coordinates, half-open rule of
// core/image/scan_conversion.h) take part. Regions that partition a layer's polygon therefore
// composite every layer pixel exactly once: the pieces of a polygon split by the BSP tree
// (core/scene/bsp_tree.h) are drawn from the polygon's one layer this way, each restricted to
// its own region, in back-to-front order. Returns the pixel count. `lazy` as composite_over.
std::int64_t composite_over_region(Image& frame, const Layer& layer, int offset_x, int offset_y,
                                   const ConvexPolygon& region, LazyClear* lazy = nullptr);

// One layer of composite_all: `layer` (it must outlive the call) with its pixel (0, 0) on
// frame pixel (offset_x, offset_y), restricted to `region` (frame pixels) as
// composite_over_region restricts it, or its whole polygon as composite_over when null.
struct CompositeItem {
  const Layer* layer = nullptr;
  int offset_x = 0;
  int offset_y = 0;
  const ConvexPolygon* region = nullptr;
};

// Composites the items over `frame` in order: the same bytes and the same total count as
// composite_over or composite_over_region called for each item in turn, but in one pass of
// bands of rows on the worker threads (each band composites every item's rows inside it,
// item after item), not one pass per layer. `lazy` as composite_over.
std::int64_t composite_all(Image& frame, const std::vector<CompositeItem>& items,
                           LazyClear* lazy = nullptr);

}  // namespace oflab
