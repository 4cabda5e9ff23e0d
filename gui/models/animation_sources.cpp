#include "models/animation_sources.h"

#include <QImage>
#include <cstring>
#include <ostream>

#include "formats/datasets.h"
#include "formats/scene_file.h"
#include "formats/script_file.h"
#include "formats/viewer_script_file.h"
#include "models/scene_model.h"
#include "runs/animation_run.h"
#include "runs/scene_run.h"
#include "runs/scene_shifting_run.h"
#include "scene/scene_animator.h"
#include "scene_shifting/scene_shifting_renderer.h"

namespace oflab {
namespace {

constexpr const char* kOpticFlowTitle = "optic-flow animation (%1)";

Image image_from_qimage(const QImage& texture) {
  const QImage rgba = texture.convertToFormat(QImage::Format_RGBA8888_Premultiplied);
  Image image(rgba.width(), rgba.height());
  for (int y = 0; y < rgba.height(); ++y) {
    std::memcpy(image.row(y), rgba.constScanLine(y), size_t(rgba.width()) * 4);
  }
  return image;
}

// The plane kinds: the scene panel's texture moved by `script`.
struct PlaneSource {
  MotionScript script;
  Image texture;
};

PlaneSource panel_plane(const SourceChoice&, const SceneModel& panel) {
  return {panel.as_script(), image_from_qimage(panel.texture())};
}

PlaneSource scripted_plane(const SourceChoice& choice, const SceneModel& panel) {
  return {read_script_file(resolve_script_path(choice.name)), image_from_qimage(panel.texture())};
}

// A kind entry's make and write_csv for a plane source read by `read`.
template <class Read>
void set_plane_functions(AnimationSourceKind& kind, Read read) {
  kind.make = [read](const SourceChoice& choice, const SceneModel& panel,
                     const EngineSettings& settings) {
    const PlaneSource source = read(choice, panel);
    return make_plane_animator(source.script, source.texture, settings);
  };
  kind.write_csv = [read](const SourceChoice& choice, const SceneModel& panel,
                          const EngineSettings& settings, std::ostream& out) {
    const PlaneSource source = read(choice, panel);
    AnimationOptions options;
    options.settings = settings;
    options.run_baseline = false;
    write_frame_csv(out, run_animation(source.script, make_layer(source.texture), options));
  };
}

// The scene kinds: a shipped or file scene and the viewer script walking through it.
struct SceneSource {
  std::shared_ptr<const Scene> scene;
  ViewerScript viewer;
};

SceneSource read_scene_source(const SourceChoice& choice) {
  return {std::make_shared<const Scene>(read_scene_file(resolve_scene_path(choice.name))),
          read_viewer_script_file(resolve_viewer_script_path(choice.viewer))};
}

SceneSettings scene_settings(const EngineSettings& settings) {
  SceneSettings s;
  s.engine = settings;
  return s;
}

// Scene shifting keeps its own tolerance (SceneShiftingSettings::epsilon_px, as `oflab-cli
// animate` does by default); it takes the sampling of the engine settings.
SceneShiftingSettings scene_shifting_settings(const EngineSettings& settings) {
  SceneShiftingSettings s;
  s.sampling = settings.sampling;
  return s;
}

AnimationSourceKind scene_kind() {
  AnimationSourceKind kind{"scene", "Scene: %1", kOpticFlowTitle, false, true, "circle",
                           shipped_scene_names, nullptr, nullptr};
  kind.make = [](const SourceChoice& choice, const SceneModel&, const EngineSettings& settings)
      -> std::unique_ptr<Animator> {
    SceneSource source = read_scene_source(choice);
    return make_scene_animator(source.scene, std::move(source.viewer), scene_settings(settings));
  };
  kind.write_csv = [](const SourceChoice& choice, const SceneModel&,
                      const EngineSettings& settings, std::ostream& out) {
    const SceneSource source = read_scene_source(choice);
    SceneRunOptions options;
    options.settings = scene_settings(settings);
    options.run_baseline = false;
    write_scene_frame_csv(out, run_scene_animation(*source.scene, source.viewer, options));
  };
  return kind;
}

AnimationSourceKind scene_shifting_kind() {
  AnimationSourceKind kind{"scene-shifting", "Scene shifting: %1", "scene shifting (slices)",
                           false, true, "train-sideways", shipped_scene_names, nullptr, nullptr};
  kind.make = [](const SourceChoice& choice, const SceneModel&, const EngineSettings& settings)
      -> std::unique_ptr<Animator> {
    SceneSource source = read_scene_source(choice);
    return make_scene_shifting_animator(source.scene, std::move(source.viewer),
                                        scene_shifting_settings(settings));
  };
  kind.write_csv = [](const SourceChoice& choice, const SceneModel&,
                      const EngineSettings& settings, std::ostream& out) {
    const SceneSource source = read_scene_source(choice);
    SceneShiftingRunOptions options;
    options.settings = scene_shifting_settings(settings);
    options.run_baseline = false;
    write_scene_frame_csv(out, run_scene_shifting(*source.scene, source.viewer, options).scene_run);
  };
  return kind;
}

std::vector<AnimationSourceKind> make_kinds() {
  AnimationSourceKind panel{"plane", "Plane of the scene panel", kOpticFlowTitle, true, false, "", nullptr,
                            nullptr, nullptr};
  panel.shipped_names = [] { return std::vector<std::string>{""}; };
  set_plane_functions(panel, panel_plane);
  AnimationSourceKind script{"script", "Plane script: %1", kOpticFlowTitle, false, false, "", shipped_script_names,
                             nullptr, nullptr};
  set_plane_functions(script, scripted_plane);
  return {panel, script, scene_kind(), scene_shifting_kind()};
}

}  // namespace

const std::vector<AnimationSourceKind>& animation_source_kinds() {
  static const std::vector<AnimationSourceKind> kinds = make_kinds();
  return kinds;
}

const AnimationSourceKind* find_animation_source_kind(const std::string& name) {
  for (const AnimationSourceKind& kind : animation_source_kinds()) {
    if (kind.name == name) return &kind;
  }
  return nullptr;
}

std::string fill_pattern(const std::string& pattern, const std::string& value) {
  const size_t at = pattern.find("%1");
  return at == std::string::npos ? pattern : pattern.substr(0, at) + value + pattern.substr(at + 2);
}

std::string animation_source_kind_names() {
  std::string names;
  for (const AnimationSourceKind& kind : animation_source_kinds()) {
    names += (names.empty() ? "" : ", ") + kind.name;
  }
  return names;
}

}  // namespace oflab
