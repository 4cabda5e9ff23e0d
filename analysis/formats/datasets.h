// Where the bundled data lives ($OFLAB_DATASETS, the installed share/oflab/datasets beside
// the running program, or datasets/ of the source tree), and lookup of shipped scripts and
// textures by name.
#pragma once

#include <string>
#include <vector>

namespace oflab {

// The datasets directory, the first of: $OFLAB_DATASETS when set; the installed datasets
// relative to the running executable (installed_datasets_dir) when that directory exists;
// the source tree's datasets/ (a program run from its build tree).
std::string datasets_dir();

// The installed datasets of the running executable: its directory (from /proc/self/exe,
// symbolic links resolved) joined with the install's relative path from bin to the
// datasets (../share/oflab/datasets for the default layout), normalised. Empty when that
// directory does not exist, e.g. in the build tree.
std::string installed_datasets_dir();

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

// Resolves a texture argument: an existing file path is used as is; otherwise a shipped
// texture's name (datasets/textures/NAME.png: butterfly, fabric, tile) when that file exists;
// otherwise `name_or_file` unchanged (its reader then names it as missing).
std::string resolve_texture_path(const std::string& name_or_file);

}  // namespace oflab
