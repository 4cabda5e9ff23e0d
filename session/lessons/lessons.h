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
// Budgets (core/flow/limits.h): at most limits::kLessonSteps steps, and at most
// limits::kLessonFrames frames played in all (the lesson's "play", and each step's "frame",
// reached by playing forward, and "play", counted in the order they are played). A file over
// either is refused when it is read, naming the file, the step and the limit:
//   "long.json: step 3: field 'play': the lesson plays 1200 frames up to here, more than 1000
//   (the lesson frames limit)".
//
// A claim is a statement about the screen the program evaluates (gui/app/lesson_check.h):
//   {"says": "the words of the sentence it checks", "claim": KIND, ...fields of the kind,
//    "at_least": number and/or "at_most": number}
// with KIND one of the registry lessons/claim_kinds.h (claim_kinds()), which says what each
// kind measures and which fields it needs; a claim of an unknown kind or with a bad field
// is refused when the file is read.
#pragma once

#include <string>
#include <vector>

#include "state/window_state.h"

namespace oflab {

// A statement about what the screen shows, checked by measuring it.
struct LessonClaim {
  std::string says;          // the sentence (or part of one) of the step that it checks
  std::string claim;         // its kind, one of claim_kinds() (lessons/claim_kinds.h)
  std::string of;            // what it measures (a flow term, a policy, a panel; see the kinds)
  std::string over;          // the second quantity of a ratio ("flow_ratio")
  std::string level;         // an update level ("level_share")
  double at_least = -1e300;  // the measured value must be >= at_least and <= at_most
  double at_most = 1e300;
};

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

// The lesson in the file at `path`. Throws SessionError (session/state/window_state_file.h)
// naming the file and the field when it cannot be read or used, or passes a budget above.
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

// The lesson `name_or_file` names: a shipped or added lesson's name, else a lesson file,
// read (read_lesson_file) and added (add_lesson). A name is taken as a file when it contains
// '/', ends in ".json" or names anything on disk (or cannot be looked up: a loop of links,
// a name too long). Throws SessionError with one line: "unknown lesson 'NAME' (known: ...)"
// for a plain word that is neither, else the file's problem naming its path ("PATH: cannot
// open the file (Too many levels of symbolic links)", "PATH: is not a regular file
// (character device)", "PATH: field 'order': ...").
const Lesson& find_or_read_lesson(const std::string& name_or_file);

// The names in teaching order, comma separated, for error messages and --help.
std::string lesson_names();

}  // namespace oflab
