// Where the bundled data lives (datasets/ of the source tree, or $OFLAB_DATASETS), and
// lookup of shipped scripts and textures by name.
#pragma once

#include <string>
#include <vector>

namespace oflab {

// The datasets directory: $OFLAB_DATASETS when set, else the source tree's datasets/.
std::string datasets_dir();

// Names (file stems) of the .json files in datasets/`folder`, sorted; empty if the folder
// is missing.
std::vector<std::string> shipped_names(const std::string& folder);

// Resolves a name-or-file argument: an existing file path is used as is; otherwise the
// shipped datasets/`folder`/NAME.json. Throws std::runtime_error naming `what` (e.g.
// "scene") and listing the shipped names when neither exists.
std::string resolve_shipped_path(const std::string& name_or_file, const std::string& folder,
                                 const std::string& what);

// Resolves a script argument: an existing file path is used as is; otherwise a shipped
// script name (datasets/scripts/NAME.json). Throws std::runtime_error listing the shipped
// names when neither exists.
std::string resolve_script_path(const std::string& name_or_file);

// Names of the shipped motion scripts, sorted.
std::vector<std::string> shipped_script_names();

// The bundled butterfly texture (datasets/textures/butterfly.png).
std::string default_texture_path();

}  // namespace oflab
