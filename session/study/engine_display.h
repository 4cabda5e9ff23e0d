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

#include <functional>
#include <vector>

#include "engine/engine.h"
#include "engine/script.h"
#include "study/study_file.h"
#include "study/study_session.h"

namespace oflab {

// The clip's picture and texture: a 640 x 480 view (focal length 600 px) of a 2 x 1.5 plane 3
// units away, facing the viewer, with a 256 x 192 texel texture.
constexpr int kClipWidth = 640;
constexpr int kClipHeight = 480;
constexpr int kClipTextureWidth = 256;
constexpr int kClipTextureHeight = 192;
Camera clip_camera();

// The clip's frames (kClipSeconds at kClipFrameRate, pose and motion of each): the plane
// turning about its vertical axis through its centre at the condition's speed.
std::vector<ScriptFrame> clip_script(const StudyCondition& condition);

// Plays `condition`'s clip with its policy at `threshold_px` (every per-term threshold of
// EngineSettings set to it, the other settings their defaults) from its first frame, on
// `texture` (premultiplied, kClipTextureWidth x kClipTextureHeight, so that the engine's
// decisions are those of the ladder's runs), calling `shown` (if set) after each frame with
// the engine showing it and the frame's report. Returns the largest measured error over the frames,
// pixels.
double play_reused_clip(const StudyCondition& condition, double threshold_px, Layer texture,
                        const std::function<void(const PlaneEngine&, const FrameReport&)>& shown);

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
// (play_reused_clip on a white texture: the error is geometry), pixels.
double clip_measured_error(const StudyCondition& condition, double threshold_px);

// The rung shown for `requested_px`: the index of the ladder's measured error nearest to it in
// log terms (the smaller error on a tie). Precondition: a non-empty ladder.
int shown_rung(const ErrorLadder& ladder, double requested_px);
// Its measured error, pixels.
double shown_error(const ErrorLadder& ladder, double requested_px);

// An ErrorDisplay (study/study_session.h) for `study`: each condition's ladder over the
// study's error range (kLadderSteps runs), played when first needed and kept for the process
// (the texture does not change the measured error: the ladder depends on the policy, the
// speed and the range).
constexpr int kLadderSteps = 48;
ErrorDisplay engine_error_display(const Study& study);
// The ladders engine_error_display shows, one per condition of `study` in its order (played
// when first needed, kept for the process; safe to call from any thread).
std::vector<ErrorLadder> study_ladders(const Study& study);

}  // namespace oflab
