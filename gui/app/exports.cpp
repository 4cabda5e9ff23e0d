#include "app/exports.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProgressDialog>
#include <filesystem>
#include <sstream>

#include "adapters/frame_images.h"
#include "app/main_window.h"
#include "app/screenshot.h"
#include "formats/atomic_file.h"
#include "formats/image_io.h"
#include "formats/video_file.h"
#include "formats/vtk_export.h"
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
  const Overwrite mode = overwrite ? Overwrite::kReplace : Overwrite::kRefuse;
  const bool ok = for_each_frame(window, error, [&](int k, const QImage& image) {
    const QString path =
        QDir(directory).filePath(QStringLiteral("frame-%1.png").arg(k, 4, 10, QChar('0')));
    try {
      write_file_atomically(path.toStdString(), encode_png(image_from_qimage(image)), mode);
    } catch (const FileWriteError& e) {
      *error = QString::fromStdString(e.what());
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
  const Overwrite mode = overwrite ? Overwrite::kReplace : Overwrite::kRefuse;
  try {
    check_output_file(path.toStdString(), mode);
    std::ostringstream csv;
    window->model()->animation()->write_csv(csv);
    write_file_atomically(path.toStdString(), csv.str(), mode);
  } catch (const std::exception& e) {  // a source that cannot be played, a failed write
    *error = QString::fromStdString(e.what());
    return false;
  }
  return true;
}

bool export_paraview_data(MainWindow* window, const QString& directory, bool overwrite,
                          QString* error) {
  namespace fs = std::filesystem;
  try {
    const std::string target = directory.toStdString();
    AtomicDir out(target, overwrite ? Overwrite::kReplace : Overwrite::kRefuse);
    const PlaneScene& scene = window->model()->scene()->scene();
    write_file_inside(
        (fs::path(out.path()) / "flow.vti").string(),
        flow_field_vti(scene.camera,
                       planar_flow_coefficients(scene.camera, scene.pose, scene.motion),
                       kDefaultVtkGridStep),
        (fs::path(target) / "flow.vti").string());
    Animator* animator = window->model()->animation()->animator();
    auto* view = qobject_cast<AnimationView*>(window->view(QStringLiteral("animation")));
    if (animator && view && animator->frame() >= 0) {
      VtkSeriesWriter series(out.path(), target);
      series.add_frame({animator->frame(), &animator->camera(), &view->engine_image(),
                        &view->exact_image(), animator->outlines()});
      series.finish();
    }
    out.commit();
  } catch (const std::exception& e) {  // a refused directory, a failed write
    *error = QString::fromStdString(e.what());
    return false;
  }
  return true;
}

}  // namespace oflab
