// View 3, "Animation, side by side": on the left the optic-flow animation (the engine's
// composited frame, each polygon outlined in the colour of the level chosen for it this
// frame, with a legend); on the right the exact projection rendered by VTK as textured 3D
// polygons with the matching camera (analysis/runs/vtk_scene_renderer.h). A difference heat map
// and a blink toggle compare the two. Beside them, the frame inspector; under them, the
// readout of the pixel under the cursor.
//
// What plays: the scene panel's plane and motion (or the script loaded into the scene
// model), or a multi-plane scene walked through by a viewer script. The scene model's
// frame drives the engine (AnimationSession), so the window's play bar, the scrub slider
// and the analysis view's clicks all move this view; the engine runs only while this view
// or the analysis view is visible.
#pragma once

#include <memory>

#include "image/image.h"
#include "views/animation_controls.h"
#include "views/view_page.h"

class QLabel;
class QTimer;

namespace oflab {

class AnimationSession;
class ImageCanvas;
class SceneModel;
class VtkSceneRenderer;

class AnimationView : public ViewPage {
  Q_OBJECT

 public:
  // The model must outlive the view.
  explicit AnimationView(SceneModel* model, QWidget* parent = nullptr);
  ~AnimationView() override;

  QString view_name() const override { return QStringLiteral("animation"); }
  QString view_title() const override { return tr("Animation, side by side"); }
  QImage render_image() override;
  void set_external_clock(bool on) override;
  void set_theme(const ViewTheme& theme) override;

  EngineSettings settings() const { return settings_; }
  // Applies engine settings (re-running to the current frame). Refused with
  // input_rejected, changing nothing, when a threshold is negative or not finite.
  bool set_settings(const EngineSettings& settings);
  SourceChoice source() const { return source_; }
  // Plays a source. A script or scene that cannot be read or used is refused with
  // input_rejected and the current source keeps playing.
  bool set_source(const SourceChoice& choice);
  PanelDisplay display() const { return display_; }
  void set_display(PanelDisplay display);
  // Blink shows the engine's frame (phase false) or the exact one (true).
  bool blink_phase() const { return blink_phase_; }
  void set_blink_phase(bool exact);

  // The engine at the scene model's frame (built and advanced on demand); nullptr only
  // when nothing can be played.
  AnimationSession* session();
  // The engine's frame and the exact frame at the current frame (camera-sized).
  const Image& engine_image();
  const Image& exact_image();

  // Brings the engine to the model's frame and redraws when visible.
  void refresh();

 signals:
  void input_rejected(const QString& message);
  // The engine moved to another frame or was re-run (the analysis view redraws).
  void frame_shown();

 protected:
  void showEvent(QShowEvent* event) override;

 private:
  QWidget* make_panels();
  bool rebuild(const SourceChoice& choice, const EngineSettings& settings);
  void sync_engine();
  QImage compose() ;
  QImage panel(bool exact);
  void show_readout(QPointF pixel);

  SceneModel* model_;
  AnimationControls* controls_;
  ImageCanvas* canvas_ = nullptr;
  QLabel* inspector_ = nullptr;
  QLabel* readout_ = nullptr;
  QTimer* blink_timer_;
  std::unique_ptr<AnimationSession> session_;
  std::unique_ptr<VtkSceneRenderer> exact_;
  Image exact_frame_;
  int exact_frame_index_ = -1;
  SourceChoice source_;
  EngineSettings settings_;
  PanelDisplay display_ = PanelDisplay::kSideBySide;
  ViewTheme theme_;
  bool stale_ = true;  // the model's plane changed: rebuild before the next use
  bool blink_phase_ = false;
  bool external_clock_ = false;
  double panel_split_ = 0.0;  // x where the right panel starts in the composed image
};

}  // namespace oflab
