#include "player/plane_panel.h"

#include <utility>

#include "state/window_state.h"

namespace oflab {
namespace {

// A per-frame motion expressed per second.
RigidMotion per_second(RigidMotion motion) {
  motion.velocity /= PlanePanel::kSecondsPerFrame;
  motion.omega /= PlanePanel::kSecondsPerFrame;
  return motion;
}

}  // namespace

PlanePanel::PlanePanel(Image texture) : scene_(default_demo_scene()), texture_(std::move(texture)) {
  scene_.pose.texture_size = glm::ivec2(texture_.width(), texture_.height());
}

int PlanePanel::loop_frames() const {
  if (loop_override_ > 0) return loop_override_;
  return script_ ? static_cast<int>(script_->frames.size()) : kLoopFrames;
}

PlaneScene PlanePanel::scene_at(int frame) const {
  // Beyond the plane's own loop (a loop override) the plane repeats its loop.
  frame %= script_ ? static_cast<int>(script_->frames.size()) : kLoopFrames;
  PlaneScene scene = scene_;
  if (script_) {
    const ScriptFrame& f = script_->frames[static_cast<size_t>(frame)];
    scene.pose = f.pose;
    scene.pose.texture_size = scene_.pose.texture_size;
    scene.motion = per_second(f.motion);
  } else {
    scene.pose = pose_at_time(scene_, frame * kSecondsPerFrame);
  }
  return scene;
}

bool PlanePanel::drawable_at(int frame) const {
  return plane_scene_problem(scene_at(frame)).empty();
}

MotionScript PlanePanel::as_script() const {
  if (script_) return *script_;
  MotionScript script;
  script.name = "scene motion";
  script.camera = scene_.camera;
  RigidMotion per_frame = scene_.motion;
  per_frame.velocity *= kSecondsPerFrame;
  per_frame.omega *= kSecondsPerFrame;
  for (int k = 0; k < kLoopFrames; ++k) {
    const PlaneScene at = scene_at(k);
    if (!plane_scene_problem(at).empty()) break;
    script.frames.push_back({at.pose, per_frame});
  }
  return script;
}

void PlanePanel::set_loop_override(int frames) {
  loop_override_ = frames > 0 ? frames : 0;
  if (frame_ >= loop_frames()) frame_ = 0;
}

std::string PlanePanel::set_scene(const PlaneScene& scene) {
  const std::string problem = plane_state_problem(scene);
  if (!problem.empty()) return problem;
  scene_ = scene;
  script_.reset();
  script_name_.clear();
  if (frame_ >= loop_frames() || !drawable_at(frame_)) frame_ = 0;
  return "";
}

std::string PlanePanel::set_script(const MotionScript& script, const std::string& name) {
  if (script.frames.empty()) return "script " + name + " has no frames";
  PlaneScene first{script.camera, script.frames.front().pose,
                   per_second(script.frames.front().motion)};
  first.pose.texture_size = scene_.pose.texture_size;
  const std::string problem = plane_scene_problem(first);
  if (!problem.empty()) return "script " + name + ", frame 0: " + problem;
  scene_ = first;
  script_ = script;
  script_name_ = name;
  frame_ = 0;
  return "";
}

std::string PlanePanel::set_texture(Image texture, const std::string& source_name) {
  if (texture.empty()) return "cannot use " + source_name + " as a texture: not a readable image";
  texture_ = std::move(texture);
  texture_source_ = source_name;
  scene_.pose.texture_size = glm::ivec2(texture_.width(), texture_.height());
  return "";
}

int PlanePanel::landing_frame(int frame) const {
  const int next = frame < 0 ? 0 : frame % loop_frames();
  return drawable_at(next) ? next : 0;
}

void PlanePanel::set_frame(int frame) { frame_ = landing_frame(frame); }

}  // namespace oflab
