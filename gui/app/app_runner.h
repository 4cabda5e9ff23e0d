// What oflab does with its parsed command line: open the window (interactive), or play
// some frames, save a screenshot and exit, or time the flow view.
#pragma once

#include <QApplication>
#include <iosfwd>

#include "app/launch_options.h"

namespace oflab {

class MainWindow;

// oflab's application: a QApplication whose notify turns an exception escaping an event
// handler (the engine running out of memory while Space or Page Down plays frames, a paint
// building the comparison) into a message in the main window (MainWindow::report_failure:
// playing stops, the window stays open) instead of the end of the program. Without a main
// window the exception goes on as before.
class GuardedApplication : public QApplication {
 public:
  GuardedApplication(int& argc, char** argv) : QApplication(argc, argv) {}
  bool notify(QObject* receiver, QEvent* event) override;
};

// Sets up the window for the options (size, lesson, view in front) and shows it, waiting
// until it is on screen. Returns false with *error set if the window never appeared.
bool prepare_window(MainWindow* window, const LaunchOptions& options, std::string* error);

// --screenshot: plays options.frames frames, captures the chosen view (or the whole
// window) and writes the PNG. Returns the exit code: 0, or 1 when the file cannot be
// written or the frames were stopped (Escape, the window closed, the engine failed: one
// line on `err` naming the frame and why).
int take_screenshot(MainWindow* window, const LaunchOptions& options, std::ostream& out,
                    std::ostream& err);

// --benchmark: plays options.benchmark frames of the animation view (or of the view named
// by --view) as fast as possible, each frame advancing the motion, running the engine,
// rendering the exact frame and painting the panels, and prints the frames per second to
// `out`. Returns 0.
int run_benchmark(MainWindow* window, const LaunchOptions& options, std::ostream& out);

// Checks the claims of options.check_lessons in the shown window (external clock) and prints
// one line per claim (gui/app/lesson_check.h describe) and a summary; 0 when every claim
// holds, 1 otherwise.
int check_lessons(MainWindow* window, const LaunchOptions& options, std::ostream& out);

// --study: opens the study window on options.study's study with its fields set. With
// --study-simulate, a simulated observer (study/study_session.h SimulatedObserver, seeded by
// the study seed, the study's assumed slope and lapse) answers every presentation in it and the
// trials go to --study-csv: 0, or 1 when the file cannot be written (one line on `err`).
// With --screenshot the study window is saved as PNG and oflab exits: its set-up page, its
// results after a simulated run, or with --frames N the first trial's first clip at frame N
// (after the rate check; the set-up page with its refusal when the display failed it); without
// either the window stays open (the event loop).
int run_study(MainWindow* window, const LaunchOptions& options, std::ostream& out,
              std::ostream& err);

// The whole program after parsing: needs a QApplication. Applies the session first, if one
// is given; a file it names that cannot be used ends the program with one line on `err`
// and exit code 2, as bad input on the command line does. Returns the exit code.
int run_oflab(const LaunchOptions& options, std::ostream& out, std::ostream& err);

}  // namespace oflab
