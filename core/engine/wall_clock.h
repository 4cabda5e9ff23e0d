// The wall clock of the engines' and the programs' timings (AnimationFrame::time_ms, the
// budget's check, the per-stage times of a frame): std::chrono::steady_clock, which is never
// adjusted, so a difference of two readings is a duration.
#pragma once

#include <chrono>

namespace oflab {

using WallClock = std::chrono::steady_clock;

// Milliseconds of wall time from `since` to now (>= 0).
inline double ms_since(WallClock::time_point since) {
  return std::chrono::duration<double, std::milli>(WallClock::now() - since).count();
}

}  // namespace oflab
