// What the animation and analysis views show: a source (gui/models/animation_sources.h), the
// engine settings, and the run of that source (an Animator, core/engine/animator.h) up to the
// scene model's frame with one record per frame. Every source plays through the same
// Animator calls. Views read this model and redraw on its signals; they never read each
// other.
//
// Frames. The scene model's frame is the frame shown: the model follows it on demand, so the
// engine runs only while a view asks for it. Seeking forward advances the animator frame by
// frame; seeking backward restarts from frame 0 (animators keep no undo state, and a re-run
// of a few hundred frames takes a fraction of a second), so every frame shown is exactly
// what an uninterrupted run shows.
#pragma once

#include <QObject>
#include <memory>
#include <vector>

#include "engine/animator.h"
#include "models/animation_sources.h"

namespace oflab {

class SceneModel;

class AnimationModel : public QObject {
  Q_OBJECT

 public:
  // Plays the scene panel's plane with default settings. `scene` must outlive the model.
  explicit AnimationModel(SceneModel* scene, QObject* parent = nullptr);
  ~AnimationModel() override;

  SceneModel* scene_model() const { return scene_; }
  const SourceChoice& source() const { return source_; }
  const AnimationSourceKind& source_kind() const;
  const EngineSettings& settings() const { return settings_; }

  // Empty when `choice` can be played with `settings` (its files read, its animator made and
  // started), else one line saying why not. Changes nothing.
  std::string source_problem(const SourceChoice& choice, const EngineSettings& settings) const;

  // Plays a source from frame 0 (the scene model's frame goes to 0, and its loop becomes the
  // source's length unless the source follows the scene panel). A source that cannot be
  // read or played is refused with input_rejected and the current one keeps playing.
  bool set_source(const SourceChoice& choice);
  // Applies engine settings (re-running to the current frame). Refused with input_rejected,
  // changing nothing, when a threshold is negative or not finite, the content cannot be
  // rendered (content_problem) or the source cannot be played with them. The content is what
  // a single plane's re-render draws (a scene's polygons keep their own kinds and take its
  // quality and light); the animator's scene() carries it, so an exact renderer built as
  // VtkSceneRenderer(animator()->scene(), animator()->camera(), near, settings().content)
  // draws the same content.
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
  void write_csv(std::ostream& out) const;

 signals:
  // The frame to show moved (the run follows when it is next read).
  void frame_changed();
  // The source or the settings changed, or the scene panel's plane it plays: the run
  // restarts, and what depends on the source (an exact renderer) must be rebuilt.
  void source_changed();
  void input_rejected(const QString& message);

 private:
  // Makes and starts the animator of `choice`: empty on success, else one line why not.
  std::string start(const SourceChoice& choice, const EngineSettings& settings,
                    std::unique_ptr<Animator>* animator, AnimationFrame* first) const;
  bool rebuild(const SourceChoice& choice, const EngineSettings& settings);
  void seek(int frame);

  SceneModel* scene_;
  SourceChoice source_;
  EngineSettings settings_;
  std::unique_ptr<Animator> animator_;
  std::vector<AnimationFrame> history_;
  bool stale_ = true;  // the scene panel's plane changed: rebuild before the next use
};

// Percent of the drawn layers of `frame` that were not re-rendered (0 when none is drawn).
double approximated_percent(const AnimationFrame& frame);

}  // namespace oflab
