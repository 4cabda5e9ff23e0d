#include "models/animation_model.h"

#include <cmath>

#include "models/scene_model.h"
#include "models/window_state.h"

namespace oflab {

double approximated_percent(const AnimationFrame& frame) {
  const int drawn = frame.drawn();
  if (drawn == 0) return 0.0;
  const int rerendered = frame.levels[static_cast<size_t>(Level::kRerender)];
  return 100.0 * (drawn - rerendered) / drawn;
}

AnimationModel::AnimationModel(SceneModel* scene, QObject* parent)
    : QObject(parent), scene_(scene) {
  connect(scene_, &SceneModel::scene_changed, this, &AnimationModel::frame_changed);
  connect(scene_, &SceneModel::source_changed, this, [this] {
    if (!source_kind().follows_scene_panel) return;
    stale_ = true;
    emit source_changed();
  });
}

AnimationModel::~AnimationModel() = default;

const AnimationSourceKind& AnimationModel::source_kind() const {
  return *find_animation_source_kind(source_.kind);
}

std::string AnimationModel::start(const SourceChoice& choice, const EngineSettings& settings,
                                  std::unique_ptr<Animator>* animator,
                                  AnimationFrame* first) const {
  const AnimationSourceKind* kind = find_animation_source_kind(choice.kind);
  if (!kind) {
    return "unknown source kind '" + choice.kind + "' (known: " + animation_source_kind_names() +
           ")";
  }
  try {
    *animator = kind->make(choice, *scene_, settings);
    *first = (*animator)->start();
  } catch (const std::exception& e) {  // unreadable files, sources that cannot be played
    return e.what();
  }
  return "";
}

std::string AnimationModel::source_problem(const SourceChoice& choice,
                                           const EngineSettings& settings) const {
  std::unique_ptr<Animator> animator;
  AnimationFrame first;
  return start(choice, settings, &animator, &first);
}

bool AnimationModel::rebuild(const SourceChoice& choice, const EngineSettings& settings) {
  std::unique_ptr<Animator> animator;
  AnimationFrame first;
  const std::string problem = start(choice, settings, &animator, &first);
  if (!problem.empty()) {
    emit input_rejected(QString::fromStdString(problem));
    return false;
  }
  animator_ = std::move(animator);
  history_.assign(1, first);
  source_ = choice;
  settings_ = settings;
  stale_ = false;
  return true;
}

bool AnimationModel::set_source(const SourceChoice& choice) {
  if (!rebuild(choice, settings_)) return false;
  emit source_changed();
  const int frames = source_kind().follows_scene_panel ? 0 : animator_->frame_count();
  scene_->set_loop_override(frames);  // both emit scene_changed, hence frame_changed
  scene_->set_frame(0);
  return true;
}

bool AnimationModel::set_settings(const EngineSettings& settings) {
  const std::string limits_problem = settings_state_problem(settings);
  if (!limits_problem.empty()) {
    emit input_rejected(QString::fromStdString(limits_problem));
    return false;
  }
  const std::string content = content_problem(settings.content);
  if (!content.empty()) {
    emit input_rejected(tr("content: %1").arg(QString::fromStdString(content)));
    return false;
  }
  if (!rebuild(source_, settings)) return false;
  emit source_changed();
  return true;
}

Animator* AnimationModel::animator() {
  if ((stale_ || !animator_) && !rebuild(source_, settings_)) return animator_.get();
  if (animator_) seek(scene_->frame() % animator_->frame_count());
  return animator_.get();
}

const std::vector<AnimationFrame>& AnimationModel::history() {
  static const std::vector<AnimationFrame> kNone;
  return animator() ? history_ : kNone;
}

void AnimationModel::seek(int frame) {
  if (frame < animator_->frame()) history_.assign(1, animator_->start());
  while (animator_->frame() < frame) history_.push_back(animator_->advance());
}

void AnimationModel::write_csv(std::ostream& out) const {
  source_kind().write_csv(source_, *scene_, settings_, out);
}

}  // namespace oflab
