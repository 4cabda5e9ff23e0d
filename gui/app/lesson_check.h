// Lessons that tell the truth on the desktop: every claim of a lesson (session/lessons/
// lessons.h) is measured on the window it describes. The lesson is played by the one lesson
// player (session/lessons/lesson_player.h) on the window, as a teacher plays it, and after
// each part each claim is measured: the engine's kinds on the window's own lab
// (session/player/engine_claims.h, the same measures as `oflab-cli lesson check`), the
// screen's kinds (session/lessons/claim_kinds.h, ClaimSource::kScreen) on what the views
// paint, through screen_claim_measures().
// A part that leaves the study window (views/study_window.h) on its set-up page is answered
// after its claims as a class would answer it: a simulated observer of a 1 px threshold (the
// study's slope, lapse and seed) runs the study in the window, then "Use X px" is pressed.
// `oflab --check-lesson NAME|FILE|all` runs it; the lesson-claims ctest runs it on every
// shipped lesson at 1920 x 1080, and on a lesson with a false claim, which it must reject.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "lessons/lessons.h"
#include "player/engine_claims.h"

namespace oflab {

class MainWindow;

// The measure of every screen kind of the registry, by kind name: the value on the window as
// it is now (the view measured rendered first); NaN when the window lacks what it names.
const std::map<std::string, std::function<double(MainWindow*, const LessonClaim&)>>&
screen_claim_measures();

// Measures one claim of any kind on the window as it is now (the view in front rendered
// first). Returns NaN for a claim that names something the window does not have (an
// unknown flow part, term or compared policy), which then never holds.
double measure_claim(MainWindow* window, const LessonClaim& claim);

// Plays `lesson` in `window` (which must run on an external clock: set_external_clock(true))
// and checks every claim of its narrative and steps, in order, and of every part that its
// caption shows whole ("caption_cut" at most 0); after the claims of each part
// calls `after_part(k)` (0: the narrative, k: the k-th step) when given, with the window as
// that part left it (for a picture of each step). Claims of a timed kind (ClaimKind::timed:
// frame_rate) are measured only with `time_claims`, else left out of the result; with
// `kinds` not empty, only the claims of those kinds are measured (caption_cut's among them
// only when named), the others left out. Throws std::runtime_error naming the lesson and
// the part when the window refuses a part's state.
std::vector<ClaimCheck> check_lesson(MainWindow* window, const Lesson& lesson,
                                     const std::function<void(int)>& after_part = {},
                                     bool time_claims = false,
                                     const std::vector<std::string>& kinds = {});

}  // namespace oflab
