// What the main window needs from a view: a name for the command line, a tab title, a
// way to render it now and read back its pixels, one animation step, and the theme.
// The phase-2 views (animation side by side, analysis) implement the same interface and
// are added with MainWindow::add_view, so the window does not change when they land.
#pragma once

#include <QImage>
#include <QString>
#include <QWidget>

#include "views/view_theme.h"

namespace oflab {

class ViewPage : public QWidget {
 public:
  using QWidget::QWidget;

  // Command-line name, lower case: "flow", "basis" (later "animation", "analysis").
  virtual QString view_name() const = 0;
  // Tab title, e.g. "Flow field".
  virtual QString view_title() const = 0;
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
};

}  // namespace oflab
