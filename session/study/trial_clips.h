// The pictures of a trial (manual/study.md): the two clips a front-end plays, one exact and one
// reused by the condition's policy at the ladder's rung that shows the requested error, in the
// order the request draws. Frames are kClipWidth x kClipHeight, opaque, the plane over a mid
// grey, one clip pixel to one screen pixel. The reused clip is the ladder's run itself (the
// same engine, settings and texture size), so the error it shows is the ladder's measured
// error, the number the session records. Plain C++ over core/ and analysis/formats.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "image/image.h"
#include "study/engine_display.h"
#include "study/study_file.h"
#include "study/study_session.h"

namespace oflab {

// The texture of a condition, kClipTextureWidth x kClipTextureHeight, premultiplied RGBA:
// the shipped butterfly resampled (bilinear) to that size, or a fine grating (black and white
// bars 4 texels wide, vertical, about 1.2 px on the screen at the start of the clip). Throws
// std::runtime_error when the butterfly cannot be read.
Image study_texture(StudyTexture texture);

struct TrialClips {
  std::vector<Image> first;   // played first
  std::vector<Image> second;  // then this
  double measured_px = 0.0;   // the reused clip's largest measured error, pixels
  double threshold_px = 0.0;  // the ladder's threshold that reused clip was played at
};

// The clips of `request` for `study`: the condition's clip exactly (core/engine/exact_render.h
// with the engine's default sampling, as the reused clip's re-renders) and reused at
// ladders[condition]'s rung for the requested error (study/engine_display.h shown_rung), the
// reused one first when request.distorted_first. `texture` is study_texture of the condition
// (given, so that a front-end reads it once). Preconditions: ladders from study_ladders(study);
// texture kClipTextureWidth x kClipTextureHeight.
TrialClips make_trial_clips(const Study& study, const std::vector<ErrorLadder>& ladders,
                            const TrialRequest& request, const Image& texture);

// A study as a front-end runs it: the session's loop with each request's pictures. The
// front-end plays clips() (first, then second), asks which clip was distorted and calls
// answer(); the error recorded is the reused clip's measured error. The desktop window and the
// page drive it alike, with a person or a SimulatedObserver answering.
class TrialRunner {
 public:
  // Plays the study's ladders (study_ladders: about 0.7 s per new condition) and draws the
  // first request. Throws std::invalid_argument for an unknown method, std::runtime_error
  // when a texture cannot be read.
  TrialRunner(const Study& study, const std::string& method, std::uint64_t seed);

  bool finished() const { return session_.finished(); }
  const TrialRequest& request() const { return session_.request(); }
  // The pictures of request(), made on the first call for it. Precondition: !finished().
  const TrialClips& clips();
  // The observer named clip `chosen` (1: first, 2: second) as the distorted one; `late`:
  // frames of the presentation were late (recorded, not counted, shown again). Makes the
  // clips first if they were not made. Throws std::invalid_argument for another `chosen`.
  void answer(int chosen, bool late);
  // The clip a simulated observer's answer names: the distorted one when correct.
  int chosen_for(bool correct) const;

  const StudySession& session() const { return session_; }

 private:
  StudySession session_;
  std::vector<ErrorLadder> ladders_;
  std::array<Image, 2> textures_;  // by StudyTexture, read when first needed
  std::unique_ptr<TrialClips> clips_;
};

// Runs `runner` to its end with `observer` answering, making every request's pictures as a
// person's run does (without playing them on a clock).
void run_simulated(TrialRunner& runner, SimulatedObserver& observer);

}  // namespace oflab
