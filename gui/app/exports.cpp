#include "app/exports.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProgressDialog>
#include <fstream>
#include <sstream>

#include "adapters/frame_images.h"
#include "app/main_window.h"
#include "app/screenshot.h"
#include "formats/video_file.h"
#include "models/animation_model.h"
#include "models/scene_model.h"
#include "models/window_model.h"
#include "views/animation_view.h"

namespace oflab {
namespace {

// Runs `write(frame, image)` over every frame of the animation source, `image` being the
// whole animation view as on screen (every panel of its layout, VTK content included),
// then goes back to the frame shown before. A progress dialog counts the frames and can
// cancel. False when there is no source (with *error set), when `write` returns false
// (which sets *error itself) or when cancelled (*error says so).
bool for_each_frame(MainWindow* window, QString* error,
                    const std::function<bool(int, const QImage&)>& write) {
  auto* view = qobject_cast<AnimationView*>(window->view(QStringLiteral("animation")));
  SceneModel* scene = window->model()->scene();
  const int saved = scene->frame();
  const Animator* animator = window->model()->animation()->animator();
  if (!animator || !view) {
    *error = QStringLiteral("the animation view has nothing to play");
    return false;
  }
  const int frames = animator->frame_count();
  QProgressDialog progress(QStringLiteral("Exporting the animation view..."),
                           QStringLiteral("Cancel"), 0, frames, window);
  progress.setWindowModality(Qt::WindowModal);
  progress.setMinimumDuration(500);
  // The view's own clock (the blink timer) stops during the export: each frame's phase is
  // that of its time in the exported animation.
  const bool was_external = view->external_clock();
  const bool blink = view->display() == PanelDisplay::kBlink;
  view->set_external_clock(true);
  bool ok = true;
  for (int k = 0; k < frames && ok; ++k) {
    progress.setValue(k);
    progress.setLabelText(QStringLiteral("Exporting frame %1 of %2...").arg(k + 1).arg(frames));
    if (progress.wasCanceled()) {
      *error = QStringLiteral("export cancelled; the frames written so far were removed");
      ok = false;
      break;
    }
    scene->set_frame(k);
    if (blink) view->set_blink_phase(AnimationView::blink_phase_at(k, kExportFps));
    view->render_image();  // brings every panel up to this frame
    ok = write(k, grab_with_vtk(view));
  }
  progress.setValue(frames);
  view->set_external_clock(was_external);  // blink restarts from the engine's frame
  scene->set_frame(saved);
  return ok;
}

}  // namespace

bool export_frames_png(MainWindow* window, const QString& directory, bool overwrite,
                       QString* error) {
  if (!QDir().mkpath(directory)) {
    *error = QStringLiteral("%1: cannot create the directory").arg(directory);
    return false;
  }
  QStringList written;  // removed again when the export stops early: no partial set
  const bool ok = for_each_frame(window, error, [&](int k, const QImage& image) {
    const QString path =
        QDir(directory).filePath(QStringLiteral("frame-%1.png").arg(k, 4, 10, QChar('0')));
    if (!overwrite && QFileInfo::exists(path)) {
      *error = QStringLiteral("%1 exists; not overwritten").arg(path);
      return false;
    }
    if (!image.save(path, "PNG")) {
      *error = QStringLiteral("%1: cannot be written").arg(path);
      return false;
    }
    written << path;
    return true;
  });
  if (!ok) {
    for (const QString& path : written) QFile::remove(path);
  }
  return ok;
}

bool export_video(MainWindow* window, const QString& path, bool overwrite, QString* error) {
  try {
    VideoWriter video(path.toStdString(), kExportFps, overwrite);
    const bool ok = for_each_frame(window, error, [&](int, const QImage& frame) {
      video.add_frame(image_from_qimage(frame));
      return true;
    });
    if (ok) video.finish();
    return ok;
  } catch (const VideoFileError& e) {
    *error = QString::fromStdString(e.what());
    return false;
  }
}

bool export_frame_csv(MainWindow* window, const QString& path, bool overwrite, QString* error) {
  if (!overwrite && QFileInfo::exists(path)) {
    *error = QStringLiteral("%1 exists; not overwritten").arg(path);
    return false;
  }
  std::ostringstream csv;
  try {
    window->model()->animation()->write_csv(csv);
  } catch (const std::exception& e) {  // a source that cannot be played
    *error = QString::fromStdString(e.what());
    return false;
  }
  std::ofstream out(path.toStdString());
  out << csv.str();
  if (!out) {
    *error = QStringLiteral("%1: cannot be written").arg(path);
    return false;
  }
  return true;
}

}  // namespace oflab
