// Scenes made elsewhere: the planar faces of a Wavefront OBJ file become the convex textured
// polygons of core/scene/scene.h. The file is read by oflab's own checked reader (not VTK's
// vtkOBJReader, which reads out of range on bad indices): every count, coordinate and index
// is checked before it is used.
#pragma once

#include <string>

#include "image/image.h"
#include "scene/scene.h"

namespace oflab {

// Limits of an OBJ file: vertices ('v' lines), faces ('f' lines, at most kMaxScenePolygons of
// analysis/formats/scene_file.h) and vertices per face; coordinates are finite with magnitude
// at most 1e6, as in oflab's JSON files.
constexpr int kMaxObjVertices = 1000000;
constexpr int kMaxObjFaceVertices = 1000;

// Reads every polygonal face of `path` (points, lines, normals, texture coordinates, groups and
// materials are read only to check their indices) as one scene polygon with `texture`
// (polygon_from_vertices in core/scene/scene.h: the front is the side from which the face's
// vertices run counter-clockwise, as OBJ files are written; the texture covers the face's
// bounding rectangle in its plane, up along world +Y, or -Z for faces facing +-Y). Faces must be
// planar and convex: triangulate other meshes before importing them. Indices are 1-based, or
// negative (relative to the last element read), and must name an element read before them.
// Throws SceneError (analysis/formats/scene_file.h) naming the file, the line or the face and
// the limit: an unreadable file, a bad number or index, a limit exceeded, no faces, or a face
// that is not planar, not convex or degenerate.
Scene read_obj_scene(const std::string& path, const Image& texture,
                     const std::string& texture_name);

// The same from OBJ text; `origin` names the source in errors.
Scene parse_obj_scene(const std::string& text, const std::string& origin, const Image& texture,
                      const std::string& texture_name);

}  // namespace oflab
