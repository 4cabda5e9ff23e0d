#include "formats/obj_scene.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "formats/json_fields.h"
#include "formats/scene_file.h"

namespace oflab {
namespace {

// A face: the 0-based position index of each vertex and the line it was read from.
struct ObjFace {
  std::vector<int> vertices;
  int line = 0;
};

// What the reader has seen so far, and where it is.
struct ObjReader {
  std::string origin;
  int line = 0;
  std::vector<Vec3> positions;
  int texture_coordinates = 0;
  int normals = 0;
  std::vector<ObjFace> faces;

  [[noreturn]] void fail(const std::string& message) const {
    throw SceneError(origin + ": line " + std::to_string(line) + ": " + message);
  }
};

double coordinate(const std::string& token, const ObjReader& r) {
  // Decimal only (strtod would read "0x10" as 16); a subnormal such as 1e-310 is finite and
  // kept, a value too large for a double reads as infinity.
  char* end = nullptr;
  const double v = std::strtod(token.c_str(), &end);
  if (token.empty() || token.find_first_of("xX") != std::string::npos ||
      end != token.c_str() + token.size() || !std::isfinite(v) ||
      std::abs(v) > json_fields::kMaxMagnitude) {
    r.fail("'" + token + "' is not a finite number of magnitude at most 1e6");
  }
  return v;
}

// The 0-based index of an OBJ index (1-based, or negative: relative to the end) among `count`
// elements of `kind` read so far.
int resolve_index(const std::string& token, int count, const char* kind, const ObjReader& r) {
  errno = 0;
  char* end = nullptr;
  const long i = std::strtol(token.c_str(), &end, 10);
  if (token.empty() || end != token.c_str() + token.size() || errno == ERANGE || i == 0) {
    r.fail("'" + token + "' is not a " + kind + " index (a non-zero whole number)");
  }
  const long index = i > 0 ? i - 1 : count + i;
  if (index < 0 || index >= count) {
    r.fail(std::string(kind) + " index " + token + " is out of range (" + std::to_string(count) +
           " read before this line)");
  }
  return static_cast<int>(index);
}

// One face corner "p", "p/t", "p//n" or "p/t/n": checks every index, returns the position's.
int face_corner(const std::string& token, ObjReader& r) {
  std::vector<std::string> parts;
  std::stringstream in(token);
  for (std::string part; std::getline(in, part, '/');) parts.push_back(part);
  if (!token.empty() && token.back() == '/') parts.push_back("");
  if (parts.empty() || parts.size() > 3) r.fail("'" + token + "' is not a face vertex");
  const int position = resolve_index(parts[0], int(r.positions.size()), "vertex", r);
  if (parts.size() > 1 && !parts[1].empty()) {
    (void)resolve_index(parts[1], r.texture_coordinates, "texture coordinate", r);
  }
  if (parts.size() > 2) (void)resolve_index(parts[2], r.normals, "normal", r);
  return position;
}

void read_line(const std::string& text, ObjReader& r) {
  std::istringstream in(text.substr(0, text.find('#')));
  std::string keyword, token;
  if (!(in >> keyword)) return;
  std::vector<std::string> tokens;
  while (in >> token) {
    if (tokens.size() > size_t(kMaxObjFaceVertices)) {
      r.fail("more than " + std::to_string(kMaxObjFaceVertices) + " values on one line");
    }
    tokens.push_back(token);
  }
  if (keyword == "v") {
    if (tokens.size() < 3 || tokens.size() > 4) r.fail("a vertex needs 3 coordinates");
    if (r.positions.size() >= size_t(kMaxObjVertices)) {
      r.fail("more than " + std::to_string(kMaxObjVertices) + " vertices");
    }
    r.positions.emplace_back(coordinate(tokens[0], r), coordinate(tokens[1], r),
                             coordinate(tokens[2], r));
  } else if (keyword == "vt" || keyword == "vn") {
    int& count = keyword == "vt" ? r.texture_coordinates : r.normals;
    if (count >= kMaxObjVertices) r.fail("more than 1000000 '" + keyword + "' lines");
    ++count;
  } else if (keyword == "f") {
    if (tokens.size() < 3) r.fail("a face needs at least 3 vertices");
    if (r.faces.size() >= size_t(kMaxScenePolygons)) {
      r.fail("more than " + std::to_string(kMaxScenePolygons) + " faces");
    }
    ObjFace face;
    face.line = r.line;
    for (const std::string& t : tokens) face.vertices.push_back(face_corner(t, r));
    r.faces.push_back(std::move(face));
  }
}

}  // namespace

Scene parse_obj_scene(const std::string& text, const std::string& origin, const Image& texture,
                      const std::string& texture_name) {
  ObjReader r;
  r.origin = origin;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    ++r.line;
    read_line(line, r);
  }
  if (r.faces.empty()) {
    throw SceneError(origin + ": no polygonal faces (is it a Wavefront OBJ file with 'f' lines?)");
  }
  Scene scene;
  scene.name = std::filesystem::path(origin).stem().string();
  scene.description = "imported from " + origin;
  scene.textures.push_back(texture);
  scene.texture_names.push_back(texture_name);
  for (std::size_t i = 0; i < r.faces.size(); ++i) {
    std::vector<Vec3> vertices;
    for (int v : r.faces[i].vertices) vertices.push_back(r.positions[size_t(v)]);
    const std::string name = "face " + std::to_string(i);
    try {
      scene.polygons.push_back(polygon_from_vertices(name, vertices, Vec3(0.0), 0));
    } catch (const std::invalid_argument& e) {
      throw SceneError(origin + ": " + name + " (line " + std::to_string(r.faces[i].line) +
                       "): " + e.what());
    }
  }
  return scene;
}

Scene read_obj_scene(const std::string& path, const Image& texture,
                     const std::string& texture_name) {
  return parse_obj_scene(json_fields::read_file_text<SceneError>(path), path, texture,
                         texture_name);
}

}  // namespace oflab
