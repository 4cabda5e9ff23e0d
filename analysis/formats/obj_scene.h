// Scenes made elsewhere: the planar faces of a Wavefront OBJ file, read with VTK's
// vtkOBJReader, become the convex textured polygons of core/scene/scene.h.
#pragma once

#include <string>

#include "image/image.h"
#include "scene/scene.h"

namespace oflab {

// Reads every polygonal face of `path` (lines and points are ignored) as one scene polygon
// with `texture` (polygon_from_vertices in core/scene/scene.h: the front is the side from which
// the face's vertices run counter-clockwise, as OBJ files are written; the texture covers
// the face's bounding rectangle in its plane, up along world +Y, or -Z for faces facing
// +-Y; the file's own texture coordinates and materials are not used). Faces must be
// planar and convex: triangulate other meshes before importing them.
// Throws SceneError (analysis/formats/scene_file.h) naming the file and the face for an unreadable
// file, a file without faces, or a face that is not planar, not convex or degenerate.
Scene read_obj_scene(const std::string& path, const Image& texture,
                     const std::string& texture_name);

}  // namespace oflab
