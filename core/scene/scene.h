// A static scene of convex textured polygons: the scenes of the dissertation's second
// experiment (sections 5.5 and 6.6, Fig. 25). Reading scene files is analysis/formats/scene_file.h;
// this is the data model shared by the BSP tree, the culling and the scene animator.
//
// Each polygon lies on a plane and carries a texture on a rectangle of that plane, the
// "texture rectangle" of core/flow/plane.h: centre C, unit up U, unit front normal F and
// size (width along the right axis R = U x F, height along U), in world units. The polygon
// itself is a convex outline inside that rectangle, given in normalised texture coordinates
// (u right, v down, both in [0, 1]); an empty outline is the whole rectangle. So one
// polygon maps onto one PlaneEngine: its texture layer's valid region is the outline.
//
// Faces are one-sided. The front normal F points to the side the polygon is seen from;
// from there the texture appears unmirrored (texel u grows along R, v grows along -U).
// In PlanePose terms the plane normal is N = -F (core/flow/plane.h: N points away from the viewer).
#pragma once

#include <string>
#include <vector>

#include "content/layer_content.h"
#include "flow/plane.h"
#include "image/image.h"
#include "scene/viewer_script.h"

namespace oflab {

struct ScenePolygon {
  std::string name;
  Vec3 centre{0.0};           // C, world units: centre of the texture rectangle
  Vec3 front{0.0, 0.0, 1.0};  // F, unit front normal
  Vec3 up{0.0, 1.0, 0.0};     // U, unit, orthogonal to F
  Vec2 size{1.0, 1.0};        // rectangle width (along R) and height (along U), world units
  int texture = 0;            // index into Scene::textures
  std::vector<Vec2> outline;  // convex, normalised texture coordinates; empty = rectangle
  // What a re-render of the polygon draws (core/content/layer_content.h); the scene
  // settings' engine.content gives the quality and the light.
  ContentKind content = ContentKind::kTexture;
  // A sheet seen from both sides (the single textured plane of the plane and script sources):
  // never culled as back-facing, only edge-on; its back shows the texture mirrored. Scene
  // files' polygons are one-sided (the faces of closed solids), so their backs are culled.
  bool two_sided = false;
};

struct Scene {
  std::string name;
  std::string description;
  std::vector<Image> textures;  // premultiplied RGBA
  // Same length as textures: a name of each image (a scene file's entries naming one file
  // share one image, listed under the first entry's name).
  std::vector<std::string> texture_names;
  std::vector<ScenePolygon> polygons;
  // Quality of the polygons' lit contents (samples per pixel, detail; LayerContent::quality),
  // 0 when the scene does not say (then the run's settings decide).
  int content_quality = 0;
};

// The quality the scene's lit contents play at: the scene's own when it gives one, else
// `setting` (the run's, LayerContent::quality). The one rule of every front-end that plays a
// scene (`oflab-cli animate` unless --quality says otherwise, the window, the benchmarks).
inline int scene_content_quality(const Scene& scene, int setting) {
  return scene.content_quality > 0 ? scene.content_quality : setting;
}

// The outline actually used: polygon.outline, or the unit square when it is empty, as
// normalised texture coordinates in order (either orientation).
std::vector<Vec2> polygon_outline(const ScenePolygon& polygon);

// The right axis R = U x F.
Vec3 polygon_right(const ScenePolygon& polygon);

// World point of normalised texture coordinate (u, v): C + (u - 1/2) w R + (1/2 - v) h U.
Vec3 polygon_point(const ScenePolygon& polygon, const Vec2& uv);

// The outline's vertices in world coordinates, in outline order.
std::vector<Vec3> polygon_vertices(const ScenePolygon& polygon);

// The polygon's texture rectangle seen from `view`, as the PlanePose the engine animates:
// point C, normal -F and up U in viewer coordinates, size, texture size `texture_size`.
PlanePose polygon_pose(const ScenePolygon& polygon, const ViewerPose& view,
                       glm::ivec2 texture_size);

// A single plane as a scene: one polygon, named "plane", on the texture rectangle of `pose`
// (its viewer frame taken as the world), carrying `texture` (premultiplied RGBA). Seen from
// the identity viewer it is exactly `pose`; see viewer_for_pose for any later pose.
Scene plane_as_scene(const PlanePose& pose, const Image& texture);

// The viewer pose from which the polygon of plane_as_scene(first, ...) appears at pose `now`
// (same size): the rotation maps first's plane axes onto now's, the translation carries the
// centre along. Precondition: both poses have valid axes (plane_pose_problem is empty).
ViewerPose viewer_for_pose(const PlanePose& first, const PlanePose& now);

// Builds a polygon from the world-space vertices of a convex planar polygon, ordered
// counter-clockwise when seen from its front (the OBJ and OpenGL convention: the front
// normal is the right-hand-rule normal of the vertex order). The texture rectangle is the
// polygon's bounding rectangle in its plane, with up = `up_hint` made orthogonal to the
// front normal, or, when up_hint is zero, world +Y (world -Z for a polygon facing +-Y).
// Throws std::invalid_argument naming the problem: fewer than 3 vertices, non-finite
// values, zero area, vertices off the plane by more than 1e-4 of the polygon's size
// (non-planar), or a turn against the others (not convex).
ScenePolygon polygon_from_vertices(const std::string& name, const std::vector<Vec3>& vertices,
                                   const Vec3& up_hint, int texture);

// What is wrong with a polygon of `scene`, as {field, message}; field is empty when the
// polygon is usable. Checks finite values, unit and orthogonal front and up (within 1e-6),
// positive size, a texture index in range and a convex outline inside [0, 1]^2.
struct PolygonProblem {
  std::string field;
  std::string message;
};
PolygonProblem scene_polygon_problem(const Scene& scene, const ScenePolygon& polygon);

// True when every texel the polygon can show (the outline's bounding box in texels, grown
// by one texel for nearest and bilinear neighbours) is fully opaque: such a polygon hides
// whatever lies behind its image.
bool polygon_is_opaque(const ScenePolygon& polygon, const Image& texture);

}  // namespace oflab
