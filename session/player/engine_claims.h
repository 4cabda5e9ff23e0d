// The measures of the claim kinds that the engine answers (lessons/claim_kinds.h,
// ClaimSource::kEngine), taken on a lab (player/lab.h) as it shows a state now: the plane's
// flow, the run of its source and the compared runs with their histories, the view in front
// and the basis explorer. The desktop's lesson check (gui/app/lesson_check.h) measures these
// kinds here too, on the window's own lab, and adds the kinds of the screen; `oflab-cli
// lesson check` measures them headlessly. Plain C++.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "lessons/lesson_player.h"
#include "lessons/lessons.h"

namespace oflab {

class Animator;
class Lab;

// A measure: the claim's value on the lab now, in its kind's unit; NaN when the claim names
// something the lab does not have (a compared policy not compared, a run that cannot play).
using EngineMeasure = std::function<double(Lab& lab, const LessonClaim& claim)>;

// The measure of every engine kind, by kind name.
const std::map<std::string, EngineMeasure>& engine_claim_measures();

// The measure of `claim` (whose kind must be an engine kind) on `lab`; NaN otherwise.
double measure_engine_claim(Lab& lab, const LessonClaim& claim);

// Plays `a` and `b` from frame 0 (start) to `last_frame` (advance) side by side and returns
// the pixels in which their images differ, summed over the frames; -1 when their images
// differ in size. Precondition: both have at least last_frame + 1 frames. (The measure of
// whole_warp_difference: a run against the same run warped whole.)
std::int64_t differing_pixels(Animator& a, Animator& b, int last_frame);

// A lab as a lesson's stage (lessons/lesson_player.h): frames played one at a time on its
// plane panel, as the window's play does.
class LabStage : public LessonStage {
 public:
  explicit LabStage(Lab* lab) : lab_(lab) {}
  WindowState stage_state() const override;
  std::string stage_apply(const WindowState& state) override;
  void stage_stop() override;
  void stage_seek(int frame) override;
  int stage_loop_frames() const override;
  void stage_play(int frames) override;
  void stage_set_step(int step) override;

 private:
  Lab* lab_;
};

// One claim checked: the part of the lesson (0: the narrative, k: step k), the claim, what
// was measured and whether it holds.
struct ClaimCheck {
  int step = 0;
  LessonClaim claim;
  double measured = 0.0;
  bool holds = false;
};

// Plays `lesson` on `stage` from its narrative through every step and, after each part,
// measures that part's claims and then `every_part` (claims every part must hold) with
// `measure`: a value in the claim's unit (NaN for something the stage does not have, which
// never holds), or nullopt for a kind this front-end does not measure (left out of the
// result). `after_part(k)` runs after part k's claims (0: the narrative). Returns the checks
// in order; throws std::runtime_error naming the lesson and the part when a part cannot be
// shown.
std::vector<ClaimCheck> check_lesson_claims(
    LessonStage& stage, const Lesson& lesson,
    const std::function<std::optional<double>(const LessonClaim&)>& measure,
    const std::vector<LessonClaim>& every_part = {},
    const std::function<void(int)>& after_part = {});

// The engine claims of `lesson` checked headlessly, as `oflab-cli lesson check` checks them:
// a Lab with the shipped default texture as the stage, every part played in order, each
// engine kind measured by measure_engine_claim; the claims of the screen's kinds are left
// out and counted in *screen_claims (when not null). Throws as check_lesson_claims.
std::vector<ClaimCheck> check_engine_claims(const Lesson& lesson, int* screen_claims = nullptr);

// One line: the lesson, the part, the claim's words, what was measured against what was
// claimed, and whether it holds: 'flow-of-a-plane, step 2: "translation is small"
// (flow_ratio first-order/translation) measured 106.9, claimed at least 5: holds'.
std::string describe(const Lesson& lesson, const ClaimCheck& check);

}  // namespace oflab
