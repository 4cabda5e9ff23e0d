#include "player/slice_walk.h"

#include <cstdio>
#include <exception>

#include "engine/reuse_policy.h"
#include "formats/scene_file.h"
#include "formats/viewer_script_file.h"

namespace oflab {
namespace {

// The settings of a re-render of every polygon: the engine's defaults at the scene's content
// quality when its file gives one (as the animation's scene source).
SceneSettings exact_settings(const Scene& scene) {
  SceneSettings s;
  s.engine.content.quality = scene_content_quality(scene, s.engine.content.quality);
  s.engine.policy = &reuse_policy("rerender");
  s.near = s.engine.near;
  s.guard_band = s.engine.guard_band;
  return s;
}

}  // namespace

SliceWalk::SliceWalk() {
  try {
    scene_ = read_scene_file(resolve_scene_path("train-window"));
    script_ = read_viewer_script_file(resolve_viewer_script_path("train-sideways"));
  } catch (const std::exception& e) {
    problem_ = e.what();
  }
  if (problem_.empty() && script_.frames.empty()) problem_ = "the train-sideways walk is empty";
  if (problem_.empty()) {
    try {
      exact_ = std::make_unique<SceneEngine>(scene_, script_.camera, exact_settings(scene_));
    } catch (const std::exception& e) {  // a scene the engine refuses: the slices alone
      exact_problem_ = e.what();
    }
  }
  restart();
}

SliceWalk::~SliceWalk() = default;

void SliceWalk::set_slicing(double epsilon_px, double speed) {
  epsilon_px_ = epsilon_px;
  speed_ = speed;
  restart();
}

void SliceWalk::restart() {
  frame_ = 0;
  exact_frame_index_ = -1;
  renderer_.reset();
  slices_.clear();
  slicing_problem_.clear();
  if (!problem_.empty()) return;
  SceneShiftingSettings s;
  s.epsilon_px = epsilon_px_;
  s.design_speed = speed_;
  try {
    renderer_ = std::make_unique<SceneShiftingRenderer>(scene_, script_.camera, s);
    renderer_->start(script_.frames[0].pose);
    slices_ = renderer_->slices();
  } catch (const std::exception& e) {
    renderer_.reset();
    slicing_problem_ = e.what();
  }
}

void SliceWalk::go_to(int window_frame) {
  if (!renderer_ || script_.frames.size() < 2) return;
  const int count = frame_count();
  const int target = ((window_frame % count) + count) % count;
  if (target < frame_) restart();
  while (renderer_ && frame_ < target) {
    const ViewerFrame& previous = script_.frames[size_t(frame_)];
    ++frame_;
    renderer_->advance(previous.pose, previous.motion, script_.frames[size_t(frame_)].pose);
  }
}

SliceDiagram SliceWalk::diagram() const {
  const std::vector<DiagramPlane> planes = script_.frames.empty()
                                               ? std::vector<DiagramPlane>{}
                                               : diagram_planes(scene_, script_.frames[0].pose);
  return slice_diagram(slices_, planes, script_.camera.focal_px, epsilon_px_, speed_);
}

const Image& SliceWalk::shifted_image() const {
  static const Image kEmpty;
  return renderer_ ? renderer_->frame() : kEmpty;
}

const Image& SliceWalk::exact_image() {
  if (!exact_ || frame_ >= frame_count()) {
    exact_frame_ = Image();
  } else if (exact_frame_index_ != frame_) {
    exact_->start(script_.frames[size_t(frame_)].pose);
    exact_frame_ = exact_->frame();
    exact_frame_index_ = frame_;
  }
  return exact_frame_;
}

std::string SliceWalk::caption(int window_frame) const {
  if (!problem_.empty()) return "Scene shifting needs the train-window scene: " + problem_;
  if (!slicing_problem_.empty()) return "Cannot slice: " + slicing_problem_;
  char wrapped[120] = "";
  if (window_frame != frame_) {
    std::snprintf(wrapped, sizeof wrapped, " (the play bar's frame %d: the %d-frame walk repeats)",
                  window_frame, frame_count());
  }
  char text[400];
  std::snprintf(text, sizeof text,
                "Frame %d%s: a viewer moving sideways at %g units/frame, slices cut so every "
                "point of a slice moves within %g px of the others (eq. 9, asymptote "
                "k|V|/epsilon = %.2f).",
                frame_, wrapped, speed_, epsilon_px_, diagram().asymptote);
  return text;
}

}  // namespace oflab
