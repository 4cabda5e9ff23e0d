// View 1, "Flow field": the instantaneous flow of the current scene at the current frame,
// drawn by FlowRenderer, with the controls that choose the part of the flow and how it is
// drawn, and the coefficient table beside it.
#pragma once

#include <QThreadPool>
#include <future>
#include <memory>
#include <vector>

#include "views/flow_renderer.h"
#include "views/view_page.h"

class QCheckBox;
class QComboBox;
class QLabel;

namespace oflab {

class CoefficientTable;
class ImageCanvas;
class SceneModel;
class WindowModel;

class FlowView : public ViewPage {
  Q_OBJECT

 public:
  // Shows and edits the window model's flow display; the model must outlive the view.
  FlowView(WindowModel* window, QWidget* parent = nullptr);
  ~FlowView() override;

  QImage render_image() override;
  void set_theme(const ViewTheme& theme) override;
  double smallest_text_px() const override;

  // What the view shows: the window model's flow display (edited there).
  FlowDisplay display() const;
  CoefficientTable* coefficient_table() const { return table_; }
  // The widget that shows the painted flow picture.
  ImageCanvas* canvas() const { return canvas_; }
  // Largest magnitude of the shown part after the last update, px/s.
  double shown_max_magnitude() const { return renderer().shown_max_magnitude(); }
  // False when the plane is outside the image after the last update; the view then draws
  // no flow, its caption says so and a note over the greyed table explains the terms.
  bool plane_in_image() const { return renderer().plane_in_image(); }
  QString caption() const { return renderer().caption(); }
  // The share (0..1) of the picture's scene region the plane's image covers, at the canvas
  // size after a render (FlowRenderer::plane_share).
  double plane_share();

  // Updates the picture from the model and, when the view is visible, has it painted on the
  // view's painting thread (otherwise it paints when shown): the canvas takes the picture when
  // it is painted itself, so the window's other views draw meanwhile.
  void refresh();

 protected:
  void showEvent(QShowEvent* event) override;

 private:
  QWidget* make_option_bar();
  void update_scene();
  void paint_canvas();        // paints the picture now, on this thread
  void paint_canvas_later();  // has the painting thread paint it (ImageCanvas::set_pending_image)
  // The renderer, once the picture the painting thread may be painting with it is done.
  FlowRenderer& renderer() const;
  void show_display();  // the controls show the model's flow display; redraws

  WindowModel* window_;
  SceneModel* model_;
  ImageCanvas* canvas_;
  std::unique_ptr<FlowRenderer> renderer_;
  // The picture being painted from renderer_ on painter_'s one thread (kept alive, so that its
  // fonts' caches are too); invalid when none is.
  mutable std::shared_future<QImage> painting_;
  QThreadPool painter_;
  CoefficientTable* table_;
  QLabel* outside_note_ = nullptr;
  QComboBox* part_box_ = nullptr;
  std::vector<QCheckBox*> draw_boxes_;  // one per flow_draw_options() entry, in order
  bool dirty_ = true;
};

}  // namespace oflab
