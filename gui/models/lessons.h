// Lessons for the classroom, as files: datasets/lessons/NAME.json, each a window state (the
// view, the scene and what plays, each view's options) with a title and a narrative shown
// above the views. The lesson menu, `oflab --lesson`, `oflab --help` and manual/lessons.md
// take their list from these files. Plain C++.
//
// A lesson file:
//   {"format": "oflab-lesson", "version": 1, "name": "occlusion", "order": 5,
//    "title": "Occlusion", "narrative": "Five textured squares ...",
//    "state": {...}}
// "name" is the file's stem; "order" places it in the menu (teaching order, distinct
// numbers); "state" holds the fields of a session's state object (gui/models/
// window_state_file.h) that differ from the default window, read over the default state,
// with "lesson" set to the lesson's name. Unknown fields are refused, so later versions can
// add fields (steps, claims) without old readers misreading them.
#pragma once

#include <string>
#include <vector>

#include "models/window_state.h"

namespace oflab {

struct Lesson {
  std::string name;       // command-line name, the file's stem: "flow-of-a-plane"
  std::string title;      // menu entry
  std::string narrative;  // the caption, a few sentences
  int order = 0;          // teaching order
  WindowState state;      // what the window shows; state.lesson == name
};

// The lesson in the file at `path`. Throws SessionError (gui/models/window_state_file.h)
// naming the file and the field when it cannot be read or used.
Lesson read_lesson_file(const std::string& path);

// Every shipped lesson (datasets/lessons/, analysis/formats/datasets.h), in teaching order;
// read once. Throws SessionError when a shipped lesson file cannot be used, or when two
// lessons share an order.
const std::vector<Lesson>& lessons();

// The shipped lesson with this name, or nullptr.
const Lesson* find_lesson(const std::string& name);

// The names in teaching order, comma separated, for error messages and --help.
std::string lesson_names();

}  // namespace oflab
