// Lessons for the classroom, as files: datasets/lessons/NAME.json, each a window state (the
// view, the scene and what plays, each view's options) with a title and a narrative shown
// above the views. The lesson menu, `oflab --lesson`, `oflab --help` and manual/lessons.md
// take their list from these files. Plain C++.
//
// A lesson file:
//   {"format": "oflab-lesson", "version": 1, "name": "occlusion", "order": 5,
//    "title": "Occlusion", "narrative": "Five textured squares ...",
//    "state": {...}, "play": 30, "claims": [...],
//    "steps": [{"say": "...", "do": {"frame": 40, "play": 10, "state": {...}},
//               "claims": [...]}, ...]}
// "name" is the file's stem; "order" places it in the menu (teaching order, distinct
// numbers); "state" holds the fields of a session's state object (gui/models/
// window_state_file.h) that differ from the default window, read over the default state,
// with "lesson" set to the lesson's name. "play" frames are played before the narrative's
// "claims" are checked. Each step says one thing (its "say" is the caption while it shows),
// does what a teacher does (go to a frame, play frames, change controls: a "state" read over
// the previous step's state), and checks its "claims". Unknown fields are refused.
//
// A claim is a statement about the screen the program evaluates (gui/app/lesson_check.h):
//   {"says": "the words of the sentence it checks", "claim": KIND, ...fields of the kind,
//    "at_least": number and/or "at_most": number}
// with KIND one of lesson_claim_kinds().
#pragma once

#include <string>
#include <vector>

#include "models/window_state.h"

namespace oflab {

// A statement about what the screen shows, checked by measuring it.
struct LessonClaim {
  std::string says;          // the sentence (or part of one) of the step that it checks
  std::string claim;         // its kind, one of lesson_claim_kinds()
  std::string of;            // what it measures (a flow term, a policy, a panel; see the kinds)
  std::string over;          // the second quantity of a ratio ("flow_ratio")
  std::string level;         // an update level ("level_share")
  double at_least = -1e300;  // the measured value must be >= at_least and <= at_most
  double at_most = 1e300;
};

// The kinds of claims and what they measure:
//   "coefficient": |coefficient `of`| of the plane's flow now (tx ty j11 j12 j21 j22 px py),
//     px/s or 1/s or 1/(px s) as core's planar_flow_coefficients;
//   "flow_ratio": the largest |flow| of part `of` over that of part `over` on the plane's
//     image (flow part keys: full, translation, first-order, second-order, ...);
//   "level_share": the share (0..1) of drawn layer-frames at `level` over frames 1 .. now, of
//     the engine (`of` "engine") or of a compared policy (`of` its name);
//   "max_error": the largest measured error (px) over frames 1 .. now, same `of`;
//   "exact_drawn": the share (0..1) of the exact panel's pixels the exact frame covers now;
//   "active_tiles": tiles of the basis gallery with a non-zero coefficient;
//   "heat_map_width": the narrowest heat map of the comparison layout, screen pixels;
//   "hole_pixels": the holes (AnimationFrame::hole_pixels) of the frame shown now of the
//     engine (`of` "engine") or of a compared policy (`of` its name), pixels;
//   "hole_map_pixels": the hole pixels marked on the comparison's heat maps as drawn now
//     (gui/adapters/hole_map.h), pixels; 0 when no hole map is drawn;
//   "near_far_error": the mean measured error of the nearer half of the layers drawn now
//     (by the depth of their polygons' centres) over that of the farther half, of the
//     engine or of a compared policy (`of`): > 1 when the error grows with inverse depth;
//   "cut_texts": texts the animation view paints elided, off its canvas or overlapping
//     another text (a count; claim at_most 0);
//   "threshold_crossings": how often the analysis view's budget chart of `level` (none ..
//     perspective) crosses its dashed threshold upwards over the frames it charts;
//   "view": 1 when the view in front is `of`, else 0;
//   "run_pixels_ratio": the pixels compared policy `of` has written over frames 0 .. now (its
//     panel's caption, "run N px") over those of compared policy `over`;
//   "caption_cut": 1 when the lesson caption's banner is shorter than its wrapped text needs,
//     else 0 (the checker claims it at most 0 for every part of every lesson);
// and of the basis explorer (gui/models/basis_explorer.h), as the basis view shows it:
//   "tile_active": 1 when the gallery's tile of term `of` (its symbol: "scale", "px", ...)
//     is lit (its coefficient is not zero), else 0;
//   "solution_count": planes and motions in front of the eye that make the dialled flow;
//   "futures_apart_frame": the first frame at which the two solutions' images are more
//     than 1 px apart (-1 when they never are within the second played, or with fewer
//     than two solutions);
//   "futures_first_px": how far apart they are after one frame, px;
//   "grid_change": what the deformation does to the grid in 1 s, field `of` of GridChange:
//     shift_px (px), area (ratio), turn_deg (degrees), keystone (fraction).
const std::vector<std::string>& lesson_claim_kinds();

struct LessonStep {
  std::string say;  // the caption while the step shows
  int frame = -1;   // go to this frame first (-1: stay)
  int play = 0;     // then play this many frames
  bool has_state = false;
  WindowState state;  // then apply this state (when has_state)
  std::vector<LessonClaim> claims;
};

struct Lesson {
  std::string name;                 // command-line name, the file's stem: "flow-of-a-plane"
  std::string title;                // menu entry
  std::string narrative;            // the caption, a few sentences
  int order = 0;                    // teaching order
  WindowState state;                // what the window shows; state.lesson == name
  int play = 0;                     // frames played before the narrative's claims are checked
  std::vector<LessonClaim> claims;  // of the narrative
  std::vector<LessonStep> steps;
};

// The lesson in the file at `path`. Throws SessionError (gui/models/window_state_file.h)
// naming the file and the field when it cannot be read or used.
Lesson read_lesson_file(const std::string& path);

// Every shipped lesson (datasets/lessons/, analysis/formats/datasets.h), in teaching order;
// read once. Throws SessionError when a shipped lesson file cannot be used, or when two
// lessons share an order.
const std::vector<Lesson>& lessons();

// The lesson with this name, shipped or added, or nullptr.
const Lesson* find_lesson(const std::string& name);

// A lesson read from a file of the user's (read_lesson_file), made known to find_lesson for
// the rest of the run; it replaces an added lesson of the same name. Returns it. Throws
// SessionError when its name is a shipped lesson's.
const Lesson& add_lesson(const Lesson& lesson);

// The names in teaching order, comma separated, for error messages and --help.
std::string lesson_names();

}  // namespace oflab
