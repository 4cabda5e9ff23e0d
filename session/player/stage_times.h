// Where a frame's wall time goes, stage by stage (the engine, the compared runs, the exact
// frame, the per-pixel maps, drawing, text), summed since the last reset: what
// `oflab --benchmark` prints after its frames per second (manual/gui.md).
//
// Times are exclusive: a stage timed inside another (the exact frame while the animation
// view draws) is taken off the outer one, so the stages add up to the wall time they cover.
// The clock is the calling thread's: stages are timed on the thread that plays the window
// (the work they hand to core's worker threads counts as the wall time it takes).
#pragma once

namespace oflab {

enum class FrameStage {
  kEngine,        // the window's own run: the engine's frame
  kComparedRuns,  // the comparison's runs (player/policy_comparison.h)
  kExactFrame,    // the exact projection of the frame
  kMaps,          // per-pixel difference, error and hole maps and their agreement figures
  kDrawing,       // painting the panels and views (what no other stage covers)
  kText,          // captions, readouts and the inspector's text
  kCount
};

// The stage's name as printed: "engine", "compared runs", "exact frame", "maps", "drawing",
// "text".
const char* frame_stage_name(FrameStage stage);

// Every stage back to zero (on this thread).
void reset_stage_times();

// The stage's exclusive wall time since the last reset, milliseconds (on this thread).
double stage_ms(FrameStage stage);

// Times one stage from construction to destruction, pausing the stage it is nested in.
class StageTimer {
 public:
  explicit StageTimer(FrameStage stage);
  ~StageTimer();
  StageTimer(const StageTimer&) = delete;
  StageTimer& operator=(const StageTimer&) = delete;

 private:
  FrameStage stage_;
  StageTimer* outer_;
  double started_ms_;
};

}  // namespace oflab
