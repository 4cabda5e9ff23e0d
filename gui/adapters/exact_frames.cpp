#include "adapters/exact_frames.h"

#include "runs/vtk_scene_renderer.h"
#include "scene/scene_animator.h"

namespace oflab {
namespace {

// Core's exact render: a scene animator that starts afresh at every view, so every visible
// polygon is re-rendered exactly (a start renders each polygon at the re-render level).
class CoreExactRenderer final : public ExactFrameRenderer {
 public:
  CoreExactRenderer(const Scene& scene, const Camera& camera, const EngineSettings& settings)
      : scene_(scene), animator_(scene_, camera, scene_settings(scene, settings)) {}

  const Image& render(const ViewerPose& view) override {
    animator_.start(view);
    return animator_.frame();
  }

 private:
  // The settings of a re-render of every polygon: the engine's, at the scene's content
  // quality when its file gives one (as the animation's scene source and VTK's renderer).
  static SceneSettings scene_settings(const Scene& scene, const EngineSettings& engine) {
    SceneSettings s;
    s.engine = engine;
    s.engine.content.quality = scene_content_quality(scene, engine.content.quality);
    s.engine.policy = &reuse_policy("rerender");
    s.near = engine.near;
    s.guard_band = engine.guard_band;
    return s;
  }

  Scene scene_;  // the animator keeps a reference: declared first, so it outlives it
  SceneEngine animator_;
};

// VTK's OpenGL pipeline, drawing the lit contents with the engine's light and quality.
class VtkExactRenderer final : public ExactFrameRenderer {
 public:
  VtkExactRenderer(const Scene& scene, const Camera& camera, const EngineSettings& settings)
      : vtk_(scene, camera, settings.near, settings.content) {}

  const Image& render(const ViewerPose& view) override {
    vtk_.render(view);
    return vtk_.image();
  }

 private:
  VtkSceneRenderer vtk_;
};

template <class Renderer>
std::unique_ptr<ExactFrameRenderer> make(const Scene& scene, const Camera& camera,
                                         const EngineSettings& settings) {
  return std::make_unique<Renderer>(scene, camera, settings);
}

}  // namespace

const std::vector<ExactRendererKind>& exact_renderers() {
  static const std::vector<ExactRendererKind> kinds = {
      {"core", "exact warp (core)", "exact projection (core warp)", make<CoreExactRenderer>},
      {"vtk", "exact by VTK (OpenGL)", "exact projection (VTK)", make<VtkExactRenderer>},
  };
  return kinds;
}

const ExactRendererKind* find_exact_renderer(const std::string& name) {
  for (const ExactRendererKind& kind : exact_renderers()) {
    if (kind.name == name) return &kind;
  }
  return nullptr;
}

std::string exact_renderer_names(const std::string& separator) {
  std::string names;
  for (const ExactRendererKind& kind : exact_renderers()) {
    names += (names.empty() ? "" : separator) + kind.name;
  }
  return names;
}

}  // namespace oflab
