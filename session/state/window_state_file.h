// A WindowState as JSON: the session file ("oflab-session", version 2) and the "state" object
// of a lesson file (session/lessons/lessons.h). Every field is named (the flow view's options by
// name, not by position); a reader takes the fields present over a base state, so a lesson
// or an old file gives only what differs from the default window. Version 1 files (flow
// options as a list of six booleans, no compared policies or zoom) still read.
//
// Refused, with the file, the field and the allowed range or names: an unknown field, a value
// of the wrong type, a name no table knows (flow part, basis, layout, policy, Delta,
// sampling, content, motion model) and a number outside its limit (core/flow/limits.h,
// through window_state_problem). The view, the source kind, the exact renderer, the lesson
// and the files a state names are checked when the window applies it (WindowModel::apply).
// Plain C++ over analysis/formats/json_fields.h.
#pragma once

#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "state/window_state.h"

namespace oflab {

// Thrown for a session or lesson file that cannot be used; what() names the file, the part
// and the field: "s.json: animation: field 'thresholds': 1e+06 is outside 0..100 px".
class SessionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

constexpr int kSessionFormatVersion = 2;

// The whole state as a format-2 session file's text (pretty-printed JSON).
std::string window_state_to_json(const WindowState& state);

// The state object (every field of a format-2 session but "format" and "version") as JSON.
nlohmann::json window_state_object(const WindowState& state);

// The fields present in `object` (a state object of format 2) read over `base`; `origin`
// and `part` name the place in errors ("lessons/occlusion.json", "state").
WindowState read_window_state_object(const nlohmann::json& object, const std::string& origin,
                                     const std::string& part, WindowState base);

// Parses session text of version 1 or 2 over the default WindowState; `origin` names the
// source in errors.
WindowState parse_session(const std::string& text, const std::string& origin);

// `state` with the files it names (texture, script, the animation's source and viewer
// script) found beside `file`, the session or lesson that names them: a relative name that
// is a file in `file`'s folder becomes that path (from the current folder); any other name
// (absolute, a shipped name, a file only beside the current folder) is kept.
WindowState with_files_beside(WindowState state, const std::string& file);

// Reads a session file (parse_session with the file's name as origin, its files found
// beside it: with_files_beside); throws SessionError when it cannot be read.
WindowState read_session_file(const std::string& path);

// Writes a session file whole (analysis/formats/atomic_file.h: a temporary beside it, renamed
// over `path`), so a failed write leaves what was there. Throws SessionError naming the file
// when it exists and `overwrite` is false, or when it cannot be written.
void write_session_file(const std::string& path, const WindowState& state, bool overwrite);

}  // namespace oflab
