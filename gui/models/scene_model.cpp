#include "models/scene_model.h"

#include "adapters/texture.h"
#include "models/window_state.h"

namespace oflab {
namespace {

// A per-frame motion expressed per second.
RigidMotion per_second(RigidMotion motion) {
  motion.velocity /= SceneModel::kSecondsPerFrame;
  motion.omega /= SceneModel::kSecondsPerFrame;
  return motion;
}

}  // namespace

SceneModel::SceneModel(QObject* parent)
    : QObject(parent), scene_(default_demo_scene()), texture_(default_texture()) {
  scene_.pose.texture_size = glm::ivec2(texture_.width(), texture_.height());
}

int SceneModel::loop_frames() const {
  if (loop_override_ > 0) return loop_override_;
  return script_ ? static_cast<int>(script_->frames.size()) : kLoopFrames;
}

PlaneScene SceneModel::scene_at(int frame) const {
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

PlanePose SceneModel::current_pose() const { return scene_at(frame_).pose; }
RigidMotion SceneModel::current_motion() const { return scene_at(frame_).motion; }

bool SceneModel::drawable_at(int frame) const {
  return plane_scene_problem(scene_at(frame)).empty();
}

MotionScript SceneModel::as_script() const {
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

void SceneModel::set_loop_override(int frames) {
  loop_override_ = frames > 0 ? frames : 0;
  if (frame_ >= loop_frames()) frame_ = 0;
  emit scene_changed();
}

bool SceneModel::set_scene(const PlaneScene& scene) {
  const std::string problem = plane_state_problem(scene);
  if (!problem.empty()) {
    emit scene_rejected(QString::fromStdString(problem));
    return false;
  }
  scene_ = scene;
  script_.reset();
  script_name_.clear();
  if (frame_ >= loop_frames() || !drawable_at(frame_)) frame_ = 0;
  emit source_changed();
  emit scene_changed();
  return true;
}

bool SceneModel::set_script(const MotionScript& script, const QString& name) {
  if (script.frames.empty()) {
    emit scene_rejected(QStringLiteral("script %1 has no frames").arg(name));
    return false;
  }
  PlaneScene first{script.camera, script.frames.front().pose,
                   per_second(script.frames.front().motion)};
  first.pose.texture_size = scene_.pose.texture_size;
  const std::string problem = plane_scene_problem(first);
  if (!problem.empty()) {
    emit scene_rejected(
        QStringLiteral("script %1, frame 0: %2").arg(name, QString::fromStdString(problem)));
    return false;
  }
  scene_ = first;
  script_ = script;
  script_name_ = name;
  frame_ = 0;
  emit source_changed();
  emit scene_changed();
  return true;
}

bool SceneModel::set_texture(const QImage& texture, const QString& source_name) {
  if (texture.isNull() || texture.width() < 1 || texture.height() < 1) {
    emit scene_rejected(
        QStringLiteral("cannot use %1 as a texture: not a readable image").arg(source_name));
    return false;
  }
  texture_ = texture;
  texture_source_ = source_name;
  scene_.pose.texture_size = glm::ivec2(texture.width(), texture.height());
  emit texture_changed();
  emit source_changed();
  emit scene_changed();
  return true;
}

void SceneModel::set_frame(int frame) {
  int next = frame < 0 ? 0 : frame % loop_frames();
  if (!drawable_at(next)) next = 0;
  if (next == frame_) return;
  frame_ = next;
  emit scene_changed();
}

}  // namespace oflab
