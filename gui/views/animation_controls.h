// The animation view's control bar: what plays (an entry of the source-kind table,
// session/player/animation_sources.h, with its shipped name and viewer script), the engine's
// reuse policy (the entries of core/engine/reuse_policy.h, with a one-click
// affine/perspective switch; with the budget policy, a spin box of its pixel budget per
// frame), the per-level thresholds, the Delta policy, the sampling, what of a scene's layer the
// warps compute (the whole layer or what shows only), the layer content and its
// quality (core/content/layer_content.h: what a re-render draws; a single plane only, a
// scene's polygons keep their own), the cadence and stabilization plane of today's
// reprojection policies (gui/views/reprojection_controls.h), how the two panels are shown, and the
// policies the comparison layout plays (a menu of the registry: 2 to kMaxComparedPolicies of them).
// It only edits values; the view applies them and puts them back when it refuses them.
#pragma once

#include <QWidget>
#include <vector>

#include "engine/engine.h"
#include "player/animation_sources.h"
#include "player/policy_comparison.h"
#include "state/window_state.h"

class QAction;
class QComboBox;
class QDoubleSpinBox;
class QHBoxLayout;
class QPushButton;
class QSpinBox;
class QToolButton;

namespace oflab {

class ReprojectionControls;

class AnimationControls : public QWidget {
  Q_OBJECT

 public:
  explicit AnimationControls(QWidget* parent = nullptr);

  EngineSettings settings() const;
  void set_settings(const EngineSettings& settings);  // emits nothing
  PanelDisplay display() const;
  void set_display(PanelDisplay display);  // emits nothing
  SourceChoice source() const;
  // Selects the choice, adding a file entry when it is not a shipped one; emits nothing.
  void set_source(const SourceChoice& choice);
  // The policies the comparison layout plays, in registry order (2 .. kMaxComparedPolicies
  // of them once the user has picked; set_compared takes what PolicyComparison takes).
  std::vector<const ReusePolicy*> compared() const;
  void set_compared(const std::vector<const ReusePolicy*>& policies);  // emits nothing
  // Shows or hides the engine's two rows (the policy and the thresholds) under the source row:
  // a short window in presentation mode leaves them out for the panels' sake.
  void set_engine_rows_shown(bool shown);

 signals:
  void settings_edited();
  void display_edited();
  void source_edited();
  void compared_edited();
  // An edit the controls refused themselves (one line saying why); nothing changed.
  void refused(const QString& message);

 private:
  std::vector<QWidget*> engine_rows_;  // the mode row and the threshold row
  QWidget* make_source_row();
  // The engine's row: the reuse policy (with the budget box and the affine/perspective
  // switch), Delta, the sampling and the reprojection menu.
  QWidget* make_mode_row();
  // The "Warp" button after the viewer box (the source row has room for it; the engine's two
  // rows fill a 1024-pixel window): a menu of the warp areas (core/image/pixel_rows.h WarpArea: the
  // whole layer, or only the pixels no nearer opaque layer covers), one checked; a scene's setting,
  // disabled for single planes and scene shifting.
  QToolButton* make_warp_area_button(QWidget* parent);
  // The warp area the button's menu has checked.
  WarpArea warp_area() const;
  // Wires the policy, Delta and sampling boxes and the affine/perspective switch to
  // settings_edited (the budget box shown or hidden first).
  void connect_mode_controls();
  // The row of the per-level thresholds, then the content box and its quality.
  QWidget* make_threshold_row();
  QToolButton* make_compare_button(QWidget* parent);
  // The content box (the content registry) and the quality spin box, added to `layout`.
  void add_content_controls(QWidget* row, QHBoxLayout* layout);
  // A policy of the compare menu was toggled: keeps 2 .. kMaxComparedPolicies checked.
  void compared_toggled(QAction* action);
  void explain_controls();  // a tooltip on every control
  void add_file_entry(QComboBox* box, const std::string& kind, const std::string& path);
  // Enables what applies to `kind`: the viewer script box, the policy, threshold and
  // Delta controls (not for scene shifting), and the content box (single planes).
  void show_kind(const AnimationSourceKind& kind);
  // The source kind of the picker's current entry.
  const AnimationSourceKind& current_kind() const;
  // Shows the budget spin box only while the mode box holds a policy that shares a budget.
  void show_budget();

  QComboBox* source_box_ = nullptr;
  QComboBox* viewer_box_ = nullptr;
  QComboBox* mode_box_ = nullptr;
  QPushButton* affine_switch_ = nullptr;
  // The budget policy's pixels written per frame; its minimum (-1) reads "auto": no budget
  // given, the engine's default (core/engine/budget.h budget_or_default).
  QSpinBox* budget_box_ = nullptr;
  QComboBox* display_box_ = nullptr;
  QToolButton* compare_button_ = nullptr;
  std::vector<QAction*> compare_actions_;  // one per registry policy, in registry order
  QDoubleSpinBox* thresholds_[kTermCount] = {};
  QComboBox* delta_box_ = nullptr;
  QComboBox* sampling_box_ = nullptr;
  QToolButton* warp_area_button_ = nullptr;
  std::vector<QAction*> warp_area_actions_;  // one per WarpArea, in enum order
  QComboBox* content_box_ = nullptr;
  QSpinBox* quality_box_ = nullptr;
  ReprojectionControls* reprojection_ = nullptr;
  std::string shown_kind_;  // the kind of the source last shown by set_source
};

}  // namespace oflab
