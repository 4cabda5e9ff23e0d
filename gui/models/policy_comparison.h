// Several reuse policies (core/engine/reuse_policy.h) playing the animation model's source
// at once: one Animator per policy, made by the source's kind exactly as the model makes
// its own, with the model's settings except the policy, and kept on the model's frame.
// The animation view's comparison layout shows them beside the exact projection, so every
// panel shows the same frame index of the same motion.
//
// Any 1..kMaxComparedPolicies policies of the registry may be compared; the default is
// affine and perspective. The runs follow the model's frame on demand (forward frame by
// frame, backward by a restart, like the model) and restart when the model's source or
// settings change.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "engine/animator.h"
#include "engine/reuse_policy.h"

namespace oflab {

class AnimationModel;

constexpr int kMaxComparedPolicies = 4;

// One compared policy: its animator and what it did, this frame and over the run so far.
struct ComparedRun {
  const ReusePolicy* policy = nullptr;
  std::unique_ptr<Animator> animator;  // null when the source cannot be played (see problem)
  std::string problem;                 // why not, one line; empty when it plays
  AnimationFrame last;                 // the record of animator->frame()
  std::int64_t pixels_written = 0;     // by the warp kernels over frames 0 .. frame()
  double time_ms = 0.0;                // wall time of frames 0 .. frame()
};

class PolicyComparison {
 public:
  // The model must outlive the comparison.
  explicit PolicyComparison(AnimationModel* model);
  ~PolicyComparison();

  // The policies compared, in panel order. Throws std::invalid_argument unless there are
  // 1 .. kMaxComparedPolicies of them, none null.
  void set_policies(const std::vector<const ReusePolicy*>& policies);
  std::vector<const ReusePolicy*> policies() const;

  // The model's source or settings changed: every run restarts when next read.
  void reset();

  // One run per policy at the model's current frame; empty when the model plays nothing
  // or its source does not use a reuse policy (scene shifting).
  const std::vector<ComparedRun>& runs();

 private:
  void build();
  static void restart(ComparedRun& run);
  static void seek(ComparedRun& run, int frame);

  AnimationModel* model_;
  std::vector<const ReusePolicy*> policies_;
  std::vector<ComparedRun> runs_;
  bool stale_ = true;
};

}  // namespace oflab
