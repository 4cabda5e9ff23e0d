// What the main window needs from a view: a way to render it now and read back its pixels,
// one animation step, and the theme. A view's command-line name and tab title are its
// entry in the view table (gui/app/view_table.h), which the window builds its tabs from.
#pragma once

#include <QImage>
#include <QString>
#include <QWidget>

#include "adapters/view_theme.h"

namespace oflab {

class ViewPage : public QWidget {
 public:
  using QWidget::QWidget;

  // Brings the view up to date with the scene, renders it and returns the rendered VTK
  // content at the view's current size (not the Qt controls around it).
  virtual QImage render_image() = 0;
  // Advances the view's own animation by one step (the basis gallery's amount); the
  // scene's frame is advanced by the window, not here.
  virtual void step_animation() {}
  // When on, the view's own timers stay stopped and only step_animation advances it
  // (reproducible screenshots and benchmarks); its playing state is kept.
  virtual void set_external_clock(bool on) { (void)on; }
  virtual void set_theme(const ViewTheme& theme) = 0;
  // The size of the smallest text the view draws inside its rendered content (captions,
  // legends, colour-bar and chart labels), screen pixels, as its drawing objects hold it
  // now; 0 for a view that draws no text of its own (its Qt controls use the app font).
  virtual double smallest_text_px() const { return 0.0; }
  // Empty when the scene panel's plane, motion and camera are what this view draws;
  // otherwise one sentence saying what the view plays instead (the window then disables
  // the panel's controls and shows the sentence on it).
  virtual QString scene_panel_note() const { return QString(); }
};

}  // namespace oflab
