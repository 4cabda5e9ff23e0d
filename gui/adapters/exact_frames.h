// The exact projection of an animator's frame for the animation view's exact panel, drawn by
// one of a table of renderers:
//
//  - "core" (the default): core's own exact render, the scene animator re-rendering every
//    visible polygon from the frame's view (core/scene/scene_animator.h with the rerender
//    policy: one exact perspective warp of each texture, core/engine/exact_render.h
//    exact_texture_warp, or the lit content rendered for the pose; BSP order; clipping at
//    the near plane). It is the picture the engine's re-render level and the analysis's
//    exact baseline (analysis/runs/source_kinds.h) draw, with the engine's own content
//    (texture, shaded, impostor; core/content/layer_content.h). A few milliseconds.
//  - "vtk": the same scene drawn independently by VTK's OpenGL pipeline
//    (analysis/runs/vtk_scene_renderer.h): textured polygons, depth buffer, depth peeling
//    for cut-out textures, read back from the GPU. It draws every polygon's texture
//    unlit, whatever its content, and costs some 20 ms a frame on software OpenGL; it is
//    the conventional renderer the two are checked against (tests/gui/views/).
//
// Adding a renderer is adding an entry to exact_renderers(); the view's picker, the
// command line and session files read the table.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "engine/animator.h"

namespace oflab {

// Draws the exact frames of one scene seen through one camera.
class ExactFrameRenderer {
 public:
  virtual ~ExactFrameRenderer() = default;
  // The scene seen from `view`: camera-sized, premultiplied RGBA, transparent where nothing
  // is drawn. The reference stays valid until the next call or the renderer's end.
  virtual const Image& render(const ViewerPose& view) = 0;
};

struct ExactRendererKind {
  std::string name;   // command line and session files: "core", "vtk"
  std::string label;  // the view's picker
  std::string title;  // the exact panel's title
  // A renderer of `scene` (copied) through `camera`, with the engine settings of the
  // animation (their content, sampling, near plane and guard band; the policy is ignored).
  // Throws std::runtime_error when the renderer cannot start (VTK without a display) and
  // std::invalid_argument for a scene the scene animator refuses.
  std::unique_ptr<ExactFrameRenderer> (*make)(const Scene& scene, const Camera& camera,
                                              const EngineSettings& settings);
};

// The renderers, the default ("core") first.
const std::vector<ExactRendererKind>& exact_renderers();
// The renderer named `name`, or nullptr.
const ExactRendererKind* find_exact_renderer(const std::string& name);
// The names joined by `separator` (error messages, usage).
std::string exact_renderer_names(const std::string& separator = ", ");

}  // namespace oflab
