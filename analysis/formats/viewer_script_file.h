// Viewer script files (JSON; format documented in manual/scenes.md#viewer-scripts): the
// camera's start pose and stretches of constant camera velocity, read into
// core/scene/viewer_script.h's ViewerScript.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "scene/viewer_script.h"

namespace oflab {

// Thrown for a viewer script that cannot be used; what() names the file and, where it
// applies, the segment and the field: "compound.json: segment 2: field 'omega': ...".
class ViewerScriptError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

ViewerScript read_viewer_script_file(const std::string& path);
ViewerScript parse_viewer_script(const std::string& text, const std::string& origin);

// A viewer script argument: an existing file, or a shipped name
// (datasets/viewer-scripts/NAME.json). Throws std::runtime_error listing the shipped names.
std::string resolve_viewer_script_path(const std::string& name_or_file);
std::vector<std::string> shipped_viewer_script_names();

}  // namespace oflab
