// View 3, "Animation, side by side": on the left the animation model's frame (each layer
// outlined in the colour of the level it was updated at this frame, with a legend); on the
// right the exact projection of the same frame rendered by VTK as textured 3D polygons with
// the matching camera (analysis/runs/vtk_scene_renderer.h). A difference heat map and a
// blink toggle compare the two. Beside them, the frame inspector; under them, the readout
// of the pixel under the cursor.
//
// What plays is the animation model's source (gui/models/animation_model.h): the scene
// panel's plane, a motion script, a multi-plane scene walked through by a viewer script, or
// scene shifting of such a scene, all through one Animator. The controls edit the model;
// the view redraws on its signals. The engine runs only while a view asks for its frames.
#pragma once

#include <memory>

#include "image/image.h"
#include "views/animation_controls.h"
#include "views/view_page.h"

class QLabel;
class QTimer;

namespace oflab {

class AnimationModel;
class ImageCanvas;
class VtkSceneRenderer;

class AnimationView : public ViewPage {
  Q_OBJECT

 public:
  // The model must outlive the view.
  explicit AnimationView(AnimationModel* model, QWidget* parent = nullptr);
  ~AnimationView() override;

  QImage render_image() override;
  void set_external_clock(bool on) override;
  void set_theme(const ViewTheme& theme) override;

  AnimationModel* model() const { return model_; }
  PanelDisplay display() const { return display_; }
  void set_display(PanelDisplay display);
  // Blink shows the engine's frame (phase false) or the exact one (true).
  bool blink_phase() const { return blink_phase_; }
  void set_blink_phase(bool exact);

  // The animator's frame and the exact frame at the current frame (camera-sized; empty
  // when nothing can be played).
  const Image& engine_image();
  const Image& exact_image();

  // Redraws when visible.
  void refresh();

 protected:
  void showEvent(QShowEvent* event) override;

 private:
  QWidget* make_panels();
  void show_model_state();
  QImage compose();
  QImage panel(bool exact);
  void show_readout(QPointF pixel);

  AnimationModel* model_;
  AnimationControls* controls_;
  ImageCanvas* canvas_ = nullptr;
  QLabel* inspector_ = nullptr;
  QLabel* readout_ = nullptr;
  QTimer* blink_timer_;
  std::unique_ptr<VtkSceneRenderer> exact_;  // of the model's source; null after a change
  Image exact_frame_;
  int exact_frame_index_ = -1;
  PanelDisplay display_ = PanelDisplay::kSideBySide;
  ViewTheme theme_;
  bool blink_phase_ = false;
  bool external_clock_ = false;
  double panel_split_ = 0.0;  // x where the right panel starts in the composed image
};

}  // namespace oflab
