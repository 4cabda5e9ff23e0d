// The scene-shifting view's walk (manual/scene-shifting.md): the shipped train-window scene
// walked by the train-sideways viewer script, drawn by core's scene-shifting renderer
// (core/scene_shifting/scene_shifting_renderer.h) with the slices cut for the view's epsilon
// and speed, beside core's exact render of the same frame (every visible polygon re-rendered
// by the scene engine, core/scene/scene_animator.h with the rerender policy). The desktop's
// view (gui/views/slices_view.h) and the page's (web/slices_view.js) play it; plain C++.
//
// Frames: the walk shows the window's frame modulo the script's length. Scene shifting keeps
// no undo state, so going back restarts from frame 0 and plays forward: every frame shown is
// the one an uninterrupted run shows.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "display/slice_diagram.h"
#include "image/image.h"
#include "scene/scene.h"
#include "scene/scene_animator.h"
#include "scene/viewer_script.h"
#include "scene_shifting/scene_shifting_renderer.h"

namespace oflab {

class SliceWalk {
 public:
  // Reads the shipped train-window scene and train-sideways script (problem() says why not)
  // and cuts the slices for epsilon 1 px/frame and speed 0.05 units/frame.
  SliceWalk();
  ~SliceWalk();
  SliceWalk(const SliceWalk&) = delete;
  SliceWalk& operator=(const SliceWalk&) = delete;

  // Cuts the slices again for epsilon (pixels per frame) and |V| (world units per frame) and
  // restarts at frame 0; slicing_problem() says why the renderer refused them, if it did.
  void set_slicing(double epsilon_px, double speed);
  double epsilon_px() const { return epsilon_px_; }
  double speed() const { return speed_; }

  // Brings the walk to `window_frame` modulo the script's length (forward frame by frame,
  // backward by a restart). Does nothing when the scene or the slicing has a problem.
  void go_to(int window_frame);
  int frame() const { return frame_; }
  int frame_count() const { return static_cast<int>(script_.frames.size()); }

  // Why the shipped scene or script cannot be read ("" when they can).
  const std::string& problem() const { return problem_; }
  // Why the renderer refused the slicing ("" when it did not).
  const std::string& slicing_problem() const { return slicing_problem_; }
  // Why the exact render cannot start ("" when it can).
  const std::string& exact_problem() const { return exact_problem_; }

  // The slices in force (empty when refused) and the diagram of them over the scene's
  // planes seen from the first pose.
  const std::vector<Slice>& slices() const { return slices_; }
  SliceDiagram diagram() const;
  // The frame as scene shifting draws it and as core's exact render projects it
  // (camera-sized, premultiplied RGBA; empty when not drawn).
  const Image& shifted_image() const;
  const Image& exact_image();

  // The caption under the pictures for the window's frame `window_frame`: the walk's frame,
  // the play bar's when the walk repeats, the speed, epsilon and the asymptote.
  std::string caption(int window_frame) const;

  static constexpr const char* kExactTitle = "exact projection (core warp)";

 private:
  void restart();

  Scene scene_;
  ViewerScript script_;
  std::unique_ptr<SceneShiftingRenderer> renderer_;
  std::unique_ptr<SceneEngine> exact_;
  Image exact_frame_;
  int exact_frame_index_ = -1;  // the walk's frame exact_frame_ shows
  std::vector<Slice> slices_;
  double epsilon_px_ = 1.0, speed_ = 0.05;
  int frame_ = 0;
  std::string problem_, slicing_problem_, exact_problem_;
};

}  // namespace oflab
