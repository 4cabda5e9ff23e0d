// Scene files (JSON; format documented in manual/scenes.md#scene-format): convex textured
// polygons in a world frame, read into core/scene/scene.h's Scene with their textures loaded.
#pragma once

#include <map>
#include <nlohmann/json_fwd.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace oflab {

// Thrown for a scene that cannot be used; what() names the file and, where it applies, the
// texture or the polygon (index and name) and the field:
//   "two.json: polygon 1 ('tilted'): field 'vertices': not planar: vertex 3 is ..."
class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Most polygons in a scene file (and faces in an OBJ file).
constexpr int kMaxScenePolygons = 100000;

// Reads a scene file and the textures it names. Texture paths are relative to the scene
// file's directory, or to the datasets directory when written "datasets:PATH".
// Checks types, finiteness, planarity and convexity of vertex polygons, non-zero normals,
// ups not parallel to normals, positive sizes, outlines, and that every texture loads.
Scene read_scene_file(const std::string& path);

// Parses scene text; `origin` names the source in errors, `base_dir` resolves texture paths.
Scene parse_scene(const std::string& text, const std::string& origin, const std::string& base_dir);

// The JSON of a scene in the rectangle form, with `texture_files[i]` written as the file of
// texture i (a path as read_scene_file resolves it).
nlohmann::json scene_to_json(const Scene& scene, const std::vector<std::string>& texture_files);

// A scene argument: an existing file is used as is; otherwise a shipped scene name
// (datasets/scenes/NAME.json). Throws std::runtime_error listing the shipped names.
std::string resolve_scene_path(const std::string& name_or_file);
std::vector<std::string> shipped_scene_names();

// The shared tile texture of the shipped scenes (datasets/textures/tile.png).
std::string tile_texture_path();

}  // namespace oflab
