// Exclusive per-stage wall times of a frame (session/player/stage_times.h).
#include "player/stage_times.h"

#include <array>

#include "engine/wall_clock.h"

namespace oflab {
namespace {

thread_local std::array<double, static_cast<int>(FrameStage::kCount)> totals{};
thread_local StageTimer* innermost = nullptr;

// Milliseconds on the wall clock from its (arbitrary) origin: only differences mean anything.
double now_ms() { return ms_since(WallClock::time_point()); }

}  // namespace

const char* frame_stage_name(FrameStage stage) {
  switch (stage) {
    case FrameStage::kEngine:
      return "engine";
    case FrameStage::kComparedRuns:
      return "compared runs";
    case FrameStage::kExactFrame:
      return "exact frame";
    case FrameStage::kMaps:
      return "maps";
    case FrameStage::kDrawing:
      return "drawing";
    case FrameStage::kText:
      return "text";
    case FrameStage::kCount:
      break;
  }
  return "?";
}

void reset_stage_times() { totals.fill(0.0); }

double stage_ms(FrameStage stage) { return totals[static_cast<int>(stage)]; }

StageTimer::StageTimer(FrameStage stage) : stage_(stage), outer_(innermost), started_ms_(now_ms()) {
  if (outer_) totals[static_cast<int>(outer_->stage_)] += started_ms_ - outer_->started_ms_;
  innermost = this;
}

StageTimer::~StageTimer() {
  const double t = now_ms();
  totals[static_cast<int>(stage_)] += t - started_ms_;
  innermost = outer_;
  if (outer_) outer_->started_ms_ = t;
}

}  // namespace oflab
