// The conventional baseline (analysis/runs/vtk_scene_renderer.h) in the browser page: the
// page has no VTK, so constructing one is refused with a one-line reason, as a desktop
// without an X display refuses it. The page never asks for it (PlayOptions::conventional is
// false in every run it plays); the definitions let analysis/runs/source_kinds.cpp, which
// offers it to `oflab-cli animate --conventional`, link into the module unchanged.
#include <stdexcept>

#include "runs/vtk_scene_renderer.h"

namespace oflab {

struct VtkSceneRenderer::Impl {};

VtkSceneRenderer::VtkSceneRenderer(const Scene&, const Camera&, double, const LayerContent&, bool) {
  throw std::runtime_error(
      "the conventional renderer (VTK) is in oflab-cli and the desktop window, not in the "
      "browser page");
}

VtkSceneRenderer::~VtkSceneRenderer() = default;

double VtkSceneRenderer::render(const ViewerPose&) {
  throw std::runtime_error("the conventional renderer (VTK) is not in the browser page");
}

void VtkSceneRenderer::add_lit_contents(const Scene&, const LayerContent&) {}

bool display_available() { return false; }

}  // namespace oflab
