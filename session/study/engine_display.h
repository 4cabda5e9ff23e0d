// The error a trial shows, from the real engine (core/engine/engine.h): each condition's clip
// (kClipSeconds at kClipFrameRate of a plane turning about its vertical axis at the condition's
// speed, on a 640 x 480 clip) is played with the condition's reuse policy at a ladder of
// thresholds, and a requested error is shown as the run whose measured error (the largest
// FrameReport::measured_error_px over the clip's frames) is nearest to it on a log scale. The
// engine can show only errors its policy produces: a request beyond them gets the nearest
// one, and the trial records that measured error, never the request. The ladder is played
// once per condition (about 0.7 s each) and kept. Plain C++ over core/.
//
// On this clip the affine policy's error is set by the motion, not the threshold: its affine
// view of the turning plane is off by 1.4 px after 1 s at 1 deg/s, 4.4 px at 3 deg/s and
// 30 px at 20 deg/s whatever the threshold (`oflab-cli study ladder`), so an affine condition
// shows one error only (manual/study.md).
#pragma once

#include <vector>

#include "study/study_file.h"
#include "study/study_session.h"

namespace oflab {

// One condition's ladder: thresholds (pixels, rising) and the measured error of each run.
struct ErrorLadder {
  std::vector<double> thresholds_px;
  std::vector<double> measured_px;
};

// Plays `condition`'s clip with its policy at `steps` (>= 2) thresholds log-spaced over
// [min_px, max_px] (0 < min < max), each from its first frame.
ErrorLadder play_error_ladder(const StudyCondition& condition, double min_px, double max_px,
                              int steps);

// The largest measured error of `condition`'s clip played with its policy at `threshold_px`
// (every per-term threshold of EngineSettings set to it), pixels.
double clip_measured_error(const StudyCondition& condition, double threshold_px);

// The shown error for `requested_px`: the ladder's measured error nearest to it in log terms
// (the smaller on a tie). Precondition: a non-empty ladder.
double shown_error(const ErrorLadder& ladder, double requested_px);

// An ErrorDisplay (study/study_session.h) for `study`: each condition's ladder over the
// study's error range (kLadderSteps runs), played when first needed and kept for the process
// (the texture does not change the measured error: the ladder depends on the policy, the
// speed and the range).
constexpr int kLadderSteps = 48;
ErrorDisplay engine_error_display(const Study& study);

}  // namespace oflab
