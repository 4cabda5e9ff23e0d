// The "Scene shifting" view (dissertation chapter 3, manual/scene-shifting.md): a top-down
// diagram of Hofmann's slices for the train-window scene (depth against lateral position:
// the eye, the slice boundaries, the asymptote k|V|/epsilon, the scene's planes, with depth
// ticks and a legend) beside the scene-shifting renderer's layered animation and the exact
// projection of the same frame, with epsilon and the viewer's speed on sliders. The walk, the
// slices, the frames and the diagram's geometry are the teaching layer's
// (session/player/slice_walk.h, session/display/slice_diagram.h, which the page draws too);
// this file only paints them with Qt.
#pragma once

#include <QImage>
#include <QLabel>
#include <memory>
#include <vector>

#include "display/slice_diagram.h"
#include "image/image.h"
#include "player/slice_walk.h"
#include "views/view_page.h"

namespace oflab {

class WindowModel;

class SliderSpin;

// Paints the top-down slice diagram (session/display/slice_diagram.h) into a width x height
// image: depth runs left to right on the diagram's square-root scale from the eye to
// diagram.max_depth, lateral position bottom to top. Preconditions: width, height > 0.
QImage paint_slice_diagram(int width, int height, const SliceDiagram& diagram,
                           const ViewTheme& theme);

class SlicesView : public ViewPage {
 public:
  // Plays the teaching layer's walk (the shipped train-window scene and train-sideways
  // viewer script); if they cannot be read the view shows the reason instead of a diagram. It shows
  // the frame of the window model's one frame counter (the scene model's frame, modulo the script's
  // length), so play, step, back, home, end and the scrub bar move it like every other view. The
  // model must outlive the view.
  explicit SlicesView(WindowModel* window, QWidget* parent = nullptr);
  ~SlicesView() override;

  QImage render_image() override;
  void set_theme(const ViewTheme& theme) override;
  // The script's frame shown now (the window's frame modulo the script's length; a hidden
  // view keeps the frame it last showed until it is shown or rendered).
  int frame() const { return walk_.frame(); }
  // The caption under the pictures: the walk's frame shown, and the play bar's when the
  // walk has repeated.
  QString caption() const;
  double smallest_text_px() const override;
  QString scene_panel_note() const override;

  // The slicing in force (for tests): epsilon in pixels per frame, speed in world units
  // per frame.
  double epsilon_px() const;
  double speed() const;
  int slice_count() const { return static_cast<int>(walk_.slices().size()); }
  // The current frame as scene shifting draws it and as core's exact render projects it
  // (camera-sized, premultiplied; the exact one is empty when it cannot be rendered).
  const Image& shifted_image() const { return walk_.shifted_image(); }
  const Image& exact_image() { return walk_.exact_image(); }

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

  SliceWalk walk_;
  WindowModel* window_;
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
