// The one home of the window's state: a thin Qt adapter over one lab (session/player/lab.h),
// which holds the whole state (session/state/window_state.h) and plays it: the plane panel
// (adapted by the scene model), the run of its source (adapted by the animation model), the
// policy comparison, and everything else the window shows (the view in front, each view's
// options, presentation mode, play rate and playing, the lesson) as one WindowState value.
// Views read and edit the state through this model and redraw on its signals; they never
// read each other. The window applies a whole state with apply() (a lesson, the command
// line, a session) and captures one with state().
//
// Every setter checks its value with the same rule as the files and the command line
// (core/flow/limits.h, window_state_problem): a refused value changes nothing and is
// reported with input_rejected, naming the field, the value and the allowed range.
#pragma once

#include <QImage>
#include <QObject>
#include <memory>
#include <string>
#include <vector>

#include "state/window_state.h"

namespace oflab {

class AnimationModel;
class Lab;
class PolicyComparison;
class SceneModel;

class WindowModel : public QObject {
  Q_OBJECT

 public:
  // The default window (WindowState{}). `view_names` are the views the window has (the view
  // table's names, gui/app/view_table.h), in order; the first is in front.
  explicit WindowModel(std::vector<std::string> view_names, QObject* parent = nullptr);
  ~WindowModel() override;

  // The lab the window plays (the headless claims of lessons measure it).
  Lab& lab() const { return *lab_; }
  SceneModel* scene() const { return scene_; }
  AnimationModel* animation() const { return animation_; }
  // The policies the animation view's comparison layout plays, kept on the scene's frame.
  PolicyComparison& comparison() const;

  // The whole state as the window shows it now.
  WindowState state() const;
  // The state's values the lab keeps beside its panel and runs (Lab::values: the view, each
  // view's options, presentation, play, the lesson), read-only; edits go through the setters.
  const WindowState& values() const;
  // Applies a whole state: checks everything first (window_state_problem, the view, the
  // source kind and its files, the exact renderer, the lesson, the texture and script files)
  // and changes nothing, returning false with *error set ("field: problem"), when any check
  // fails. Emits every signal below on success.
  bool apply(const WindowState& state, QString* error);

  const std::vector<std::string>& view_names() const { return view_names_; }
  const std::string& view() const { return values().view; }
  bool set_view(const std::string& name);  // false (and input_rejected) for an unknown view

  const FlowDisplay& flow_display() const { return values().flow; }
  void set_flow_display(const FlowDisplay& display);
  BasisKind basis() const { return values().basis; }
  void set_basis(BasisKind basis);
  bool basis_playing() const { return values().basis_playing; }
  void set_basis_playing(bool playing);
  // The basis view shows the explorer (WindowState::basis_explorer).
  bool basis_explorer() const { return values().basis_explorer; }
  void set_basis_explorer(bool on);
  // The explorer's eight values (session/basis/basis_explorer.h), each in its term's unit.
  const ExplorerTerms& explorer_terms() const { return values().explorer_terms; }
  // Sets the value of term `index` (0 .. kExplorerTermCount - 1); refused (false, and
  // input_rejected naming the term and its limit) outside the term's limit.
  bool set_explorer_term(int index, double value);
  // Sets all eight; refused as a whole when one is outside its limit.
  bool set_explorer_terms(const ExplorerTerms& terms);

  PanelDisplay panel_display() const { return values().display; }
  void set_panel_display(PanelDisplay display);
  // The compared policies by registry name; refused unless 1 .. kMaxComparedPolicies
  // distinct known names.
  std::vector<std::string> compared() const;
  bool set_compared(const std::vector<std::string>& names);
  const std::string& exact_renderer() const { return values().exact_renderer; }
  bool set_exact_renderer(const std::string& name);
  // How every panel is framed (WindowState::framing) and whether that frames what is drawn now.
  PanelFraming framing() const { return values().framing; }
  void set_framing(PanelFraming framing);
  bool frames_content() const { return oflab::frames_content(framing(), presentation()); }
  double zoom() const { return values().zoom; }
  bool set_zoom(double zoom);  // refused outside limits::kZoom

  bool presentation() const { return values().presentation; }
  void set_presentation(bool on);
  bool scene_panel() const { return values().scene_panel; }
  void set_scene_panel(bool shown);
  // The cause-and-effect layout (WindowState::cause_and_effect) is shown.
  bool cause_and_effect() const { return values().cause_and_effect; }
  void set_cause_and_effect(bool shown);
  // Where the world view looks from (WindowState::world_camera).
  WorldCamera world_camera() const { return values().world_camera; }
  void set_world_camera(WorldCamera camera);
  int play_rate() const { return values().play_rate; }
  bool set_play_rate(int frames_per_second);  // refused outside limits::kPlayRate
  bool playing() const { return values().playing; }
  void set_playing(bool playing);

  // The lesson whose narrative shows; empty for none. Set by apply() only.
  const std::string& lesson() const { return values().lesson; }
  // The lesson's step on screen (0: its narrative). The window performs a step's actions and
  // then sets it (app/main_window.h perform_lesson_step); refused beyond the lesson's steps.
  int lesson_step() const { return values().lesson_step; }
  bool set_lesson_step(int step);

  // Reports a refused value from a control (the control keeps the model's value): the same
  // signal as the model's own refusals.
  void reject(const QString& message) { emit input_rejected(message); }

 signals:
  void view_changed();
  void flow_display_changed();
  void basis_changed();     // the basis or its playing
  void explorer_changed();  // the explorer shown or hidden, or its values
  // The animation view's layout, compared policies, exact renderer, framing or zoom.
  void panels_changed();
  void presentation_changed();
  void scene_panel_changed();
  void layout_changed();  // the cause-and-effect layout was shown or hidden
  void world_camera_changed();
  void play_changed();  // the play rate or playing
  void lesson_changed();
  void study_changed();  // a state was applied: its study.open may differ
  void input_rejected(const QString& message);

 private:
  // The checks of apply() that need the window's tables (the views, the exact renderers);
  // "" when none fails. The lab checks the rest (Lab::problem).
  std::string front_end_problem(const WindowState& state) const;

  WindowState& values();

  std::vector<std::string> view_names_;
  std::unique_ptr<Lab> lab_;
  QImage default_texture_;  // the texture of a state without one (adapters/texture.h)
  QImage loaded_texture_;   // the texture file the lab last read, as Qt read it
  SceneModel* scene_;
  AnimationModel* animation_;
};

}  // namespace oflab
