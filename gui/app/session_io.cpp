#include "app/session_io.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QProgressDialog>
#include <fstream>
#include <sstream>

#include "adapters/exact_frames.h"
#include "adapters/frame_images.h"
#include "adapters/texture.h"
#include "app/main_window.h"
#include "app/screenshot.h"
#include "formats/datasets.h"
#include "formats/script_file.h"
#include "formats/video_file.h"
#include "models/animation_model.h"
#include "models/scene_model.h"
#include "views/animation_view.h"
#include "views/basis_view.h"
#include "views/flow_view.h"

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

// Runs `write(frame, image)` over every frame of the animation source, `image` being the
// whole animation view as on screen (every panel of its layout, VTK content included),
// then goes back to the frame shown before. A progress dialog counts the frames and can
// cancel. False when there is no source (with *error set), when `write` returns false
// (which sets *error itself) or when cancelled (*error says so).
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
    window->model()->set_frame(k);
    if (blink) view->set_blink_phase(AnimationView::blink_phase_at(k, kExportFps));
    view->render_image();  // brings every panel up to this frame
    ok = write(k, grab_with_vtk(view));
  }
  progress.setValue(frames);
  view->set_external_clock(was_external);  // blink restarts from the engine's frame
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
  s.exact_renderer = window->animation_view()->exact_renderer().name;
  s.frame = model->frame();
  s.view = window->current_view_name().toStdString();
  const FlowDisplay flow = window->flow_view()->display();
  s.flow_part = flow_part_key(flow.part);
  s.flow_draw = {flow.arrows,  flow.streamlines,   flow.colour_wheel,
                 flow.texture, flow.zoom_to_plane, flow.common_scale};
  s.basis = basis_key(window->basis_view()->basis());
  s.basis_playing = window->basis_view()->playing();
  s.presentation = window->presentation();
  s.lesson = window->lesson().toStdString();
  s.play_rate = window->play_rate();
  return s;
}

namespace {

// The window part of a session (flow view, basis, presentation, lesson, rate) when every
// name in it is known; false with *error naming the field otherwise.
bool parse_window_state(const Session& s, FlowDisplay* flow, BasisKind* basis, QString* error) {
  if (!parse_flow_part(s.flow_part, &flow->part)) {
    *error = QStringLiteral("window.flow_part: unknown part '%1'").arg(s.flow_part.c_str());
    return false;
  }
  if (!parse_basis_kind(s.basis, basis)) {
    *error = QStringLiteral("window.basis: unknown basis '%1'").arg(s.basis.c_str());
    return false;
  }
  if (!s.lesson.empty() && !find_lesson(s.lesson)) {
    *error = QStringLiteral("window.lesson: unknown lesson '%1'").arg(s.lesson.c_str());
    return false;
  }
  flow->arrows = s.flow_draw[0], flow->streamlines = s.flow_draw[1];
  flow->colour_wheel = s.flow_draw[2], flow->texture = s.flow_draw[3];
  flow->zoom_to_plane = s.flow_draw[4], flow->common_scale = s.flow_draw[5];
  return true;
}

}  // namespace

bool apply_session(MainWindow* window, const Session& s, QString* error) {
  QImage texture;
  std::optional<MotionScript> script;
  PanelDisplay display = PanelDisplay::kSideBySide;
  if (!parse_panel_display(s.display, &display)) {
    *error = QStringLiteral("unknown display '%1'").arg(QString::fromStdString(s.display));
    return false;
  }
  const ExactRendererKind* exact = find_exact_renderer(s.exact_renderer);
  if (!exact) {
    *error = QStringLiteral("animation.exact_renderer: unknown renderer '%1' (known: %2)")
                 .arg(QString::fromStdString(s.exact_renderer),
                      QString::fromStdString(exact_renderer_names()));
    return false;
  }
  if (!window->view(QString::fromStdString(s.view))) {
    *error = QStringLiteral("unknown view '%1'").arg(QString::fromStdString(s.view));
    return false;
  }
  FlowDisplay flow = window->flow_view()->display();
  BasisKind basis = BasisKind::kPlanar;
  if (!parse_window_state(s, &flow, &basis, error)) return false;
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
  window->animation_view()->set_exact_renderer(*exact);
  model->set_frame(s.frame);
  window->flow_view()->set_display(flow);
  window->basis_view()->set_basis(basis);
  window->basis_view()->set_playing(s.basis_playing);
  window->set_presentation(s.presentation);
  window->show_lesson_caption(QString::fromStdString(s.lesson));
  window->set_play_rate(s.play_rate);
  window->show_view(QString::fromStdString(s.view));
  return true;
}

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
