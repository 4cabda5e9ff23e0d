// Several reuse policies (core/engine/reuse_policy.h) playing the run player's source
// at once: one Animator per policy, made by the source's kind exactly as the model makes
// its own, with the model's settings except the policy, and kept on the model's frame.
// The animation view's comparison layout (and the lesson claims about compared runs) shows them
// beside the exact projection, so every panel shows the same frame index of the same motion.
//
// Any 1..kMaxComparedPolicies policies of the registry may be compared; the default is
// affine and perspective. The runs follow the model's frame on demand (forward frame by
// frame, backward by a restart, like the model) and restart when the model's source or
// settings change.
//
// The compared runs are made only when every engine of the window fits the run memory limit
// together (core/scene/scene_resources.h run_memory_problem): the model's animator, its exact
// baseline and one animator per compared policy, each estimated as the model's scene seen
// through its camera. Otherwise every run carries that one-line problem and none plays.
//
// Each run also keeps its per-frame history (ComparedFrame: levels, measured error, time and
// work) over the current pass, for the analysis view's overlays (gui/views/analysis_view.h):
// at most kComparedHistoryFrames frames, the oldest dropped first, 56 bytes a frame.
#pragma once

#include <array>
#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <vector>

#include "engine/animator.h"
#include "engine/reuse_policy.h"
#include "state/window_state.h"

namespace oflab {

class RunPlayer;

// Frames of history kept per compared run: 5.6 MB per run at most, whatever the script's
// length (a script may have up to a million frames).
constexpr int kComparedHistoryFrames = 100000;

// The engines a window holds beside the compared runs: the model's animator and its exact
// baseline (the animation view's exact panel).
constexpr int kEnginesBesideComparedRuns = 2;

// What a compared policy did at one frame: the fields of its AnimationFrame that the
// analysis view charts, without the per-layer books.
struct ComparedFrame {
  int frame = 0;
  std::array<int, kLevelCount> levels{};  // drawn layers per update level
  double max_measured_error_px = 0.0;     // largest measured error of a drawn layer, pixels
  double time_ms = 0.0;                   // wall time of the frame, milliseconds
  double model_work = 0.0;                // the engine's cost model (AnimationFrame::model_work)
  std::int64_t pixels_written = 0;        // by the warp kernels

  // The charted fields of `record`, copied as they are (same units).
  static ComparedFrame of(const AnimationFrame& record);
  int drawn() const;  // sum of levels
};

// One compared policy: its animator and what it did, this frame and over the run so far.
// A compared policy that is the model's own plays no second engine: the run follows the
// model's animator and records (the same frames, made once).
struct ComparedRun {
  const ReusePolicy* policy = nullptr;
  std::unique_ptr<Animator> owned;  // its own engine; null when it follows the model's
  const Animator* model = nullptr;  // the model's engine, when the policy is the model's
  // The engine whose frame this run shows; nullptr when the source cannot be played (see
  // problem).
  const Animator* animator() const { return owned ? owned.get() : model; }
  std::string problem;              // why not, one line; empty when it plays
  AnimationFrame last;              // the record of animator->frame()
  std::int64_t pixels_written = 0;  // by the warp kernels over frames 0 .. frame()
  // Of pixels_written, those the warps computed (AnimationFrame::pixels_not_warped left out:
  // fewer under a visible-only warp, EngineSettings::warp_area), over frames 0 .. frame().
  std::int64_t pixels_warped = 0;
  double time_ms = 0.0;  // wall time of frames 0 .. frame()
  // Frames of the current pass, consecutive and oldest first, ending at animator->frame():
  // frames 0 .. frame() while they number at most the comparison's limit
  // (kComparedHistoryFrames by default), else the last that many.
  std::deque<ComparedFrame> history;

  // The history's record of frame `frame`; nullptr when it is not kept (not played yet in
  // this pass, or dropped).
  const ComparedFrame* at(int frame) const;
  // Drawn layer-frames per level over the kept frames among first .. last (inclusive).
  std::array<std::int64_t, kLevelCount> level_totals(int first, int last) const;
};

class PolicyComparison {
 public:
  // The model must outlive the comparison. Each run keeps at most `history_frames` (>= 1)
  // frames of history.
  explicit PolicyComparison(RunPlayer* model, int history_frames = kComparedHistoryFrames);
  ~PolicyComparison();

  // The policies compared, in panel order. Throws std::invalid_argument unless there are
  // 1 .. kMaxComparedPolicies of them, none null.
  void set_policies(const std::vector<const ReusePolicy*>& policies);
  std::vector<const ReusePolicy*> policies() const;

  // The model's source or settings changed: every run restarts when next read.
  void reset();

  // One run per policy at the model's current frame; empty when the model plays nothing
  // or its source does not use a reuse policy (scene shifting). The runs advance one after
  // another, each one's pixel loops on core's worker threads (core/image/thread_pool.h), so
  // their frames and records are those of a run on its own.
  const std::vector<ComparedRun>& runs();

 private:
  void build();
  // "" when the model's engines and one per compared policy fit limits::kRunMemory together;
  // else the message every run carries. Precondition: the model has an animator.
  std::string memory_problem() const;
  void restart(ComparedRun& run) const;
  void seek(ComparedRun& run, int frame) const;
  // A run of the model's own policy: its records become the model's of frames up to `frame`.
  void follow_model(ComparedRun& run, int frame) const;
  void record(ComparedRun& run) const;

  RunPlayer* model_;
  int history_frames_;
  std::vector<const ReusePolicy*> policies_;
  std::vector<ComparedRun> runs_;
  bool stale_ = true;
};

}  // namespace oflab
