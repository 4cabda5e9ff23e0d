#include "player/animation_sources.h"

#include <ostream>

#include "formats/datasets.h"
#include "formats/scene_file.h"
#include "formats/script_file.h"
#include "formats/viewer_script_file.h"
#include "player/plane_panel.h"
#include "runs/source_kinds.h"

namespace oflab {
namespace {

constexpr const char* kOpticFlowTitle = "optic-flow animation (%1)";

// The run source of a plane kind: the scene panel's texture moved by a motion script.
RunSource plane_source(MotionScript script, const PlanePanel& panel,
                       const EngineSettings& settings) {
  RunSource source;
  source.script = std::move(script);
  source.texture = panel.texture();
  source.settings.engine = settings;
  return source;
}

// The run source of a scene kind: a scene and the viewer script walking through it. Scene
// shifting keeps its own tolerance (SceneShiftingSettings::epsilon_px, as `oflab-cli
// animate` does by default) and takes the sampling of the engine settings; its polygons show
// the contents its file gives, at its quality when it gives one.
RunSource scene_source(const SourceChoice& choice, const EngineSettings& settings) {
  RunSource source;
  source.scene = std::make_shared<const Scene>(read_scene_file(resolve_scene_path(choice.name)));
  source.viewer = read_viewer_script_file(resolve_viewer_script_path(choice.viewer));
  source.settings.engine = settings;
  // The polygons keep their own contents and the scene's quality, as `oflab-cli animate`.
  source.settings.engine.content.quality =
      scene_content_quality(*source.scene, settings.content.quality);
  source.shifting.sampling = settings.sampling;
  return source;
}

using ReadSource = RunSource (*)(const SourceChoice&, const PlanePanel&, const EngineSettings&);

// A GUI kind playing analysis kind `run_kind` (analysis/runs/source_kinds.h) from the run
// source `read` gives.
AnimationSourceKind kind(std::string name, std::string label, std::string panel_title,
                         bool follows_scene_panel, std::string default_viewer,
                         std::function<std::vector<std::string>()> shipped_names,
                         const char* run_kind, ReadSource read) {
  AnimationSourceKind k{std::move(name),
                        std::move(label),
                        std::move(panel_title),
                        follows_scene_panel,
                        !default_viewer.empty(),
                        std::move(default_viewer),
                        std::move(shipped_names),
                        nullptr,
                        nullptr,
                        nullptr,
                        nullptr};
  const SourceKind& run = source_kind(run_kind);
  k.make = [&run, read](const SourceChoice& choice, const PlanePanel& panel,
                        const EngineSettings& settings) {
    return run.make(read(choice, panel, settings), false);
  };
  k.write_csv = [&run, read](const SourceChoice& choice, const PlanePanel& panel,
                             const EngineSettings& settings, std::ostream& out) {
    PlayOptions options;
    options.baseline = false;
    run.write_csv(out, run.play(read(choice, panel, settings), options));
  };
  return k;
}

std::vector<AnimationSourceKind> make_kinds() {
  const auto none = [] { return std::vector<std::string>{""}; };
  const ReadSource panel = [](const SourceChoice&, const PlanePanel& p, const EngineSettings& s) {
    return plane_source(p.as_script(), p, s);
  };
  const ReadSource script = [](const SourceChoice& c, const PlanePanel& p,
                               const EngineSettings& s) {
    return plane_source(read_script_file(resolve_script_path(c.name)), p, s);
  };
  const ReadSource scene = [](const SourceChoice& c, const PlanePanel&, const EngineSettings& s) {
    return scene_source(c, s);
  };
  const auto plane_script = [](ReadSource read) {
    return [read](const SourceChoice& c, const PlanePanel& p) {
      return read(c, p, EngineSettings()).script;
    };
  };
  AnimationSourceKind plane =
      kind("plane", "Plane of the scene panel", kOpticFlowTitle, true, "", none, "plane", panel);
  plane.plane_script = plane_script(panel);
  AnimationSourceKind plane_file = kind("script", "Plane script: %1", kOpticFlowTitle, false, "",
                                        shipped_script_names, "plane", script);
  plane_file.plane_script = plane_script(script);
  AnimationSourceKind shifting =
      kind("scene-shifting", "Scene shifting: %1", "scene shifting (slices)", false,
           "train-sideways", shipped_scene_names, "scene-shifting", scene);
  shifting.uses_reuse_policy = false;  // its slices follow epsilon (core/scene_shifting)
  AnimationSourceKind scenes = kind("scene", "Scene: %1", kOpticFlowTitle, false, "circle",
                                    shipped_scene_names, "scene", scene);
  const auto viewer_script = [](const SourceChoice& c) {
    return read_viewer_script_file(resolve_viewer_script_path(c.viewer));
  };
  scenes.viewer_script = viewer_script;
  shifting.viewer_script = viewer_script;
  return {plane, plane_file, scenes, shifting};
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

std::string describe_source(const SourceChoice& choice) {
  const AnimationSourceKind* kind = find_animation_source_kind(choice.kind);
  if (!kind) return choice.kind;
  std::string text = fill_pattern(kind->label, choice.name);
  if (kind->uses_viewer && !choice.viewer.empty()) text += ", viewer script " + choice.viewer;
  return text;
}

std::string animation_source_kind_names() {
  std::string names;
  for (const AnimationSourceKind& kind : animation_source_kinds()) {
    names += (names.empty() ? "" : ", ") + kind.name;
  }
  return names;
}

FrameBounds source_frame_bounds(const SourceChoice& choice, const PlanePanel& panel,
                                const Scene* scene, double near) {
  const AnimationSourceKind* kind = find_animation_source_kind(choice.kind);
  try {
    if (kind && kind->plane_script)
      return script_frame_bounds(kind->plane_script(choice, panel), near);
    if (kind && kind->viewer_script && scene) {
      return scene_frame_bounds(*scene, kind->viewer_script(choice), near);
    }
  } catch (const std::exception&) {  // the lab refuses such sources with a message
  }
  return {};
}

}  // namespace oflab
