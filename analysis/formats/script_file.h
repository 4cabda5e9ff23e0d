// Motion script files (JSON; format documented in manual/animation.md#script-format).
#pragma once

#include <stdexcept>
#include <string>

#include "engine/script.h"

namespace oflab {

// Thrown for a script that cannot be used; what() names the file, and where it applies
// the frame or segment and the field: "loop.json: frame 3: field 'normal': must not be zero".
class ScriptError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Reads a script file. Checks types, finiteness, non-zero normals and ups, positive sizes
// and frame counts, and that every pose given in the file has its centre in front of the
// camera. Poses reached by integrating segments are not checked: a motion may pass
// edge-on or behind the camera, and the engine reports such frames.
MotionScript read_script_file(const std::string& path);

// Parses script text; `origin` names the source in error messages.
MotionScript parse_script(const std::string& text, const std::string& origin);

}  // namespace oflab
