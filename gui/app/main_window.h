// The main window: the models (one SceneModel and one AnimationModel) shared by every view;
// the views as tabs, one per entry of the view table (gui/app/view_table.h); the scene panel
// as a dock; a caption banner for lessons and a message banner for rejected input; play
// controls for the scene's motion; presentation mode.
#pragma once

#include <QElapsedTimer>
#include <QMainWindow>
#include <vector>

#include "app/lessons.h"
#include "models/frame_pacer.h"

class QAction;
class QComboBox;
class QSlider;
class QToolBar;
class QDockWidget;
class QLabel;
class QMenu;
class QTabWidget;
class QTimer;

namespace oflab {

class AnalysisView;
class AnimationModel;
class AnimationView;
class BasisView;
class FlowView;
class SceneControls;
class SceneModel;
class ViewPage;
struct ViewEntry;

class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  // A tab: a view made by its table entry, with the entry's name.
  struct Tab {
    QString name;
    ViewPage* page;
  };

  // Opens on the default demo with the flow view in front.
  explicit MainWindow(QWidget* parent = nullptr);

  SceneModel* model() const { return model_; }
  AnimationModel* animation_model() const { return animation_model_; }
  SceneControls* scene_controls() const { return controls_; }
  // The view of type V among the tabs (nullptr when there is none). V must be complete
  // where this is called.
  template <class V>
  V* find_view() const {
    for (const Tab& tab : views_) {
      if (auto* v = dynamic_cast<V*>(tab.page)) return v;
    }
    return nullptr;
  }
  FlowView* flow_view() const;
  BasisView* basis_view() const;
  AnimationView* animation_view() const;
  AnalysisView* analysis_view() const;

  // The view with this command-line name, or nullptr; all names in tab order.
  ViewPage* view(const QString& name) const;
  QStringList view_names() const;
  // Brings the named view to the front; false when there is no such view.
  bool show_view(const QString& name);
  ViewPage* current_view() const;
  QString current_view_name() const;

  // Sets up a lesson: its scene, view, options and caption.
  void apply_lesson(const Lesson& lesson);
  QString caption() const;
  // The lesson whose caption shows ("" for none); show_lesson_caption sets it and its
  // caption without touching the scene (a saved session carries the scene itself).
  QString lesson() const { return lesson_; }
  void show_lesson_caption(const QString& name);
  void set_caption(const QString& text);  // empty hides the banner

  // The message shown for rejected input; empty when none is visible.
  QString message() const;

  bool presentation() const { return presentation_; }
  void set_presentation(bool on);

  // Live play rate in frames per second (the speed box offers 5, 10, 15, 30 and 60; another
  // rate is added to it, one below 1 is taken as 1). Frames follow the wall clock
  // (models/frame_pacer.h).
  int play_rate() const;
  void set_play_rate(int frames_per_second);

  bool motion_playing() const;
  void set_motion_playing(bool playing);

  // Advances the scene's motion and each view's own animation by `frames` steps, rendering
  // the visible view after each (used by --screenshot --frames N).
  void play_frames(int frames);

  // With an external clock no timer advances anything: only play_frames does, so
  // screenshots and benchmarks are reproducible. Playing states are kept.
  void set_external_clock(bool on);

  // Plays a motion script (a shipped name or a file). A script that cannot be read or
  // used shows a message and leaves the session as it was; returns false then.
  bool load_script(const QString& name_or_path);

  // Saves the session as JSON; refuses an existing file unless `overwrite`. Loads one,
  // changing nothing when it cannot be used. Both show a message and return false on
  // failure.
  bool save_session(const QString& path, bool overwrite);
  bool load_session(const QString& path);

  // The whole window as drawn, VTK content included.
  QImage grab_window_image();

 protected:
  // The play keys (Space, Left, Right, Home, End) act whatever has focus, except in a number
  // field the user is typing into; Enter in a number field applies the value and gives the
  // focus back to the view.
  bool eventFilter(QObject* watched, QEvent* event) override;

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
  void show_message(const QString& text);
  void clear_message();
  void update_frame_label();
  void add_scrub_controls(QToolBar* bar);
  void load_texture();
  void save_screenshot();
  void save_view_screenshot();
  void create_export_menu(QMenu* file);

  SceneModel* model_;
  SceneControls* controls_;
  QTabWidget* tabs_;
  QDockWidget* scene_dock_ = nullptr;
  AnimationModel* animation_model_;
  QSlider* scrub_ = nullptr;
  QComboBox* speed_box_ = nullptr;
  QAction* end_action_ = nullptr;
  std::vector<Tab> views_;
  QLabel* caption_banner_ = nullptr;
  QLabel* message_banner_ = nullptr;
  QLabel* frame_label_ = nullptr;
  QTimer* motion_timer_;
  QElapsedTimer play_clock_;
  FramePacer pacer_;
  QAction* play_action_ = nullptr;
  QAction* step_action_ = nullptr;
  QAction* back_action_ = nullptr;
  QAction* reset_action_ = nullptr;
  QAction* presentation_action_ = nullptr;
  bool presentation_ = false;
  QString lesson_;
  bool external_clock_ = false;
};

}  // namespace oflab
