#include "state/window_state_file.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <vector>

#include "engine/reuse_policy.h"
#include "formats/atomic_file.h"
#include "formats/json_fields.h"
#include "state/state_fields.h"

namespace oflab {
namespace {

using namespace json_fields;
using Where = Place<SessionError>;

// The limits of every number (one rule per value: window_state_problem), as a file error.
void check_limits(const WindowState& s, const std::string& origin) {
  const std::string problem = window_state_problem(s);
  if (problem.empty()) return;
  const size_t colon = problem.find(": ");
  const std::string field = problem.substr(0, colon);
  const size_t dot = field.rfind('.');
  const Where w{origin, dot == std::string::npos ? "" : field.substr(0, dot)};
  w.fail(dot == std::string::npos ? field : field.substr(dot + 1), problem.substr(colon + 2));
}

// Copies root[from] to (*out)[to] when present; with `required`, refuses its absence.
void move_field(const json& root, const Where& w, const char* from, json* out, const char* to,
                bool required) {
  if (required) member(root, w, from);
  if (root.contains(from)) (*out)[to] = root.at(from);
}

// Version 1's "window" object: the flow options as six booleans in a fixed order, the basis,
// presentation, lesson and play rate; every member required.
void window_version_1(const json& window, const std::string& origin, json* v2) {
  const Where w{origin, "window"};
  (*v2)["flow"]["part"] = member(window, w, "flow_part");
  const json& draw = member(window, w, "flow_draw");
  if (!draw.is_array() || draw.size() != 6) w.fail("flow_draw", "must be a list of 6 booleans");
  const char* keys[6] = {"arrows",  "streamlines",   "colour_wheel",
                         "texture", "zoom_to_plane", "common_scale"};
  for (size_t k = 0; k < 6; ++k) {
    if (!draw[k].is_boolean()) w.fail("flow_draw", "must be a list of booleans");
    (*v2)["flow"][keys[k]] = draw[k];
  }
  (*v2)["basis"]["kind"] = member(window, w, "basis");
  (*v2)["basis"]["playing"] = member(window, w, "basis_playing");
  for (const char* key : {"presentation", "lesson", "play_rate"}) {
    (*v2)[key] = member(window, w, key);
  }
}

// Version 1 as a format-2 state object: every part present, the budget as "budget_pixels"
// or "budget_ms" (at most one), the window's options in "window".
json version_1_as_2(const json& root, const std::string& origin) {
  const Where top{origin, ""};
  json v2 = json::object();
  for (const char* key : {"plane", "script", "texture", "frame", "view"}) {
    move_field(root, top, key, &v2, key, true);
  }
  const json& animation = object(root, top, "animation");
  const Where w{origin, "animation"};
  json& a = v2["animation"];
  const json& source = object(animation, w, "source");
  const Where in_source{origin, "animation.source"};
  for (const char* key : {"kind", "name", "viewer"}) text(source, in_source, key);
  a["source"] = source;
  for (const char* key : {"mode", "thresholds", "display"})
    move_field(animation, w, key, &a, key, true);
  for (const char* key :
       {"delta", "sampling", "content", "content_quality", "cadence", "exact_renderer"}) {
    move_field(animation, w, key, &a, key, false);
  }
  const bool pixels = animation.contains("budget_pixels"), ms = animation.contains("budget_ms");
  if (pixels && ms) w.fail("budget_ms", "give budget_pixels or budget_ms, not both");
  if (pixels || ms) {
    a["budget"] = {{"unit", pixels ? "pixels" : "ms"},
                   {"amount", animation.at(pixels ? "budget_pixels" : "budget_ms")}};
  }
  if (root.contains("window")) window_version_1(object(root, top, "window"), origin, &v2);
  return v2;
}

}  // namespace

json window_state_object(const WindowState& s) { return state_fields_object(s); }

std::string window_state_to_json(const WindowState& state) {
  json j = {{"format", "oflab-session"}, {"version", kSessionFormatVersion}};
  j.update(window_state_object(state));
  return j.dump(2) + "\n";
}

WindowState read_window_state_object(const json& j, const std::string& origin,
                                     const std::string& part, WindowState s) {
  read_state_fields(j, origin, part, &s);
  check_limits(s, origin);
  return s;
}

WindowState parse_session(const std::string& json_text, const std::string& origin) {
  const Where top{origin, ""};
  json root = parse_object(json_text, top);
  if (text(root, top, "format") != "oflab-session") top.fail("format", "must be \"oflab-session\"");
  const double version = number(member(root, top, "version"), top, "version");
  if (version == 1) {
    return read_window_state_object(version_1_as_2(root, origin), origin, "", WindowState());
  }
  if (version != kSessionFormatVersion) top.fail("version", "must be 1 or 2");
  root.erase("format");
  root.erase("version");
  return read_window_state_object(root, origin, "", WindowState());
}

namespace {

// `value`, a file a state names, as a path from the current folder: beside the file `dir`
// names when such a file exists there, else unchanged.
std::string beside(const std::filesystem::path& dir, const std::string& value) {
  if (value.empty() || dir.empty() || std::filesystem::path(value).is_absolute()) return value;
  const std::filesystem::path near = dir / value;
  std::error_code error;
  return std::filesystem::exists(near, error) ? near.lexically_normal().string() : value;
}

}  // namespace

WindowState with_files_beside(WindowState state, const std::string& file) {
  const std::filesystem::path dir = std::filesystem::path(file).parent_path();
  state.texture = beside(dir, state.texture);
  state.script = beside(dir, state.script);
  state.source.name = beside(dir, state.source.name);
  state.source.viewer = beside(dir, state.source.viewer);
  return state;
}

WindowState read_session_file(const std::string& path) {
  return with_files_beside(parse_session(read_file_text<SessionError>(path),
                                         std::filesystem::path(path).filename().string()),
                           path);
}

void write_session_file(const std::string& path, const WindowState& state, bool overwrite) {
  try {
    write_file_atomically(path, window_state_to_json(state),
                          overwrite ? Overwrite::kReplace : Overwrite::kRefuse);
  } catch (const FileWriteError& e) {
    throw SessionError(e.what());
  }
}

}  // namespace oflab
