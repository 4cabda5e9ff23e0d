#include "app/app_runner.h"

#include <QVTKOpenGLNativeWidget.h>

#include <QApplication>
#include <QBuffer>
#include <QByteArray>
#include <QElapsedTimer>
#include <QWindow>
#include <algorithm>
#include <new>
#include <ostream>

#include "app/lesson_check.h"
#include "app/main_window.h"
#include "app/screenshot.h"
#include "formats/atomic_file.h"
#include "image/thread_pool.h"
#include "models/scene_model.h"
#include "models/window_model.h"
#include "player/stage_times.h"
#include "views/study_window.h"
#include "views/view_page.h"

namespace oflab {
namespace {

// Processes events until the window is exposed or the timeout passes.
bool wait_until_exposed(QWidget* window, int timeout_ms) {
  QElapsedTimer timer;
  timer.start();
  while (timer.elapsed() < timeout_ms) {
    QApplication::processEvents(QEventLoop::AllEvents, 20);
    if (window->windowHandle() && window->windowHandle()->isExposed()) {
      QApplication::processEvents();
      return true;
    }
  }
  return false;
}

// The frame and what failed, for the window's banner: "out of memory at frame 15
// (std::bad_alloc)" or "the engine failed at frame 15: WHAT".
QString failure_text(const MainWindow& window, const std::exception& e) {
  const int frame = window.model()->scene()->frame();
  if (dynamic_cast<const std::bad_alloc*>(&e)) {
    return QObject::tr("out of memory at frame %1 (%2)").arg(frame).arg(e.what());
  }
  return QObject::tr("the engine failed at frame %1: %2").arg(frame).arg(e.what());
}

}  // namespace

bool GuardedApplication::notify(QObject* receiver, QEvent* event) {
  try {
    return QApplication::notify(receiver, event);
  } catch (const std::exception& e) {
    MainWindow* window = nullptr;
    for (QWidget* w : topLevelWidgets()) {
      if (auto* m = qobject_cast<MainWindow*>(w)) window = m;
    }
    if (!window) throw;
    window->report_failure(failure_text(*window, e));
    return false;
  }
}

bool prepare_window(MainWindow* window, const LaunchOptions& options, std::string* error) {
  window->resize(options.width, options.height);
  if (!options.screenshot.empty() || options.benchmark > 0 || !options.check_lessons.empty()) {
    window->set_external_clock(true);
  }
  window->show();
  if (!wait_until_exposed(window, 10000)) {
    *error = "the window did not appear on the display within 10 s";
    return false;
  }
  return true;
}

// `image` as PNG into `path`, written whole through a temporary file beside it
// (formats/atomic_file.h); whether it may replace an existing file was decided with --force
// before the window opened. False, with one line on `err` naming `option`, when it fails.
bool write_png(const QImage& image, const std::string& path, const char* option,
               std::ostream& err) {
  QByteArray png;
  QBuffer buffer(&png);
  buffer.open(QIODevice::WriteOnly);
  if (image.isNull() || !image.save(&buffer, "PNG")) {
    err << "oflab: " << option << ": cannot encode the " << image.width() << " x " << image.height()
        << " image as PNG\n";
    return false;
  }
  try {
    write_file_atomically(path, png.toStdString(), Overwrite::kReplace);
  } catch (const FileWriteError& e) {
    err << "oflab: " << option << ": " << e.what() << "\n";
    return false;
  }
  return true;
}

int take_screenshot(MainWindow* window, const LaunchOptions& options, std::ostream& out,
                    std::ostream& err) {
  window->clear_cancel();
  window->play_frames(options.frames);
  if (window->cancelled()) {
    const QString why = window->message().isEmpty() ? QStringLiteral("Escape or the window closed")
                                                    : window->message();
    err << "oflab: --frames: stopped at frame " << window->model()->scene()->frame() << " of "
        << options.frames << ": " << why.simplified().toStdString() << "\n";
    return 1;
  }
  const QString view = QString::fromStdString(options.view);
  ViewPage* page = view.isEmpty() || options.whole_window ? nullptr : window->view(view);
  const QImage image = page ? page->render_image() : window->grab_window_image();
  if (!write_png(image, options.screenshot, "--screenshot", err)) return 1;
  out << "oflab: wrote " << options.screenshot << " (" << image.width() << " x " << image.height()
      << ", " << (page ? options.view : std::string("window")) << " after " << options.frames
      << " frames)\n";
  return 0;
}

namespace {

// The benchmark's stages (player/stage_times.h) in milliseconds per frame, the rest (Qt's
// events, VTK, what no stage covers) as "other", and the worker threads.
void print_stage_times(double total_ms, int frames, std::ostream& out) {
  out << "oflab: per frame (ms, " << worker_threads() << " threads):";
  double staged = 0.0;
  for (int k = 0; k < static_cast<int>(FrameStage::kCount); ++k) {
    const FrameStage stage = static_cast<FrameStage>(k);
    staged += stage_ms(stage);
    out << " " << frame_stage_name(stage) << " " << stage_ms(stage) / frames << ",";
  }
  out << " other " << std::max(0.0, total_ms - staged) / frames << ", total " << total_ms / frames
      << "\n";
}

}  // namespace

int run_benchmark(MainWindow* window, const LaunchOptions& options, std::ostream& out) {
  // The animation view unless another view is asked for: it runs the engine, renders the
  // exact frame (core's exact render, or VTK's with --animation-exact vtk) and paints both
  // panels every frame. With --cause-and-effect, the layout's two views draw every frame.
  const bool layout = window->model()->cause_and_effect();
  const QString name = layout ? QStringLiteral("cause-and-effect layout (world + flow)")
                       : options.view.empty() || options.view == "window"
                           ? QStringLiteral("animation")
                           : QString::fromStdString(options.view);
  if (!layout) window->show_view(name);
  SceneModel* model = window->model()->scene();
  for (int i = 0; i < 3; ++i) window->play_frames(1);  // warm up caches and shaders
  reset_stage_times();
  QElapsedTimer timer;
  timer.start();
  for (int i = 0; i < options.benchmark; ++i) {
    model->advance(1);  // the visible view refreshes on scene_changed
    QApplication::processEvents();
  }
  const double seconds = timer.nsecsElapsed() * 1e-9;
  QSize size = window->current_view()->size();  // the view's area
  if (layout) {
    size = QSize(0, 0);
    for (const ViewPage* page : window->layout_views()) {
      size = QSize(size.width() + page->width(), std::max(size.height(), page->height()));
    }
  }
  out << "oflab: " << name.toStdString() << (layout ? ", " : " view, ") << options.benchmark
      << " frames in " << seconds << " s: " << (seconds > 0 ? options.benchmark / seconds : 0.0)
      << " frames per second (window " << options.width << " x " << options.height << ", view "
      << size.width() << " x " << size.height() << ")\n";
  print_stage_times(seconds * 1e3, options.benchmark, out);
  return 0;
}

int check_lessons(MainWindow* window, const LaunchOptions& options, std::ostream& out,
                  std::ostream& err) {
  int claims = 0, false_claims = 0;
  bool shots_written = true;
  for (const std::string& name : options.check_lessons) {
    const Lesson& lesson = *find_lesson(name);
    // --step-shots: the window as each part of the lesson leaves it, claims measured.
    const auto shoot = [&](int step) {
      if (options.step_shots.empty() || !shots_written) return;
      const std::string path = step_shot_path(options.step_shots, lesson.name, step);
      shots_written = write_png(window->grab_window_image(), path, "--step-shots", err);
      if (shots_written) out << "oflab: wrote " << path << "\n";
    };
    std::vector<ClaimCheck> checks;
    try {
      checks = check_lesson(window, lesson, shoot, options.time_claims, options.claim_kinds);
    } catch (const std::runtime_error& e) {  // a part the window refused
      err << "oflab: " << e.what() << "\n";
      ++false_claims;
    }
    for (const ClaimCheck& check : checks) {
      out << describe(lesson, check) << "\n";
      ++claims;
      false_claims += !check.holds;
    }
  }
  out << "oflab: " << claims << " claims of " << options.check_lessons.size() << " lessons at "
      << options.width << " x " << options.height << ": "
      << (false_claims == 0 ? std::string("all hold") : std::to_string(false_claims) + " false")
      << "\n";
  if (!shots_written) return 1;
  return false_claims == 0 ? 0 : 1;
}

namespace {

// The window's refusal of the launch state as one line naming the option and file it came
// from: "--session: s.json: texture: ...", "--scene: big.json: the scene's 1000 polygons ...".
std::string launch_problem(const LaunchOptions& options, std::string problem) {
  std::string origin = options.state_origin;
  const std::string source_field = "animation.source: ";
  if (!options.scene_origin.empty() && problem.rfind(source_field, 0) == 0) {
    origin = options.scene_origin;
    problem.erase(0, source_field.size());
  }
  return origin.empty() ? problem : origin + ": " + problem;
}

}  // namespace

int run_study(MainWindow* window, const LaunchOptions& options, std::ostream& out,
              std::ostream& err) {
  const StudyLaunch& s = options.study;
  StudyWindow* study = window->open_study_window();
  study->resize(options.width, options.height);
  study->select_study(*s.study);
  study->set_fields(s.method, s.observer, s.ppi, s.seed);
  if (s.simulate_px > 0.0) {
    SimulatedObserver observer(s.seed, PsychometricFunction{s.simulate_px, s.study->assumed_slope,
                                                            s.study->assumed_lapse});
    const std::string problem = study->run_simulated(observer);
    const std::string error = problem.empty() ? study->write_csv(s.csv, s.force) : problem;
    if (!error.empty()) {
      err << "oflab: --study-csv: " << error << "\n";
      return 1;
    }
    out << "oflab: wrote " << s.csv << ": " << study->session()->trials().size() << " trials of "
        << s.study->name << " (" << s.method << ", seed " << s.seed << ")\n";
  }
  if (options.screenshot.empty()) return s.simulate_px > 0.0 ? 0 : QApplication::exec();
  if (options.frames > 0 && s.simulate_px <= 0.0) {  // the first trial at its frame
    study->start();
    QElapsedTimer waited;
    waited.start();
    while (study->first_clip_frame() < options.frames && study->setup_status().empty() &&
           waited.elapsed() < 30000) {
      QApplication::processEvents(QEventLoop::AllEvents, 5);
    }
  }
  QApplication::processEvents();
  const QImage image = study->grab().toImage();
  if (!write_png(image, options.screenshot, "--screenshot", err)) return 1;
  out << "oflab: wrote " << options.screenshot << " (" << image.width() << " x " << image.height()
      << ", the study window)\n";
  return 0;
}

int run_oflab(const LaunchOptions& options, std::ostream& out, std::ostream& err) {
  set_worker_threads(options.threads);
  MainWindow window;
  QString problem;
  if (!window.model()->apply(options.state, &problem)) {  // the files it names, the source
    err << "oflab: " << launch_problem(options, problem.simplified().toStdString()) << "\n";
    return 2;
  }
  std::string error;
  if (!prepare_window(&window, options, &error)) {
    err << "oflab: " << error << "\n";
    return 1;
  }
  if (!options.check_lessons.empty()) return check_lessons(&window, options, out, err);
  if (options.study.study) return run_study(&window, options, out, err);
  if (!options.screenshot.empty()) return take_screenshot(&window, options, out, err);
  if (options.benchmark > 0) return run_benchmark(&window, options, out);
  return QApplication::exec();
}

}  // namespace oflab
