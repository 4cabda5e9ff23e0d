// Saving and loading the whole session of the window as JSON ("oflab-session", version 1):
// the plane scene (camera, pose, motion), the motion script, the texture file, the
// animation view's source, engine settings and display, the frame and the view in front.
// A file format like the scripts and scenes, read with formats/json_fields.h; the GUI
// captures and applies sessions (gui/app/session_io.h).
#pragma once

#include <stdexcept>
#include <string>

#include "engine/engine.h"
#include "flow/plane_scene.h"

namespace oflab {

// Thrown for a session file that cannot be used; what() names the file, the part and the field:
//     "s.json: plane.pose: field 'normal': must be a list of 3 numbers".
class SessionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Session {
  PlaneScene plane;           // the scene panel's plane at frame 0
  std::string script;         // shipped script name or file, empty when none plays
  std::string texture;        // texture file, empty for the default texture
  // The animation source's kind, by its name in gui/models/animation_sources.h.
  std::string source_kind = "plane";
  std::string source_name;    // script or scene name or file
  std::string viewer_script;  // kinds with a viewer script only
  EngineSettings settings;
  std::string display = "side-by-side";  // gui/views/animation_controls.h panel_display_name
  int frame = 0;
  std::string view = "flow";
};

// The session as JSON text (pretty-printed).
std::string session_to_json(const Session& session);

// Parses session text; `origin` names the source in errors. Checks the format tag, the
// version, types, finite numbers of magnitude at most 1e6, a drawable plane
// (plane_scene_problem), non-negative thresholds and known names; the files it names and the
// source kind are checked when the session is applied.
Session parse_session(const std::string& text, const std::string& origin);

// Reads a session file (parse_session, with the file name as origin); throws SessionError
// when it cannot be read.
Session read_session_file(const std::string& path);

// Writes a session file. Throws SessionError when the file exists and `overwrite` is
// false, or when it cannot be written.
void write_session_file(const std::string& path, const Session& session, bool overwrite);

}  // namespace oflab
