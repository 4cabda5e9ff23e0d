// What the animation and analysis views show, as Qt sees it: a thin adapter over the run
// player of the window's lab (session/player/run_player.h: the source, the engine settings
// and the run up to the scene's frame with one record per frame), adding the signals views
// redraw on and reporting refusals. Views read this model and redraw on its signals; they
// never read each other.
#pragma once

#include <QObject>
#include <iosfwd>
#include <memory>
#include <vector>

#include "engine/animator.h"
#include "player/animation_sources.h"
#include "player/run_player.h"

namespace oflab {

class SceneModel;

class AnimationModel : public QObject {
  Q_OBJECT

 public:
  // Adapts `player` (whose panel `scene` adapts); both must outlive the model.
  AnimationModel(RunPlayer* player, SceneModel* scene, QObject* parent = nullptr);
  // A model with a run player of its own over the scene model's panel, playing the plane
  // with default settings (for a model used alone, as the tests do).
  explicit AnimationModel(SceneModel* scene, QObject* parent = nullptr);
  ~AnimationModel() override;

  RunPlayer& player() const { return *player_; }
  SceneModel* scene_model() const { return scene_; }
  const SourceChoice& source() const { return player_->source(); }
  const AnimationSourceKind& source_kind() const { return player_->source_kind(); }
  const EngineSettings& settings() const { return player_->settings(); }

  // RunPlayer::source_problem.
  std::string source_problem(const SourceChoice& choice, const EngineSettings& settings) const {
    return player_->source_problem(choice, settings);
  }

  // Plays a source from frame 0 (RunPlayer::set_source); a source that cannot be read or
  // played is refused with input_rejected and the current one keeps playing.
  bool set_source(const SourceChoice& choice);
  // Applies engine settings (RunPlayer::set_settings); refused with input_rejected,
  // changing nothing.
  bool set_settings(const EngineSettings& settings);

  // The animator at the scene model's frame (built and advanced on demand); nullptr only
  // when nothing can be played.
  Animator* animator();
  // Records of frames 0 .. animator()->frame(), in order; empty when nothing plays.
  const std::vector<AnimationFrame>& history();
  // The current frame's record. Precondition: animator() is not nullptr.
  const AnimationFrame& current() { return history().back(); }

  // Writes the per-frame CSV of the whole source (animation_sources.h write_csv).
  // Throws std::runtime_error or std::invalid_argument when the source cannot be played.
  void write_csv(std::ostream& out) const { player_->write_csv(out); }

  // The run was replaced whole (the window's lab applied a state): emits source_changed.
  void run_replaced() { emit source_changed(); }

 signals:
  // The frame to show moved (the run follows when it is next read).
  void frame_changed();
  // The source or the settings changed, or the scene panel's plane it plays: the run
  // restarts, and what depends on the source (an exact renderer) must be rebuilt.
  void source_changed();
  void input_rejected(const QString& message);

 private:
  void report(const std::string& problem);

  std::unique_ptr<RunPlayer> own_player_;  // set by the constructor without a player
  RunPlayer* player_;
  SceneModel* scene_;
};

}  // namespace oflab
