// Saving and loading the whole session of the window as JSON ("oflab-session", version 1):
// the plane scene (camera, pose, motion), the motion script, the texture file, the
// animation view's source, engine settings (with the layer content and its quality, and the
// budget policy's frame budget when one is set), display
// and exact renderer, the frame and the view in front,
// and the window's state (flow view options, basis, presentation mode, lesson, play rate).
// A file format like the scripts and scenes, read with formats/json_fields.h; the GUI
// captures and applies sessions (gui/app/session_io.h).
#pragma once

#include <array>
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
  PlaneScene plane;     // the scene panel's plane at frame 0
  std::string script;   // shipped script name or file, empty when none plays
  std::string texture;  // texture file, empty for the default texture
  // The animation source's kind, by its name in gui/models/animation_sources.h.
  std::string source_kind = "plane";
  std::string source_name;    // script or scene name or file
  std::string viewer_script;  // kinds with a viewer script only
  EngineSettings settings;
  std::string display = "side-by-side";  // gui/views/animation_controls.h panel_display_name
  // Who draws the animation view's exact panel, by name in gui/adapters/exact_frames.h
  // ("animation.exact_renderer"; files without it get the default, core's exact render).
  std::string exact_renderer = "core";
  int frame = 0;
  std::string view = "flow";
  // What the window shows beyond the scene ("window" object; files without it get these
  // defaults). Names are the GUI's keys, checked when applied.
  std::string flow_part = "full";  // gui/views/flow_parts.h flow_part_key
  // The flow view's drawing options, in the order arrows, streamlines, colour wheel,
  // texture, zoom to the plane, common scale (gui/adapters/flow_display.h).
  std::array<bool, 6> flow_draw{{true, false, false, true, true, false}};
  std::string basis = "planar";  // gui/views/basis_catalog.h basis_key
  bool basis_playing = false;
  bool presentation = false;
  std::string lesson;  // the lesson whose caption shows, empty for none
  int play_rate = 30;  // live play, frames per second (> 0)
};

// The session as JSON text (pretty-printed).
std::string session_to_json(const Session& session);

// Parses session text; `origin` names the source in errors. Checks the format tag, the
// version, types, finite numbers of magnitude at most 1e6, a drawable plane
// (plane_scene_problem), non-negative thresholds, a content quality in
// 1..kMaxContentQuality (files without "content" or "content_quality" get the texture, 1) and known
// names; the files it names and the source kind are checked when the session is applied.
Session parse_session(const std::string& text, const std::string& origin);

// Reads a session file (parse_session, with the file name as origin); throws SessionError
// when it cannot be read.
Session read_session_file(const std::string& path);

// Writes a session file. Throws SessionError when the file exists and `overwrite` is
// false, or when it cannot be written.
void write_session_file(const std::string& path, const Session& session, bool overwrite);

}  // namespace oflab
