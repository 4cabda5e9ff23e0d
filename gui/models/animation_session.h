// What the animation view plays: a source (one textured plane driven by a motion script,
// or a multi-plane scene walked through by a viewer script), the engine settings, and the
// engine's run up to the current frame with one record per frame for the analysis view.
// Plain C++ over core and analysis (no Qt, no VTK).
//
// Frames. Frame k of a source is script frame k. Seeking forward advances the engine frame
// by frame; seeking backward re-runs from frame 0 (the engine keeps no undo state, and a
// re-run of a few hundred frames takes a fraction of a second), so every frame shown is
// exactly what an uninterrupted run shows.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "engine/engine.h"
#include "scene/scene.h"
#include "scene/scene_animator.h"
#include "engine/script.h"
#include "scene/viewer_script.h"

namespace oflab {

struct AnimationSource {
  // Single plane: the script, and its texture (premultiplied RGBA).
  MotionScript plane_script;
  Image plane_texture;
  // Multi-plane: a scene and a viewer script (scene set means this kind).
  std::shared_ptr<const Scene> scene;
  ViewerScript viewer;
  std::string scene_name;   // shipped name or file, for the session file and titles
  std::string script_name;  // the script's or viewer script's name or file

  bool is_scene() const { return scene != nullptr; }
  const Camera& camera() const { return is_scene() ? viewer.camera : plane_script.camera; }
  int frame_count() const;
};

// Empty when the source can be played, else one line saying why not (no frames, no
// texture, an invalid camera, a scene polygon problem).
std::string animation_source_problem(const AnimationSource& source);

// One frame of the run, as the analysis view and the inspector show it. For a scene the
// per-term books belong to each polygon's engine and are not kept (zero); the level
// counts and the measured error cover every polygon.
struct FrameRecord {
  int frame = 0;
  double time_ms = 0.0;                   // engine time of the frame
  std::array<int, kLevelCount> levels{};  // drawn polygons per level
  int drawn = 0;                          // polygons drawn (sum of levels)
  double approximated_percent = 0.0;      // drawn polygons not re-rendered, percent
  double measured_error_px = 0.0;         // largest measured corner error (NaN: none)
  FrameReport plane;                      // single plane: the engine's report
  bool has_books = false;                 // plane.flow/carried/accumulated are meaningful
};

// A polygon's outline in image pixels (top-left origin) and the level chosen for it.
struct PolygonOutline {
  std::vector<Vec2> points;
  Level level = Level::kNone;
};

class AnimationSession {
 public:
  // Starts at frame 0. Precondition: animation_source_problem(source) is empty.
  AnimationSession(AnimationSource source, const EngineSettings& settings);
  ~AnimationSession();
  AnimationSession(const AnimationSession&) = delete;
  AnimationSession& operator=(const AnimationSession&) = delete;

  const AnimationSource& source() const { return source_; }
  const EngineSettings& settings() const { return settings_; }
  int frame_count() const { return source_.frame_count(); }
  int frame() const { return frame_; }

  // Shows `frame`, clamped to [0, frame_count() - 1]: advances, or re-runs from frame 0.
  void seek(int frame);

  // The engine's composited frame (camera-sized, premultiplied, transparent background).
  const Image& frame_image() const;
  // Outlines of the drawn polygons with their levels: the displayed polygon of the single
  // plane; for a scene, each drawn polygon's exact outline (its layer is within the
  // threshold of it).
  std::vector<PolygonOutline> outlines() const;
  // Records of frames 0..frame(), in order.
  const std::vector<FrameRecord>& history() const { return history_; }
  const FrameRecord& current() const { return history_.back(); }

  // The exact image of the current frame as a scene seen by a viewer: for a scene source
  // the scene itself; for a single plane, one polygon placed at frame 0's pose (viewer
  // frame of frame 0 = world) seen from the viewer that brings it to the current pose.
  const Scene& reference_scene() const { return *reference_scene_; }
  ViewerPose reference_view() const;

  // Single plane only: the engine's displayed texel -> pixel warp, the exact one, and the
  // pose and per-frame motion at the current frame (identity or default otherwise).
  Mat3 displayed_warp() const;
  Mat3 exact_warp() const;
  PlanePose plane_pose() const;
  RigidMotion plane_motion() const;

 private:
  void restart();
  void step();
  void record_plane(const FrameReport& report);
  void record_scene(const AnimationFrame& report);

  AnimationSource source_;
  EngineSettings settings_;
  std::shared_ptr<const Scene> reference_scene_;
  std::unique_ptr<PlaneAnimator> plane_;
  std::unique_ptr<SceneAnimator> scene_;
  Image plane_frame_;
  std::vector<FrameRecord> history_;
  int frame_ = 0;
};

}  // namespace oflab
