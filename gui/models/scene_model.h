// The one current scene that drives every view: the scene at time 0 (what the controls
// edit), the texture, and the current frame of its motion, or a motion script whose
// frames give the pose and motion of each frame. Views read it and redraw on
// scene_changed; nothing else holds scene state.
//
// Time: frames are 1/30 s apart. The scene's V and Omega are per second; a script's
// per-frame velocities (core/engine/script.h) are converted to per second at that rate.
#pragma once

#include <QImage>
#include <QObject>
#include <QString>
#include <optional>

#include "engine/script.h"
#include "flow/plane_scene.h"

namespace oflab {

class SceneModel : public QObject {
  Q_OBJECT

 public:
  // Starts on the default demo scene with the default texture, at frame 0.
  explicit SceneModel(QObject* parent = nullptr);

  // The scene at frame 0 (with a script: the script's camera, first pose and motion).
  const PlaneScene& scene() const { return scene_; }
  const QImage& texture() const { return texture_; }
  // The file the texture came from, empty for the default texture.
  QString texture_source() const { return texture_source_; }
  int frame() const { return frame_; }
  double time() const { return frame_ * kSecondsPerFrame; }
  // Frames in one loop of the motion (the script's length, else kLoopFrames).
  int loop_frames() const;

  // The plane pose and the motion (per second) at the current frame.
  PlanePose current_pose() const;
  RigidMotion current_motion() const;

  // Name of the script being played, empty when the scene's own motion plays.
  QString script_name() const { return script_name_; }
  // The script being played, or nullptr when the scene's own motion plays.
  const MotionScript* script() const { return script_ ? &*script_ : nullptr; }

  // The motion of one loop as a script (per-frame velocities): the script itself, or the
  // scene's motion sampled every frame up to loop_frames() or the first frame the plane
  // cannot be drawn in. What the animation view plays for the single plane.
  MotionScript as_script() const;

  // Frames in one loop when another source plays (the animation view's multi-plane
  // scenes): 0 restores the scene's own loop length. Emits scene_changed.
  void set_loop_override(int frames);

  // Replaces the scene (and drops any script) when plane_scene_problem() accepts it, and
  // emits scene_changed; otherwise emits scene_rejected(message) and keeps everything.
  // The frame is kept unless the new scene cannot be drawn at it (then frame 0).
  bool set_scene(const PlaneScene& scene);

  // Plays a script: frame k shows the script's frame k. Rejected (scene_rejected, nothing
  // changes) when the script has no frames or its first frame cannot be drawn.
  bool set_script(const MotionScript& script, const QString& name);

  // Replaces the texture (any non-null image; its size becomes the pose's texture size).
  // A null image is rejected with scene_rejected and changes nothing.
  bool set_texture(const QImage& texture, const QString& source_name);

  // Moves to `frame` (>= 0), looping over loop_frames(); returns to frame 0 early when
  // the plane cannot be drawn at that frame (for instance behind the eye).
  void set_frame(int frame);
  void advance(int frames = 1) { set_frame(frame_ + frames); }

  static constexpr double kSecondsPerFrame = 1.0 / 30.0;
  static constexpr int kLoopFrames = 150;

 signals:
  void scene_changed();
  void texture_changed();
  // The scene, its motion, its script or its texture changed (not only the frame).
  void source_changed();
  void scene_rejected(const QString& message);

 private:
  PlaneScene scene_at(int frame) const;
  bool drawable_at(int frame) const;

  PlaneScene scene_;
  std::optional<MotionScript> script_;
  QString script_name_;
  QImage texture_;
  QString texture_source_;
  int frame_ = 0;
  int loop_override_ = 0;
};

}  // namespace oflab
