// Textured depth meshes: the `depth-mesh` policy of core/engine/reuse_policy.h
// (manual/policies.md "Textured depth meshes").
//
// What it models. Sillion, Drettakis and Bodelet, "Efficient impostor manipulation for
// real-time visualization of urban scenery", Eurographics 97 (the dissertation's chapter 2):
// the scene is split at a distance from the viewer; the near part is rendered every frame, the
// far part is replaced by a mesh built from a rendered depth image of it, textured with that
// image's colours, and drawn from each new viewpoint with a depth test against the near part.
// Triangles across a depth discontinuity stretch into "rubber sheets"; the paper's remedy is to
// drop them, which leaves holes.
// This is oflab's own clean-room version, written from that description:
//   split    a polygon is far when every vertex of its outline lies at view depth Z >= split
//            from the viewer of the build (far_polygons); the others are near;
//   mesh     a regular grid of vertices on the pixel corners of the far part's render, every
//            `grid_px` pixels (the last row and column on the image's edge), each lifted to 3D
//            by the nearest surface among the (up to four) pixels that touch its corner: that
//            surface's plane (DepthFrame::planes) evaluated at the corner, so a vertex lies on
//            a surface exactly; a corner that touches only background is a background vertex;
//            each grid cell is two triangles (split along the diagonal from its top-left);
//   sheets   a triangle is a rubber sheet when its vertices' depths differ by more than
//            `max_depth_jump` relative to the nearest (Z_max / Z_min - 1), or when some but not
//            all of its vertices are background; dropped (default) or drawn, a background
//            vertex then lifted to the farthest surface vertex's depth (a depth buffer's far
//            plane); a triangle of three background vertices is not drawn (nothing is there);
//   draw     every triangle projected into the view after the viewer's step and rasterised at
//            pixel centres (barycentric, edges inclusive), the source position in the render
//            interpolated perspective-correctly and sampled nearest, nearest surface kept (its
//            inverse depth interpolated in the image, exact for a planar triangle); a sample of
//            the render's background leaves the pixel unreached; a triangle with a vertex at
//            Z <= near is dropped.
// For a single plane every vertex lies on it, so its mesh is the plane itself: only resampling
// errs. A triangle across a crease (two planes at one depth) cuts the corner: the method's
// approximation error, which the per-pixel error measures.
//
// Error (a diagnostic, as depth reprojection's): for a mesh pixel shown, the distance between
// its centre and the exact projection now of the surface point at the centre of the render's
// pixel it shows (that pixel's own depth, moved by the step), pixels.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "flow/camera.h"
#include "flow/reprojection.h"
#include "image/image.h"
#include "scene/depth_reprojection.h"
#include "scene/scene.h"
#include "scene/viewer_script.h"

namespace oflab {

// The settings of the depth-mesh policy (SceneSettings::mesh).
struct DepthMeshSettings {
  int grid_px = 4;  // k: a vertex every k pixels (limits::kMeshGrid, as the others below)
  // View depth (world units) beyond which a polygon is far; 0: automatic, the middle of the
  // nearest and farthest surface depth seen at frame 0 (automatic_split), kept for the run.
  double split = 0.0;
  // Viewer travel since the build (world units) that rebuilds the mesh before its cadence
  // frame; 0: none, the cadence alone.
  double rebuild_distance = 0.0;
  double max_depth_jump = 0.1;     // relative depth jump of a rubber sheet (> 0)
  bool drop_rubber_sheets = true;  // false: draw them stretched
};

// "" when the settings are within their limits (core/flow/limits.h kMeshGrid, kMeshSplit,
// kMeshRebuild, kMeshJump), else the first problem, naming the setting and its range.
std::string depth_mesh_settings_problem(const DepthMeshSettings& settings);

// The middle (Z_min + Z_max) / 2 of the view depths (world units) of the pixels of `depth`
// showing a surface; 0 when none does.
double automatic_split(const DepthFrame& depth);

// Per polygon of `scene`, 1 when every vertex of its outline lies at view depth Z >= split seen
// from `view` (the far part), else 0.
std::vector<char> far_polygons(const Scene& scene, const ViewerPose& view, double split);

struct DepthMesh {
  int columns = 0;  // vertices per row
  int rows = 0;     // vertices per column
  // Per vertex, row-major: its position in the render (top-left pixels), its point in the
  // viewer frame of the render (world units; meaningless for a background vertex).
  std::vector<Vec2> positions;
  std::vector<Vec3> points;
  std::vector<char> background;
  std::vector<std::array<int, 3>> triangles;  // the triangles drawn (vertex indices)
  int rubber_sheets = 0;                      // triangles over a depth jump, dropped or drawn
  int dropped = 0;                            // rubber sheets dropped
};

// The mesh of a far render's depth (see the header's "mesh" and "sheets"). Preconditions:
// depth has the camera's size and its planes cover every polygon index it shows;
// 1 <= grid_px <= 64; max_depth_jump > 0.
DepthMesh build_depth_mesh(const DepthFrame& depth, const Camera& camera, int grid_px,
                           double max_depth_jump, bool drop_rubber_sheets);

struct MeshDraw {
  Image image;                        // camera-sized, premultiplied; unreached transparent
  std::vector<double> inverse_depth;  // per pixel, 1/Z now (world units^-1); 0: unreached
  std::vector<int> source;            // per pixel, the render's pixel shown; -1: unreached
  std::int64_t pixels_written = 0;    // pixel writes (a pixel may be written twice)
  int triangles_drawn = 0;            // triangles with a pixel centre inside
};

// The mesh drawn from the viewer after `step` (viewer_step from the render's viewer), textured
// by `rendered` (the far render it was built from, with `depth`). Preconditions: rendered and
// depth have the camera's size and are those of the mesh.
MeshDraw draw_depth_mesh(const DepthMesh& mesh, const Image& rendered, const DepthFrame& depth,
                         const Camera& camera, const RigidStep3& step, double near);

// The error of showing render pixel `source` (showing a surface of `depth`) at pixel `pixel`
// after `step` (see the header), pixels; 0 when the point is at or behind the eye now.
double mesh_pixel_error(const DepthFrame& depth, const Camera& camera, const RigidStep3& step,
                        int source, int pixel);

struct MeshFrame {
  Image image;                   // camera-sized, premultiplied
  std::vector<char> unreached;   // per pixel: neither the near part nor the mesh reached it
  std::vector<int> source;       // the mesh's source pixel, the pixel itself where only the
                                 // near part shows, -1 where unreached
  std::vector<char> mesh_shown;  // per pixel: the mesh's pixel shows (not behind opaque near)
};

// The near part's render (`near_image`, its depth `near_depth`) and the drawn mesh merged per
// pixel by depth: the nearer over the farther ("over", premultiplied), either alone where the
// other reached nothing. Preconditions: all have the camera's size.
MeshFrame merge_near_and_mesh(const Image& near_image, const DepthFrame& near_depth,
                              const MeshDraw& mesh);

}  // namespace oflab
