// The runs the browser page's comparison and analysis views show of its lab
// (session/player/lab.h): the compared policies' runs (session/player/policy_comparison.h),
// or the source's own run when its kind has no reuse policy (scene shifting), each with its
// frame's record, its level shares and its largest measured error over frames 1 .. now.
#pragma once

#include <array>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/animator.h"

namespace oflab {

class Lab;

// One panel's record: the engine, its frame's record, and its level shares and largest error
// over frames 1 .. now.
struct ShownRun {
  std::string policy;
  const Animator* animator = nullptr;
  const AnimationFrame* last = nullptr;
  std::array<std::int64_t, kLevelCount> level_frames{};
  double max_error_px = 0.0;
};

// The runs `lab` shows at its frame (its runs advanced to it), by the state's display as the
// desktop's animation view shows them: in the comparison layout the compared runs (the
// source's own run when its kind has no reuse policy); side by side, difference and blink
// the model's own engine, named by its policy. Empty with *problem set (one line) when the
// source cannot be played or the compared runs do not fit the run memory limit.
std::vector<ShownRun> shown_runs(Lab& lab, std::string* problem);

// One panel of the comparison as JSON: policy, the policy's summary, the level of the frame
// (or the drawn layers per level of a scene), measured error and largest error so far in
// pixels, the frame's pixels written and of those the pixels its warps computed
// (`pixels_warped`: fewer under the visible-only warp, core/image/pixel_rows.h), level shares
// over frames 1 .. now, `psnr_db` and `heat_max` (its difference from the exact frame), and
// the outlines of the shown layers (frame pixels, top-left).
nlohmann::json shown_run_json(const ShownRun& run, double psnr_db, int heat_max);

// The analysis charts' history of `lab` (WebSession::analysis_json, whose contract it is): per
// compared run, or the source's own run, frames max(0, now - frames + 1) .. now as JSON.
std::string analysis_history_json(Lab& lab, int frames);

}  // namespace oflab
