#include "models/animation_model.h"

#include "models/scene_model.h"

namespace oflab {

AnimationModel::AnimationModel(SceneModel* scene, QObject* parent)
    : AnimationModel(nullptr, scene, parent) {}

AnimationModel::AnimationModel(RunPlayer* player, SceneModel* scene, QObject* parent)
    : QObject(parent),
      own_player_(player ? nullptr : std::make_unique<RunPlayer>(&scene->panel())),
      player_(player ? player : own_player_.get()),
      scene_(scene) {
  connect(scene_, &SceneModel::scene_changed, this, &AnimationModel::frame_changed);
  connect(scene_, &SceneModel::source_changed, this, [this] {
    if (player_->panel_changed()) emit source_changed();
  });
}

AnimationModel::~AnimationModel() = default;

void AnimationModel::report(const std::string& problem) {
  emit input_rejected(QString::fromStdString(problem));
}

bool AnimationModel::set_source(const SourceChoice& choice) {
  const std::string problem = player_->set_source(choice);
  if (!problem.empty()) {
    report(problem);
    return false;
  }
  emit source_changed();
  emit scene_->scene_changed();  // the loop and the frame moved (hence frame_changed)
  return true;
}

bool AnimationModel::set_settings(const EngineSettings& settings) {
  const std::string problem = player_->set_settings(settings);
  if (!problem.empty()) {
    report(problem);
    return false;
  }
  emit source_changed();
  return true;
}

Animator* AnimationModel::animator() {
  Animator* animator = player_->animator();
  const std::string problem = player_->take_problem();
  if (!problem.empty()) report(problem);
  return animator;
}

const std::vector<AnimationFrame>& AnimationModel::history() {
  static const std::vector<AnimationFrame> kNone;
  return animator() ? player_->history() : kNone;
}

}  // namespace oflab
