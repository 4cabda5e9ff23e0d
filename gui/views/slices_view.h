// The "Scene shifting" view (dissertation chapter 3, manual/scene-shifting.md): a top-down
// diagram of Hofmann's slices for the train-window scene (depth against lateral position:
// the eye, the slice boundaries, the asymptote k|V|/epsilon, the scene's planes, with depth
// ticks and a legend) beside the scene-shifting renderer's layered animation and the exact
// projection of the same frame (core's exact render, gui/adapters/exact_frames.h), with epsilon and
// the viewer's speed on sliders. Everything shown comes from core/scene_shifting/scene_shifting.h
// and core/scene_shifting/scene_shifting_renderer.h; this file only draws it.
#pragma once

#include <QImage>
#include <QLabel>
#include <memory>
#include <vector>

#include "image/image.h"
#include "scene/scene.h"
#include "scene/viewer_script.h"
#include "scene_shifting/scene_shifting_renderer.h"
#include "views/view_page.h"

namespace oflab {

class WindowModel;

class ExactFrameRenderer;
class SliderSpin;

// The depths the diagram's axis marks: 1, 2 and 5 times powers of ten from 1 up to
// `max_depth` (world units), increasing. Precondition: max_depth > 0.
std::vector<double> depth_ticks(double max_depth);

// Paints the top-down slice diagram into a width x height image: depth runs left to right
// on a square-root scale from the eye to `max_depth` (world units), lateral position
// bottom to top. `planes` are (depth, left x, right x) of the scene's planes in the start
// view. Preconditions: width, height > 0, max_depth > 0.
struct DiagramPlane {
  double depth, left, right;
};
QImage slice_diagram(int width, int height, const std::vector<Slice>& slices, double asymptote,
                     const std::vector<DiagramPlane>& planes, double max_depth,
                     const ViewTheme& theme);

class SlicesView : public ViewPage {
 public:
  // Loads the shipped train-window scene and train-sideways viewer script; if they cannot
  // be read the view shows the reason instead of a diagram. It shows the frame of the window
  // model's one frame counter (the scene model's frame, modulo the script's length), so
  // play, step, back, home, end and the scrub bar move it like every other view. The model
  // must outlive the view.
  explicit SlicesView(WindowModel* window, QWidget* parent = nullptr);
  ~SlicesView() override;

  QImage render_image() override;
  void set_theme(const ViewTheme& theme) override;
  // The script's frame shown now (the window's frame modulo the script's length; a hidden
  // view keeps the frame it last showed until it is shown or rendered).
  int frame() const { return frame_; }
  // The caption under the pictures: the walk's frame shown, and the play bar's when the
  // walk has repeated.
  QString caption() const;
  double smallest_text_px() const override;
  QString scene_panel_note() const override;

  // The slicing in force (for tests): epsilon in pixels per frame, speed in world units
  // per frame.
  double epsilon_px() const;
  double speed() const;
  int slice_count() const { return static_cast<int>(slices_.size()); }
  // The current frame as scene shifting draws it and as core's exact render projects it
  // (camera-sized, premultiplied; the exact one is empty when it cannot be rendered).
  const Image& shifted_image() const;
  const Image& exact_image() const { return exact_frame_; }

 protected:
  void resizeEvent(QResizeEvent* event) override;
  void showEvent(QShowEvent* event) override;

 private:
  void restart();
  void refresh();
  // Brings the slices to the window's frame (forward frame by frame, backward by a restart)
  // when the view is visible; a hidden view waits and catches up when shown or rendered, so
  // the other views do not pay for its frames and it still shows an uninterrupted run.
  void follow_frame();
  void catch_up();  // follow_frame even when hidden
  void render_exact();

  Scene scene_;
  ViewerScript script_;
  std::unique_ptr<SceneShiftingRenderer> renderer_;
  std::unique_ptr<ExactFrameRenderer> exact_;
  Image exact_frame_;
  QString exact_problem_;  // why the exact frame cannot be shown, if it cannot
  std::vector<Slice> slices_;
  int frame_ = 0;
  WindowModel* window_;
  QString problem_;
  ViewTheme theme_;
  SliderSpin* epsilon_ = nullptr;
  SliderSpin* speed_ = nullptr;
  QLabel* diagram_ = nullptr;
  bool diagram_current_ = false;  // diagram_ shows the slices and theme at diagram_size_
  QSize diagram_size_;
  QLabel* frame_label_ = nullptr;
  QLabel* exact_label_ = nullptr;
  QLabel* caption_ = nullptr;
};

}  // namespace oflab
