#include "models/frame_pacer.h"

#include <cmath>

namespace oflab {

void FramePacer::start(std::int64_t now_ms, double frames_per_second) {
  start_ms_ = now_ms;
  advanced_ = 0;
  rate_ = frames_per_second > 0.0 ? frames_per_second : 1.0;
}

int FramePacer::frames_due(std::int64_t now_ms) {
  const double elapsed_s = static_cast<double>(now_ms - start_ms_) / 1000.0;
  const auto target = static_cast<std::int64_t>(std::floor(elapsed_s * rate_ + 1e-9));
  if (target <= advanced_) return 0;
  const std::int64_t due = target - advanced_;
  advanced_ = target;
  return static_cast<int>(due);
}

}  // namespace oflab
