// The one current scene that drives every view, as Qt sees it: a thin adapter over the
// plane panel of the window's lab (session/player/plane_panel.h: the scene at time 0, the
// texture, the frame and the motion script), adding the signals views redraw on and the
// texture as a QImage. Views read it and redraw on scene_changed; nothing else holds scene
// state.
//
// Time: frames are 1/30 s apart. The scene's V and Omega are per second; a script's
// per-frame velocities (core/engine/script.h) are converted to per second at that rate.
#pragma once

#include <QImage>
#include <QObject>
#include <QString>
#include <memory>

#include "engine/script.h"
#include "flow/plane_scene.h"
#include "player/plane_panel.h"

namespace oflab {

class SceneModel : public QObject {
  Q_OBJECT

 public:
  // Adapts `panel` (which must outlive the model) whose texture is `texture`.
  SceneModel(PlanePanel* panel, QImage texture, QObject* parent = nullptr);
  // A model with a panel of its own: the default demo scene with the default texture, at
  // frame 0 (for a model used alone, as the tests do).
  explicit SceneModel(QObject* parent = nullptr);
  ~SceneModel() override;

  PlanePanel& panel() const { return *panel_; }

  // The scene at frame 0 (with a script: the script's camera, first pose and motion).
  const PlaneScene& scene() const { return panel_->scene(); }
  const QImage& texture() const { return texture_; }
  // The file the texture came from, empty for the default texture.
  QString texture_source() const { return QString::fromStdString(panel_->texture_source()); }
  int frame() const { return panel_->frame(); }
  double time() const { return frame() * kSecondsPerFrame; }
  // Frames in one loop of the motion (the script's length, else kLoopFrames).
  int loop_frames() const { return panel_->loop_frames(); }

  // The plane pose and the motion (per second) at the current frame.
  PlanePose current_pose() const { return panel_->current_pose(); }
  RigidMotion current_motion() const { return panel_->current_motion(); }

  // Name of the script being played, empty when the scene's own motion plays.
  QString script_name() const { return QString::fromStdString(panel_->script_name()); }
  // The script being played, or nullptr when the scene's own motion plays.
  const MotionScript* script() const { return panel_->script(); }

  // The motion of one loop as a script (PlanePanel::as_script).
  MotionScript as_script() const { return panel_->as_script(); }

  // Frames in one loop when another source plays: 0 restores the scene's own loop length.
  // Emits scene_changed.
  void set_loop_override(int frames);

  // Replaces the scene (and drops any script) when plane_state_problem() accepts it, and
  // emits scene_changed; otherwise emits scene_rejected(message) and keeps everything.
  bool set_scene(const PlaneScene& scene);
  // Plays a script from frame 0; refused (scene_rejected, nothing changes) when it has no
  // frames or its first frame cannot be drawn.
  bool set_script(const MotionScript& script, const QString& name);
  // Replaces the texture (any non-null image); refused with scene_rejected when null.
  bool set_texture(const QImage& texture, const QString& source_name);

  // Moves to `frame` (>= 0), as PlanePanel::set_frame lands on it.
  void set_frame(int frame);
  void advance(int frames = 1) { set_frame(frame() + frames); }

  // The panel was changed whole (the window's lab applied a state): `texture` is its texture
  // as a QImage. Emits texture_changed, source_changed and scene_changed.
  void panel_replaced(const QImage& texture);

  static constexpr double kSecondsPerFrame = PlanePanel::kSecondsPerFrame;
  static constexpr int kLoopFrames = PlanePanel::kLoopFrames;

 signals:
  void scene_changed();
  void texture_changed();
  // The scene, its motion, its script or its texture changed (not only the frame).
  void source_changed();
  void scene_rejected(const QString& message);

 private:
  std::unique_ptr<PlanePanel> own_panel_;  // set by the constructor without a panel
  PlanePanel* panel_;
  QImage texture_;
};

}  // namespace oflab
