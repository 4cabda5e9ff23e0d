// The main window's files (app/main_window.h): what it reads (textures, scripts, sessions)
// and writes (screenshots, sessions, exports) from its File menu, split from the window's
// layout and play controls in main_window.cpp.
#include <QAction>
#include <QFileDialog>
#include <QFileInfo>
#include <QInputDialog>
#include <QLabel>
#include <QMenu>
#include <QPainter>
#include <QStatusBar>
#include <algorithm>

#include "adapters/texture.h"
#include "app/exports.h"
#include "app/main_window.h"
#include "app/screenshot.h"
#include "formats/datasets.h"
#include "formats/script_file.h"
#include "models/animation_model.h"
#include "models/scene_model.h"
#include "models/window_model.h"
#include "state/window_state_file.h"
#include "views/study_window.h"
#include "views/view_page.h"

namespace oflab {

QImage MainWindow::grab_window_image() {
  QImage image = grab_with_vtk(this);
  if (!study_window_ || !study_window_->isVisible()) return image;
  // Under the lesson's caption, scaled down when the window is too short for it.
  const int border = 3;
  const int top = caption_banner_->isVisible()
                      ? caption_banner_->mapTo(this, QPoint(0, caption_banner_->height())).y()
                      : 0;
  QImage study = grab_with_vtk(study_window_);
  const QSize room(image.width() - 2 * border, image.height() - top - 2 * border);
  if (study.width() > room.width() || study.height() > room.height()) {
    study = study.scaled(room, Qt::KeepAspectRatio, Qt::SmoothTransformation);
  }
  const QPoint at(image.width() - study.width() - border, image.height() - study.height() - border);
  QPainter painter(&image);
  painter.fillRect(QRect(at - QPoint(border, border), study.size() + QSize(2, 2) * border),
                   QColor(40, 40, 40));
  painter.drawImage(at, study);
  return image;
}

void MainWindow::load_texture() {
  const QString path = QFileDialog::getOpenFileName(this, tr("Load texture"), QString(),
                                                    tr("Images (*.png *.jpg *.jpeg)"));
  if (path.isEmpty()) return;
  QString error;
  const QImage image = load_texture_image(path, &error);
  if (image.isNull()) {
    show_message(error);
    return;
  }
  model_->scene()->set_texture(image, path);
}

bool MainWindow::load_script(const QString& name_or_path) {
  try {
    const MotionScript script = read_script_file(resolve_script_path(name_or_path.toStdString()));
    return model_->scene()->set_script(script, QFileInfo(name_or_path).completeBaseName());
  } catch (const std::runtime_error& e) {  // unreadable or invalid: keep the session
    show_message(QString::fromStdString(e.what()));
    return false;
  }
}

void MainWindow::save_screenshot() {
  const QString path = QFileDialog::getSaveFileName(
      this, tr("Save screenshot"), QStringLiteral("oflab.png"), tr("PNG images (*.png)"));
  if (path.isEmpty()) return;
  QString error;
  if (!save_png(grab_window_image(), path, &error)) show_message(error);
}

void MainWindow::create_export_menu(QMenu* file) {
  // QFileDialog asks before replacing a file, so the writes below may overwrite.
  file->addSeparator();
  connect(file->addAction(tr("Open session...")), &QAction::triggered, this, [this] {
    const QString path = QFileDialog::getOpenFileName(this, tr("Open session"), QString(),
                                                      tr("oflab sessions (*.json)"));
    if (!path.isEmpty()) load_session(path);
  });
  connect(file->addAction(tr("Save session...")), &QAction::triggered, this, [this] {
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Save session"), QStringLiteral("session.json"), tr("oflab sessions (*.json)"));
    if (!path.isEmpty()) save_session(path, true);
  });
  QMenu* exports = file->addMenu(tr("Export"));
  connect(exports->addAction(tr("View screenshot at a resolution...")), &QAction::triggered, this,
          &MainWindow::save_view_screenshot);
  connect(
      exports->addAction(tr("Animation as numbered PNGs...")), &QAction::triggered, this, [this] {
        const QString dir = QFileDialog::getExistingDirectory(this, tr("Directory for the frames"));
        QString error;
        if (dir.isEmpty()) return;
        if (!export_frames_png(this, dir, false, &error)) return show_message(error);
        Animator* animator = model_->animation()->animator();
        const int frames = animator ? animator->frame_count() : 0;
        statusBar()->showMessage(tr("Wrote %1 frames of the animation view (frame-0000.png to "
                                    "frame-%2.png) to %3")
                                     .arg(frames)
                                     .arg(std::max(0, frames - 1), 4, 10, QChar('0'))
                                     .arg(dir),
                                 15000);
      });
  QAction* video = exports->addAction(tr("Animation as video (MP4, GIF, Ogg Theora)..."));
  connect(video, &QAction::triggered, this, [this] {
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Save video"), QStringLiteral("oflab.mp4"),
        tr("MP4 video (*.mp4);;Animated GIF (*.gif);;Ogg Theora video (*.ogv)"));
    QString error;
    if (path.isEmpty()) return;
    if (!export_video(this, path, true, &error)) return show_message(error);
    statusBar()->showMessage(tr("Wrote the video to %1").arg(path), 15000);
  });
  connect(exports->addAction(tr("Per-frame CSV...")), &QAction::triggered, this, [this] {
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Save per-frame CSV"), QStringLiteral("frames.csv"), tr("CSV (*.csv)"));
    QString error;
    if (!path.isEmpty() && !export_frame_csv(this, path, true, &error)) show_message(error);
  });
  connect(exports->addAction(tr("ParaView data of this frame...")), &QAction::triggered, this,
          [this] {
            // A new (or empty) directory: an existing one is never replaced from the menu.
            const QString dir = QFileDialog::getSaveFileName(
                this, tr("New directory for the ParaView data"), QStringLiteral("oflab-paraview"));
            QString error;
            if (dir.isEmpty()) return;
            if (!export_paraview_data(this, dir, false, &error)) return show_message(error);
            statusBar()->showMessage(tr("Wrote the frame as ParaView data to %1").arg(dir), 15000);
          });
}

void MainWindow::save_view_screenshot() {
  bool ok = false;
  const int width = QInputDialog::getInt(this, tr("View screenshot"), tr("Width in pixels"), 1920,
                                         320, 8192, 1, &ok);
  if (!ok) return;
  const QString path = QFileDialog::getSaveFileName(
      this, tr("Save view screenshot"), QStringLiteral("view.png"), tr("PNG images (*.png)"));
  if (path.isEmpty()) return;
  const QImage image =
      current_view()->render_image().scaledToWidth(width, Qt::SmoothTransformation);
  QString error;
  if (!save_png(image, path, &error)) show_message(error);
}

bool MainWindow::save_session(const QString& path, bool overwrite) {
  try {
    write_session_file(path.toStdString(), model_->state(), overwrite);
  } catch (const SessionError& e) {
    show_message(QString::fromStdString(e.what()));
    return false;
  }
  statusBar()->showMessage(tr("Saved the session to %1").arg(path), 15000);
  return true;
}

bool MainWindow::load_session(const QString& path) {
  QString error;
  try {
    if (model_->apply(read_session_file(path.toStdString()), &error)) {
      statusBar()->showMessage(tr("Opened the session %1").arg(path), 15000);
      return true;
    }
    error = QStringLiteral("%1: %2").arg(QFileInfo(path).fileName(), error);
  } catch (const SessionError& e) {
    error = QString::fromStdString(e.what());
  }
  show_message(error);
  return false;
}

}  // namespace oflab
