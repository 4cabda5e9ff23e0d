// The window state's fields as one table: each field of a WindowState (state/window_state.h)
// once, with its place in a session's state object ("animation.zoom"), its JSON type, its
// allowed range or names, its default and one line of what it is. The session reader and
// writer (state/window_state_file.h), the state's equality, the JSON schema the browser page
// asks for (state_schema) and the manual's field table (manual/gui.md, "Session fields",
// state_fields_markdown) all come from this table, so adding a field is one entry here plus
// its use. Plain C++ over analysis/formats/json_fields.h.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "formats/json_fields.h"
#include "state/window_state.h"

namespace oflab {

class SessionError;

// One field of the state object. `get` writes the field of a state as JSON; `set` reads a
// JSON value into a state, refusing (through `where`, which names the file, the part and the
// field) a value of the wrong type or a name no table knows. Numbers are range-checked
// afterwards, all at once (window_state_problem), so `set` checks type and names only.
struct StateField {
  std::string path;   // place in the state object, '.' between parts: "plane.camera.width"
  std::string type;   // "number", "whole number", "true or false", "name", "text", "[x, y, z]",
                      // "[x, y]", "list of names", "list of 4 numbers"
  std::string range;  // the allowed values in words: "0.25..8 x", "one of flow, basis, ..."
  std::string doc;    // one line: what the field is
  std::function<nlohmann::json(const WindowState&)> get;
  std::function<void(const nlohmann::json& value, const json_fields::Place<SessionError>& where,
                     const std::string& key, WindowState* state)>
      set;
};

// Every field, in the order of the manual's table (the top level's first: "view").
const std::vector<StateField>& state_fields();

// The field at `path`, or nullptr.
const StateField* find_state_field(const std::string& path);

// The state object of `state`: every field of the table at its place.
nlohmann::json state_fields_object(const WindowState& state);

// Reads the fields present in `object` over `state`: an object part ("plane", "animation")
// must be a JSON object, and a member that no field's path names is refused as an unknown
// field listing the known ones. `origin` names the file; `part` the top-level part in errors
// ("" for a session, "state" for a lesson's state). Limits are not checked here.
void read_state_fields(const nlohmann::json& object, const std::string& origin,
                       const std::string& part, WindowState* state);

// true when every field of the table is equal in a and b (numbers exactly).
bool same_fields(const WindowState& a, const WindowState& b);

// The table as JSON for the browser page: [{"name", "type", "range", "default", "doc"}, ...].
nlohmann::json state_schema();

// The table as the Markdown table of manual/gui.md ("| field | type | range | default |
// meaning |", one row per field), which a test compares with the page.
std::string state_fields_markdown();

}  // namespace oflab
