// The main window: the window model (gui/models/window_model.h), the one home of what the
// window shows, shared by every view; the views as tabs, one per entry of the view table
// (gui/app/view_table.h); the scene panel as a dock; a caption banner for lessons and a
// message banner for rejected input; play controls for the scene's motion; presentation
// mode. The window follows the model's signals (the view in front, the theme, the play
// timer, the lesson's caption); its own controls edit the model.
#pragma once

#include <QElapsedTimer>
#include <QMainWindow>
#include <vector>

#include "adapters/view_theme.h"
#include "lessons/lesson_player.h"
#include "lessons/lessons.h"
#include "models/frame_pacer.h"

class QAction;
class QComboBox;
class QSlider;
class QToolBar;
class QDockWidget;
class QLabel;
class QMenu;
class QSplitter;
class QStackedWidget;
class QTabWidget;
class QTimer;

namespace oflab {

class SceneControls;
class ViewPage;
class WindowModel;
struct ViewEntry;

class StudyWindow;

class MainWindow : public QMainWindow, public LessonStage {
  Q_OBJECT

 public:
  // A tab: a view made by its table entry, with the entry's name.
  struct Tab {
    QString name;
    ViewPage* page;
  };

  // Opens on the default demo with the flow view in front.
  explicit MainWindow(QWidget* parent = nullptr);

  // What the window shows: read and edit it here, never through a view.
  WindowModel* model() const { return model_; }
  SceneControls* scene_controls() const { return controls_; }

  // The view with this command-line name, or nullptr; all names in tab order.
  ViewPage* view(const QString& name) const;
  QStringList view_names() const;
  // Brings the named view to the front (through the model); false when there is no such
  // view.
  bool show_view(const QString& name);
  ViewPage* current_view() const;
  QString current_view_name() const;
  // The views of the cause-and-effect layout (the flow view and the world view, made from the
  // view table beside each other), empty while the layout was never shown. The layout shows
  // instead of the tabs while the model's cause_and_effect() is on (View menu, F8).
  const std::vector<ViewPage*>& layout_views() const { return layout_views_; }

  // Applies a lesson's state (WindowModel::apply); its narrative shows as the caption.
  void apply_lesson(const Lesson& lesson);

  // The threshold study's window (views/study_window.h; Study menu), made on the first call,
  // shown and raised.
  StudyWindow* open_study_window();
  // A lesson's steps, as the teacher takes them, played by the one lesson player
  // (session/lessons/lesson_player.h) on this window as its stage. perform_lesson_step does
  // step `step` (1-based) of `lesson`: its state (over the one on screen), then its frame,
  // then its frames played, and shows its text. go_to_lesson_step starts the lesson paused
  // (playing live at step 0 when the lesson plays and the clock is the window's own), plays
  // its frames, and performs steps 1 .. `step` in turn (0: the narrative). Both return false
  // and show a message for a step the lesson does not have or a state the window refuses.
  bool perform_lesson_step(const Lesson& lesson, int step);
  bool go_to_lesson_step(const Lesson& lesson, int step);

  // The window as a lesson's stage (lessons/lesson_player.h): its model's state, applied
  // whole; seeking and playing its scene's frames as play_frames does.
  WindowState stage_state() const override;
  std::string stage_apply(const WindowState& state) override;
  void stage_stop() override;
  void stage_seek(int frame) override;
  int stage_loop_frames() const override;
  void stage_play(int frames) override { play_frames(frames); }
  void stage_set_step(int step) override;
  // The caption banner's text: the narrative of the model's lesson, "" for none.
  QString caption() const;

  // The message shown for rejected input; empty when none is visible.
  QString message() const;

  // Presentation mode, the play rate (frames per second; frames follow the wall clock,
  // models/frame_pacer.h) and playing are the model's: the window follows its play_changed
  // and presentation_changed.

  // Advances the scene's motion and each view's own animation by `frames` steps, rendering
  // the visible view after each (used by --screenshot --frames N and the lessons). Events
  // are processed between frames, so Escape (cancel_long_work) or closing the window stops
  // it after the frame drawn; it does nothing while frames are already playing (a key
  // pressed meanwhile starts no second loop).
  void play_frames(int frames);
  // Escape: stops what plays (frames played by play_frames, a lesson's steps being played,
  // live play), keeping the frame shown; the status bar says where it stopped. Sticky until
  // the next lesson step or play_frames run starts afresh (clear_cancel).
  void cancel_long_work();
  bool cancelled() const { return cancelled_; }
  bool playing_frames() const { return playing_frames_; }
  void clear_cancel() { cancelled_ = false; }
  // An exception that escaped the engine in an event handler (the application's notify,
  // app/app_runner.h): live play and any frames playing stop, and the banner says `what`
  // ("the engine stopped at frame 15: std::bad_alloc"); the window stays open.
  void report_failure(const QString& what);

  // With an external clock no timer advances anything: only play_frames does, so
  // screenshots and benchmarks are reproducible. Playing states are kept.
  void set_external_clock(bool on);

  // Plays a motion script (a shipped name or a file). A script that cannot be read or
  // used shows a message and leaves the session as it was; returns false then.
  bool load_script(const QString& name_or_path);

  // Saves the model's state as a session file (session/state/window_state_file.h); refuses an
  // existing file unless `overwrite`. Loads one and applies it, changing nothing when it
  // cannot be read or used. Both show a message naming the file and return false on
  // failure; both confirm success in the status bar.
  bool save_session(const QString& path, bool overwrite);
  bool load_session(const QString& path);

  // The views' theme: the model's look at the window's presentation scale
  // (presentation_scale of the window's size when the look was last set).
  ViewTheme theme() const;

  // The whole window as drawn, VTK content included.
  QImage grab_window_image();

 protected:
  // The play keys (Space, Left, Right, Home, End, Escape) act whatever has focus, except in a
  // number field the user is typing into; Enter in a number field applies the value and gives the
  // focus back to the view.
  bool eventFilter(QObject* watched, QEvent* event) override;
  // Closing the window stops frames playing (cancel_long_work).
  void closeEvent(QCloseEvent* event) override;
  // In presentation mode, sizes the look to the window (presentation_scale).
  void resizeEvent(QResizeEvent* event) override;

 private:
  void create_view_shortcuts(QMenu* menu);
  bool handle_play_key(QWidget* target, int key);
  void add_view(const ViewEntry& entry);
  void create_actions();
  void create_menus();
  void create_play_bar();
  QWidget* create_banners();
  void style_banners();
  void fit_scene_panel();
  // Disables the scene panel's controls, with the view's note, when the view in front does
  // not draw the panel's plane (ViewPage::scene_panel_note).
  void update_scene_panel();
  // The status bar's permanent note of what the animation and analysis views play.
  void update_source_status();
  void show_message(const QString& text);
  // Follow the model: the view in front, the theme, the play timer and the caption.
  void show_model_view();
  void show_presentation();
  void show_play();
  void show_lesson();
  void show_layout();
  // The lesson's next (+1) or previous (-1) step, if it has one (PageDown, PageUp).
  void step_lesson(int delta);
  void clear_message();
  void update_frame_label();
  void add_scrub_controls(QToolBar* bar);
  void load_texture();
  void save_screenshot();
  void save_view_screenshot();
  void create_export_menu(QMenu* file);

  WindowModel* model_;
  SceneControls* controls_;
  QTabWidget* tabs_;
  QStackedWidget* stack_ = nullptr;  // the tabs, or the cause-and-effect layout
  QSplitter* cause_effect_ = nullptr;
  std::vector<ViewPage*> layout_views_;
  QAction* layout_action_ = nullptr;
  QDockWidget* scene_dock_ = nullptr;
  QSlider* scrub_ = nullptr;
  QComboBox* speed_box_ = nullptr;
  QAction* end_action_ = nullptr;
  std::vector<Tab> views_;
  QLabel* caption_banner_ = nullptr;
  QLabel* source_status_ = nullptr;
  QLabel* message_banner_ = nullptr;
  QLabel* frame_label_ = nullptr;
  StudyWindow* study_window_ = nullptr;  // made when first opened
  QTimer* motion_timer_;
  QElapsedTimer play_clock_;
  FramePacer pacer_;
  QAction* play_action_ = nullptr;
  QAction* step_action_ = nullptr;
  QAction* back_action_ = nullptr;
  QAction* reset_action_ = nullptr;
  QAction* presentation_action_ = nullptr;
  QAction* stop_action_ = nullptr;
  double theme_scale_ = 1.0;  // presentation_scale of the window when the look was set
  bool external_clock_ = false;
  bool playing_frames_ = false;  // play_frames is running
  bool cancelled_ = false;       // Escape or closing asked it to stop
};

}  // namespace oflab
