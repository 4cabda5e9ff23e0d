#include "app/session_io.h"

#include <QDir>
#include <QFileInfo>
#include <fstream>

#include <sstream>

#include "adapters/frame_images.h"
#include "adapters/texture.h"
#include "app/main_window.h"
#include "formats/datasets.h"
#include "formats/script_file.h"
#include "formats/video_file.h"
#include "models/animation_model.h"
#include "models/scene_model.h"
#include "views/animation_view.h"

namespace oflab {
namespace {

// Checks every file the session names and that its source can be played; the message
// names the file or the source and what is wrong.
bool check_files(const Session& s, const AnimationModel& animation, QImage* texture,
                 std::optional<MotionScript>* script, QString* error) {
  try {
    if (!s.texture.empty()) {
      *texture = load_texture_image(QString::fromStdString(s.texture), error);
      if (texture->isNull()) return false;
    }
    if (!s.script.empty()) *script = read_script_file(resolve_script_path(s.script));
  } catch (const std::runtime_error& e) {
    *error = QString::fromStdString(e.what());
    return false;
  }
  *error = QString::fromStdString(
      animation.source_problem({s.source_kind, s.source_name, s.viewer_script}, s.settings));
  return error->isEmpty();
}

// Runs `write(frame, image)` over every frame of the animation source, then goes back to
// the frame shown before. False when there is no source (with *error set) or when `write`
// returns false (which sets *error itself).
bool for_each_frame(MainWindow* window, QString* error,
                    const std::function<bool(int, const QImage&)>& write) {
  AnimationView* view = window->animation_view();
  const int saved = window->model()->frame();
  const Animator* animator = window->animation_model()->animator();
  if (!animator) {
    *error = QStringLiteral("the animation view has nothing to play");
    return false;
  }
  const int frames = animator->frame_count();
  bool ok = true;
  for (int k = 0; k < frames && ok; ++k) {
    window->model()->set_frame(k);
    ok = write(k, view->render_image());
  }
  window->model()->set_frame(saved);
  return ok;
}

}  // namespace

Session capture_session(MainWindow* window) {
  SceneModel* model = window->model();
  const AnimationModel* animation = window->animation_model();
  Session s;
  s.plane = model->scene();
  if (model->script()) {
    // The scene at frame 0 of a script is the script's; the panel's own plane is kept.
    s.script = model->script_name().toStdString();
  }
  s.texture = model->texture_source().toStdString();
  s.source_kind = animation->source().kind;
  s.source_name = animation->source().name;
  s.viewer_script = animation->source().viewer;
  s.settings = animation->settings();
  s.display = panel_display_name(window->animation_view()->display());
  s.frame = model->frame();
  s.view = window->current_view_name().toStdString();
  return s;
}

bool apply_session(MainWindow* window, const Session& s, QString* error) {
  QImage texture;
  std::optional<MotionScript> script;
  PanelDisplay display = PanelDisplay::kSideBySide;
  if (!parse_panel_display(s.display, &display)) {
    *error = QStringLiteral("unknown display '%1'").arg(QString::fromStdString(s.display));
    return false;
  }
  if (!window->view(QString::fromStdString(s.view))) {
    *error = QStringLiteral("unknown view '%1'").arg(QString::fromStdString(s.view));
    return false;
  }
  SceneModel* model = window->model();
  AnimationModel* animation = window->animation_model();
  if (!check_files(s, *animation, &texture, &script, error)) return false;
  if (!texture.isNull()) model->set_texture(texture, QString::fromStdString(s.texture));
  if (s.texture.empty() && !model->texture_source().isEmpty()) {
    model->set_texture(default_texture(), QString());
  }
  model->set_scene(s.plane);
  if (script) model->set_script(*script, QString::fromStdString(s.script));
  animation->set_settings(s.settings);
  animation->set_source({s.source_kind, s.source_name, s.viewer_script});
  window->animation_view()->set_display(display);
  model->set_frame(s.frame);
  window->show_view(QString::fromStdString(s.view));
  return true;
}

bool export_frames_png(MainWindow* window, const QString& directory, bool overwrite,
                       QString* error) {
  if (!QDir().mkpath(directory)) {
    *error = QStringLiteral("%1: cannot create the directory").arg(directory);
    return false;
  }
  return for_each_frame(window, error, [&](int k, const QImage& image) {
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
    return true;
  });
}

bool export_video(MainWindow* window, const QString& path, bool overwrite, QString* error) {
  try {
    VideoWriter video(path.toStdString(), 30, overwrite);
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
    window->animation_model()->write_csv(csv);
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
