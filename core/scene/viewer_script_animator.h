// The Animator (core/engine/animator.h) of a scene renderer playing a viewer script: frame
// k of the script is the renderer's view of the scene from script.frames[k].pose, reached by
// the renderer's own start and advance. Shared by the scene animator
// (core/scene/scene_animator.h) and scene shifting
// (core/scene_shifting/scene_shifting_renderer.h).
//
// Renderer requirements: constructible from (const Scene&, const Camera&, const Settings&);
// AnimationFrame start(const ViewerPose&); AnimationFrame advance(const ViewerPose& previous,
// const RigidMotion&, const ViewerPose& current); const Image& frame() const (the composed
// frame); std::vector<LayerOutline> outlines(const ViewerPose& view) const. A renderer with
// set_future_views(std::function<bool(int, ViewerPose&)>) is also given the script's views to
// come (the scene engine's view interpolation renders the next render's ahead).
#pragma once

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

#include "engine/animator.h"
#include "scene/scene.h"
#include "scene/viewer_script.h"

namespace oflab {

// Whether Renderer takes the views to come (set_future_views).
template <class Renderer, class = void>
struct TakesFutureViews : std::false_type {};
template <class Renderer>
struct TakesFutureViews<Renderer, std::void_t<decltype(std::declval<Renderer&>().set_future_views(
                                      std::declval<bool (*)(int, ViewerPose&)>()))>>
    : std::true_type {};

template <class Renderer, class Settings>
class ViewerScriptAnimator final : public Animator {
 public:
  // Keeps `scene` alive for the renderer. Throws std::invalid_argument when the scene is null
  // or the script has no frames, and whatever the renderer's constructor throws.
  ViewerScriptAnimator(std::shared_ptr<const Scene> scene, ViewerScript script,
                       const Settings& settings)
      : scene_(checked(std::move(scene), script)),
        script_(std::move(script)),
        renderer_(*scene_, script_.camera, settings) {
    if constexpr (TakesFutureViews<Renderer>::value) {
      // The animator owns the renderer and is neither copied nor moved: `this` stays valid.
      renderer_.set_future_views([this](int k, ViewerPose& pose) {
        if (k < 0 || k >= frame_count()) return false;
        pose = script_.frames[static_cast<std::size_t>(k)].pose;
        return true;
      });
    }
  }

  int frame_count() const override { return static_cast<int>(script_.frames.size()); }
  int frame() const override { return frame_; }

  AnimationFrame start() override {
    frame_ = 0;
    return renderer_.start(script_.frames[0].pose);
  }

  AnimationFrame advance() override {
    const ViewerFrame& previous = script_.frames.at(static_cast<std::size_t>(frame_));
    ++frame_;
    return renderer_.advance(previous.pose, previous.motion,
                             script_.frames.at(static_cast<std::size_t>(frame_)).pose);
  }

  const Image& image() const override { return renderer_.frame(); }
  const Camera& camera() const override { return script_.camera; }
  std::vector<LayerOutline> outlines() const override { return renderer_.outlines(view()); }
  const Scene& scene() const override { return *scene_; }
  ViewerPose view() const override {
    return script_.frames[static_cast<std::size_t>(std::max(frame_, 0))].pose;
  }

  // The renderer, for what only this kind reports (e.g. the BSP tree, the slices).
  const Renderer& renderer() const { return renderer_; }
  const ViewerScript& script() const { return script_; }

 private:
  static std::shared_ptr<const Scene> checked(std::shared_ptr<const Scene> scene,
                                              const ViewerScript& script) {
    if (!scene) throw std::invalid_argument("no scene");
    if (script.frames.empty()) throw std::invalid_argument("the viewer script has no frames");
    return scene;
  }

  std::shared_ptr<const Scene> scene_;
  ViewerScript script_;
  Renderer renderer_;
  int frame_ = -1;
};

}  // namespace oflab
