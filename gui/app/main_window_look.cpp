// The main window's look (app/main_window.h): presentation mode's palette and fonts, sized
// to the window (presentation_scale: a 1366 x 768 projector shows the 1920 x 1080 look at
// 0.711 of its pixels), the banners' style and the scene panel's width; split from the
// window's layout and play controls in main_window.cpp.
#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QLabel>
#include <QResizeEvent>
#include <algorithm>
#include <cmath>

#include "app/app_theme.h"
#include "app/main_window.h"
#include "models/window_model.h"
#include "views/scene_controls.h"
#include "views/view_page.h"

namespace oflab {

ViewTheme MainWindow::theme() const { return view_theme(model_->presentation(), theme_scale_); }

void MainWindow::style_banners() {
  // Okabe-Ito blue for the lesson caption, vermillion for refused input. Style sheets fix
  // the font, so its size follows the presentation mode (and its scale) here.
  const QString style = QStringLiteral(
      "QLabel { background: %1; color: white; padding: 6px; border-radius: 3px; "
      "font-size: %2pt; }");
  const double points = model_->presentation() ? 17.0 * theme_scale_ : 10.0;
  const QString size = QString::number(points, 'f', 1);
  caption_banner_->setStyleSheet(style.arg(QStringLiteral("#0072B2")).arg(size));
  message_banner_->setStyleSheet(style.arg(QStringLiteral("#D55E00")).arg(size));
}

void MainWindow::fit_scene_panel() {
  // The panel is as wide as its controls want (fonts change with presentation mode), up
  // to a third of a 1280-pixel window, so the views keep most of the screen.
  controls_->ensurePolished();
  const int wanted = controls_->sizeHint().width() + 20;
  scene_dock_->widget()->setMinimumWidth(std::min(wanted, 430));
}

void MainWindow::show_presentation() {
  const bool on = model_->presentation();
  const QSignalBlocker block(presentation_action_);
  presentation_action_->setChecked(on);
  theme_scale_ = presentation_scale(width(), height());
  apply_app_theme(theme());
  // A dock paints its title in the font it was made with unless it has one of its own.
  scene_dock_->setFont(QApplication::font());
  style_banners();
  for (const Tab& tab : views_) tab.page->set_theme(theme());
  for (ViewPage* page : layout_views_) page->set_theme(theme());
  // Let the scene panel grow with the fonts instead of clipping its controls.
  fit_scene_panel();
}

void MainWindow::resizeEvent(QResizeEvent* event) {
  QMainWindow::resizeEvent(event);
  // Presentation mode follows the window's size; the normal look does not change with it.
  const double scale = presentation_scale(width(), height());
  if (model_->presentation() && std::abs(scale - theme_scale_) > 1e-3) show_presentation();
}

}  // namespace oflab
