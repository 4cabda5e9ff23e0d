#include "formats/scene_file.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>

#include "formats/datasets.h"
#include "formats/image_io.h"
#include "formats/json_fields.h"

namespace oflab {
namespace {

namespace fs = std::filesystem;

using namespace json_fields;
using Where = json_fields::Place<SceneError>;

std::string resolve_texture(const std::string& file, const std::string& base_dir) {
  const std::string prefix = "datasets:";
  if (file.rfind(prefix, 0) == 0)
    return (fs::path(datasets_dir()) / file.substr(prefix.size())).string();
  const fs::path p(file);
  return p.is_absolute() ? file : (fs::path(base_dir) / p).string();
}

// Reads the "textures" object into scene.textures and returns, for every entry's name, the
// index of its image. Each file is read and decoded once: entries naming the same file (by
// its path after links) share the first one's image, which is listed once, under the
// first entry's name.
std::map<std::string, int> read_textures(const json& root, const Where& top,
                                         const std::string& base_dir, Scene& scene) {
  const json& textures = member(root, top, "textures");
  if (!textures.is_object() || textures.empty()) {
    top.fail("textures", "must be an object naming at least one texture file");
  }
  std::map<std::string, int> decoded;  // file after links -> image index
  std::map<std::string, int> by_name;
  for (const auto& [name, file] : textures.items()) {
    const Where w{top.origin, "texture '" + name + "'"};
    if (!file.is_string()) w.fail("", "the file name must be a string");
    const std::string path = resolve_texture(file.get<std::string>(), base_dir);
    std::error_code ec;
    const fs::path real = fs::canonical(path, ec);
    const std::string key = ec ? path : real.string();
    if (const auto it = decoded.find(key); it != decoded.end()) {
      by_name[name] = it->second;
      continue;
    }
    try {
      scene.textures.push_back(read_image(path));
    } catch (const ImageFileError& e) {
      w.fail("", e.what());
    }
    if (scene.textures.back().empty()) w.fail("", "the image '" + path + "' is empty");
    scene.texture_names.push_back(name);
    decoded[key] = by_name[name] = static_cast<int>(scene.textures.size()) - 1;
  }
  return by_name;
}

// The image index of the texture an object names ("texture", or `fallback`).
int texture_index(const json& obj, const Where& w, const std::map<std::string, int>& textures,
                  const std::string& fallback) {
  const std::string name = obj.contains("texture") ? text(obj, w, "texture") : fallback;
  if (name.empty()) w.fail("texture", "is missing and the scene names no default 'texture'");
  const auto it = textures.find(name);
  if (it == textures.end()) w.fail("texture", "'" + name + "' is not in 'textures'");
  return it->second;
}

// The "content" of an object (core/content/layer_content.h), `fallback` when it has none.
ContentKind content_kind(const json& obj, const Where& w, ContentKind fallback) {
  if (!obj.contains("content")) return fallback;
  const std::string name = text(obj, w, "content");
  ContentKind kind = fallback;
  if (!parse_content(name, &kind)) {
    w.fail("content", "'" + name + "' is not one of " + content_name_list());
  }
  return kind;
}

ScenePolygon read_rectangle(const json& obj, const Where& w) {
  ScenePolygon p;
  p.centre = vec3(obj, w, "centre");
  const Vec3 normal = vec3(obj, w, "normal");
  const Vec3 up = vec3(obj, w, "up");
  p.size = limited_vec2(obj, w, "size", limits::kPlaneSize);
  if (glm::length(normal) < 1e-12) w.fail("normal", "must not be zero");
  p.front = glm::normalize(normal);
  const Vec3 in_plane = up - glm::dot(up, p.front) * p.front;
  if (glm::length(in_plane) < 1e-9 * std::max(1e-300, glm::length(up))) {
    w.fail("up", "must be non-zero and not parallel to the normal");
  }
  p.up = glm::normalize(in_plane);
  if (obj.contains("outline")) {
    const json& outline = obj.at("outline");
    if (!outline.is_array() || outline.size() < 3) {
      w.fail("outline", "must be a list of at least 3 [u, v] points");
    }
    for (const json& uv : outline) p.outline.push_back(vec2_value(uv, w, "outline"));
  }
  return p;
}

ScenePolygon read_vertices(const json& obj, const Where& w) {
  const json& list = member(obj, w, "vertices");
  if (!list.is_array() || list.size() < 3)
    w.fail("vertices", "must be a list of at least 3 points");
  std::vector<Vec3> vertices;
  for (const json& v : list) vertices.push_back(vec3_value(v, w, "vertices"));
  const Vec3 up = obj.contains("up") ? vec3(obj, w, "up") : Vec3(0.0);
  try {
    return polygon_from_vertices("", vertices, up, 0);
  } catch (const std::invalid_argument& e) {
    w.fail(std::string(e.what()).find("up") == 0 ? "up" : "vertices", e.what());
  }
}

}  // namespace

Scene parse_scene(const std::string& text_in, const std::string& origin,
                  const std::string& base_dir) {
  const Where top{origin, ""};
  const json root = parse_object(text_in, top);
  if (root.contains("format") && root.at("format") != "oflab-scene") {
    top.fail("format", "must be \"oflab-scene\"");
  }
  Scene scene;
  scene.name = optional_text(root, top, "name", fs::path(origin).stem().string());
  scene.description = optional_text(root, top, "description", "");
  const std::map<std::string, int> textures = read_textures(root, top, base_dir, scene);
  const std::string default_texture = optional_text(root, top, "texture", "");
  if (!default_texture.empty()) (void)texture_index(root, top, textures, "");
  const ContentKind default_content = content_kind(root, top, ContentKind::kTexture);
  if (root.contains("content_quality")) {
    scene.content_quality = limited_integer(root, top, "content_quality", limits::kContentQuality);
  }
  const json& polygons = member(root, top, "polygons");
  if (!polygons.is_array() || polygons.empty()) top.fail("polygons", "must be a non-empty list");
  if (polygons.size() > size_t(kMaxScenePolygons)) {
    top.fail("polygons", "more than " + std::to_string(kMaxScenePolygons) + " polygons");
  }
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    const json& obj = polygons[i];
    Where w{origin, "polygon " + std::to_string(i)};
    if (!obj.is_object()) w.fail("", "must be an object");
    const std::string name =
        obj.contains("name") ? text(obj, w, "name") : "polygon " + std::to_string(i);
    w.part += " ('" + name + "')";
    const bool by_vertices = obj.contains("vertices");
    if (by_vertices && (obj.contains("centre") || obj.contains("outline"))) {
      w.fail("vertices", "give either 'vertices' or 'centre', 'normal', 'up' and 'size'");
    }
    ScenePolygon p = by_vertices ? read_vertices(obj, w) : read_rectangle(obj, w);
    p.name = name;
    p.texture = texture_index(obj, w, textures, default_texture);
    p.content = content_kind(obj, w, default_content);
    const PolygonProblem problem = scene_polygon_problem(scene, p);
    if (!problem.field.empty()) w.fail(problem.field, problem.message);
    scene.polygons.push_back(std::move(p));
  }
  return scene;
}

Scene read_scene_file(const std::string& path) {
  return parse_scene(read_file_text<SceneError>(path), path, fs::path(path).parent_path().string());
}

json scene_to_json(const Scene& scene, const std::vector<std::string>& texture_files) {
  json textures = json::object();
  for (std::size_t i = 0; i < scene.texture_names.size(); ++i) {
    textures[scene.texture_names[i]] = i < texture_files.size() ? texture_files[i] : "";
  }
  json polygons = json::array();
  for (const ScenePolygon& p : scene.polygons) {
    json j = {{"name", p.name},
              {"centre", {p.centre.x, p.centre.y, p.centre.z}},
              {"normal", {p.front.x, p.front.y, p.front.z}},
              {"up", {p.up.x, p.up.y, p.up.z}},
              {"size", {p.size.x, p.size.y}}};
    if (scene.texture_names.size() > 1) j["texture"] = scene.texture_names.at(p.texture);
    if (p.content != ContentKind::kTexture) j["content"] = content_name(p.content);
    if (!p.outline.empty()) {
      json outline = json::array();
      for (const Vec2& uv : p.outline) outline.push_back({uv.x, uv.y});
      j["outline"] = outline;
    }
    polygons.push_back(j);
  }
  json root = {{"format", "oflab-scene"},
               {"version", 1},
               {"name", scene.name},
               {"description", scene.description},
               {"textures", textures}};
  if (!scene.texture_names.empty()) root["texture"] = scene.texture_names[0];
  if (scene.content_quality > 0) root["content_quality"] = scene.content_quality;
  root["polygons"] = polygons;
  return root;
}

std::vector<std::string> shipped_scene_names() { return shipped_names("scenes"); }

std::string resolve_scene_path(const std::string& name_or_file) {
  return resolve_shipped_path(name_or_file, "scenes", "scene");
}

std::string tile_texture_path() {
  return (fs::path(datasets_dir()) / "textures" / "tile.png").string();
}

}  // namespace oflab
