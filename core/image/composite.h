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
//
// From frame to frame (start_on): finish knows, per row, the interval the frame's layers
// reached; every pixel outside it is transparent black once finish returns. When the next
// frame is composited into the same image, unchanged since, those pixels need no store at
// all: the clears of the gaps and of finish skip them (a frame that shows a street's two
// sides leaves most of the sky between them as it was).
class LazyClear {
 public:
  // Starts a frame of `height` rows (>= 0): no pixel is cleared yet, and nothing is known of
  // the frame's pixels.
  void start(int height);

  // Starts a frame on `frame`: as start(frame.height()), except that when `frame` is the
  // image the last finish cleared (the same pixel buffer, width and height) and forget() has
  // not been called since, the pixels that finish left transparent black outside its rows'
  // reached intervals count as such (dirty_begin, dirty_end). Precondition: no code other
  // than composites with this LazyClear and its finish changed the frame's pixels since the
  // last finish, unless forget() was called.
  void start_on(const Image& frame);

  // Forgets what the last finish left: the frame's pixels were changed by other code.
  void forget();

  // Clears every pixel of `frame` no composite reached since start (in bands of rows on the
  // worker threads; with start_on, only those not known transparent black); `frame` has the
  // height given to start. Afterwards, until the next start, every pixel counts as cleared.
  void finish(Image& frame);

  // The row's interval of pixels holding their value (begin >= end: none). Row y in
  // [0, height); a composite's band may change only its own rows' intervals.
  int& begin(int y) { return begin_[static_cast<std::size_t>(y)]; }
  int& end(int y) { return end_[static_cast<std::size_t>(y)]; }

  // The row's interval of pixels that may be other than transparent black before they are
  // cleared or composited (the whole row, [0, INT_MAX), when nothing is known); the pixels
  // outside it are transparent black. Row y in [0, height).
  int dirty_begin(int y) const { return dirty_begin_[static_cast<std::size_t>(y)]; }
  int dirty_end(int y) const { return dirty_end_[static_cast<std::size_t>(y)]; }

 private:
  std::vector<int> begin_;
  std::vector<int> end_;
  std::vector<int> dirty_begin_;  // per row: outside [dirty_begin, dirty_end) transparent
  std::vector<int> dirty_end_;
  const Pixel* finished_ = nullptr;  // the pixels the last finish cleared (null: none known)
  int finished_width_ = 0;
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
