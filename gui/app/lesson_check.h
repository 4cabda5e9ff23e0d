// Lessons that tell the truth: every claim of a lesson (gui/models/lessons.h) is measured on
// the screen it describes. The checker plays the lesson in a real window as a teacher does
// (the lesson's state, its frames played, then each step's actions in order) and after each
// part measures each claim on the window's own models and on what its views paint.
// `oflab --check-lesson NAME|FILE|all` runs it; the lesson-claims ctest runs it on every
// shipped lesson at 1920 x 1080, and on a lesson with a false claim, which it must reject.
#pragma once

#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "models/lessons.h"

namespace oflab {

class MainWindow;

struct ClaimCheck {
  int step = 0;  // 0: the narrative; k: the k-th step
  LessonClaim claim;
  double measured = 0.0;  // in the claim's unit (gui/models/lessons.h lesson_claim_kinds)
  bool holds = false;
};

// Measures one claim on the window as it is now (the view in front rendered first).
// Returns NaN for a claim that names something the window does not have (an unknown flow
// part, term or compared policy), which then never holds.
double measure_claim(MainWindow* window, const LessonClaim& claim);

// Plays `lesson` in `window` (which must run on an external clock: set_external_clock(true))
// and checks every claim of its narrative and steps, in order, and of every part that its
// caption shows whole ("caption_cut" at most 0); after the claims of each part
// calls `after_part(k)` (0: the narrative, k: the k-th step) when given, with the window as
// that part left it (for a picture of each step).
std::vector<ClaimCheck> check_lesson(MainWindow* window, const Lesson& lesson,
                                     const std::function<void(int)>& after_part = {});

// One line: the lesson, the step, the claim's words, what was measured against what was
// claimed, and whether it holds: 'flow-of-a-plane, step 2: "translation is small"
// (flow_ratio first-order/translation) measured 106.9, claimed at least 5: holds'.
std::string describe(const Lesson& lesson, const ClaimCheck& check);

}  // namespace oflab
