// Live play at a requested rate whatever the drawing costs: the frame to show follows the
// wall clock, so a tick that comes late advances by several frames (frames are dropped)
// and a motion asked for at 30 frames per second runs at real speed even when a frame
// takes longer than 1/30 s to draw. Plain C++; the window feeds it a clock.
#pragma once

#include <cstdint>

namespace oflab {

class FramePacer {
 public:
  // Starts counting at `now_ms` (any monotonic clock, milliseconds) at `frames_per_second`
  // (> 0; other values are taken as 1).
  void start(std::int64_t now_ms, double frames_per_second);

  // Frames to advance at `now_ms` (>= the start time) so that, counting every earlier
  // call, floor(elapsed seconds * rate) frames have been advanced; 0 when the clock has
  // not reached the next frame or runs backwards.
  int frames_due(std::int64_t now_ms);

  double rate() const { return rate_; }

 private:
  std::int64_t start_ms_ = 0;
  std::int64_t advanced_ = 0;  // frames advanced since start
  double rate_ = 30.0;
};

}  // namespace oflab
