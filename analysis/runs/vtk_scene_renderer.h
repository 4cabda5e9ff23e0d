// The conventional baseline of Experiment 2 (dissertation section 6.7.2): the same scene
// rendered from scratch every frame by VTK's OpenGL pipeline (textured polygons, depth
// buffer, backface culling, nearest-texel sampling; lit contents as their geometry and
// materials), offscreen, with the camera of core/flow/camera.h. VTK stays behind this
// interface.
//
// Camera. The VTK camera sits at the viewer's eye, looks along the viewer's +Z and has the
// viewer's -Y as its view-up, so that image rows grow with Y as in core/flow/camera.h; its
// vertical view angle is 2 atan(H / 2f) and the near clipping plane is the scene
// animator's (SceneSettings::near). Textures are uploaded once, unlit, without mipmaps or
// interpolation; texture row 0 of a core image is its top row.
//
// Display. Debian's VTK renders through X11 only: construct the renderer where an X
// display is available (run under `xvfb-run -a` on headless machines); the constructor
// throws std::runtime_error when $DISPLAY is not set or no connection can be made. All
// renderers share the process's one X connection (shared_x_display in analysis/report/charts.h).
#pragma once

#include <memory>

#include "flow/camera.h"
#include "image/image.h"
#include "scene/scene.h"
#include "scene/viewer_script.h"

namespace oflab {

class VtkSceneRenderer {
 public:
  // Builds one textured vtkPolyData actor per scene texture for the polygons of texture
  // content, and the actors of the lit contents (analysis/runs/vtk_content_actors.h: the
  // impostors' facade geometry, the shaded brick) with `content`'s light and quality (the
  // scene's content_quality when it gives one), lit by a directional light fixed to the
  // viewer as the engine's. With `multisample`, a scene with shaded polygons at more than one
  // sample per pixel is multisampled with that many samples (OpenGL rounds up to a supported
  // count), as the engine supersamples them; otherwise one sample per pixel. `scene`
  // is copied into VTK's structures and need not outlive the renderer. Throws
  // std::runtime_error without a display or when VTK cannot create an OpenGL context, and
  // std::invalid_argument for a lit scene with an invalid content (content_problem).
  VtkSceneRenderer(const Scene& scene, const Camera& camera, double near,
                   const LayerContent& content = LayerContent{}, bool multisample = false);
  ~VtkSceneRenderer();
  VtkSceneRenderer(const VtkSceneRenderer&) = delete;
  VtkSceneRenderer& operator=(const VtkSceneRenderer&) = delete;

  // Renders the scene seen from `view` and reads the frame back into memory (so the time
  // covers a finished frame, as the engine's does). Returns the wall time in milliseconds.
  double render(const ViewerPose& view);

  // The last rendered frame: camera-sized, premultiplied RGBA (transparent where nothing
  // was drawn), top row first.
  const Image& image() const { return image_; }

 private:
  void add_lit_contents(const Scene& scene, const LayerContent& content);
  struct Impl;
  std::unique_ptr<Impl> impl_;
  Image image_;
};

// True when an X display is available for VTK ($DISPLAY is set and not empty).
bool display_available();

}  // namespace oflab
