// A scene's lit contents (core/content/layer_content.h) drawn by VTK as a conventional
// renderer draws them: the facade impostors as their real geometry, the shaded brick as a
// baked, normal-mapped texture. Used by the conventional baseline
// (analysis/runs/vtk_scene_renderer.h), so that VTK renders the same geometry and materials
// as the engine's re-render.
//
//  - impostor polygons: the faces of facade_faces(size, quality) placed on the polygon
//    (plane coordinates (s, t, h) at C + s R + t U + h F, scene.h's axes), one actor per
//    facade part over all impostors (five draws however many facades), flat-lit with the
//    part's material, depth-tested, back faces culled. Unlike the engine's layer, the
//    balconies are not cut at the proxy rectangle's outline.
//  - shaded polygons: the polygon's rectangle textured with the brick's albedo and normal
//    map (brick_at) baked at kBrickTexelsPerUnit texels per world unit (at most
//    kMaxBakedTexels a side), mipmapped, trilinearly and anisotropically filtered and lit per
//    fragment through VTK's normal mapping; a baked texture is shared by polygons of equal
//    size. The engine instead evaluates the material per sample (the quality's samples per
//    pixel); the conventional renderer filters a texture and multisamples the frame.
//
// Materials. Ambient kContentAmbient and diffuse kContentDiffuse of the albedo as in the
// engine. VTK's specular is Phong's (reflected light . view)^p rather than Blinn's
// (normal . half vector)^s; near a highlight the first angle is twice the second, so p = s/4
// gives the same highlight width. VTK multiplies a texture into the whole lit colour, so the
// brick's specular is tinted by its albedo (the engine adds it untinted): a small
// difference, bounded by the tests.
#pragma once

#include <vtkSmartPointer.h>

#include <vector>

#include "content/layer_content.h"
#include "scene/scene.h"

class vtkPolyData;
class vtkRenderer;

namespace oflab {

constexpr int kBrickTexelsPerUnit = 256;
constexpr int kMaxBakedTexels = 4096;

// Adds the actors above for every polygon of `scene` whose content is lit, with the
// quality of `content` (detail of the impostors; the shaded polygons' textures do not
// depend on it). The lights are the caller's (the light of `content` is not used here).
// Returns the number of faces added (impostor faces plus one per shaded polygon).
// Preconditions: content_problem(content) is empty, the scene's polygons valid
// (scene_polygon_problem), `renderer` not null.
int add_content_actors(const Scene& scene, const LayerContent& content, vtkRenderer* renderer);

// The outlines of `polygons` (world points, one cell each, counter-clockwise seen from the
// front as VTK culls) with texture coordinates (s, t) = (u, 1 - v) of the normalised
// outline, and per point the front normal F and the tangent R (for normal mapping).
vtkSmartPointer<vtkPolyData> outline_polydata(const std::vector<const ScenePolygon*>& polygons);

// True when some polygon of `scene` has a lit content.
bool scene_has_lit_content(const Scene& scene);

}  // namespace oflab
