// The animation view's control bar: what plays (the single plane of the scene panel, a
// shipped motion script, or a shipped multi-plane scene with a viewer script), the engine's
// reuse policy (the entries of core/engine/reuse_policy.h, with a one-click
// affine/perspective switch), the per-level thresholds, the Delta policy, the sampling, and
// how the two panels are shown. It only edits values; the view applies them and puts them
// back when it refuses them.
#pragma once

#include <QWidget>

#include "engine/engine.h"

class QComboBox;
class QDoubleSpinBox;
class QPushButton;

namespace oflab {

// How the animation view shows the engine's frame and the exact one.
enum class PanelDisplay { kSideBySide, kDifference, kBlink };
const char* panel_display_name(PanelDisplay display);  // "side-by-side", "difference", "blink"
bool parse_panel_display(const std::string& text, PanelDisplay* display);

// The source picker's choice: kind "plane" (the scene panel's plane and motion), "script"
// (a motion script for the plane) or "scene" (a scene with a viewer script); names are
// shipped names or file paths.
struct SourceChoice {
  std::string kind = "plane";
  std::string name;    // script or scene
  std::string viewer;  // viewer script, scenes only
  bool operator==(const SourceChoice& o) const {
    return kind == o.kind && name == o.name && viewer == o.viewer;
  }
};

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

 signals:
  void settings_edited();
  void display_edited();
  void source_edited();

 private:
  QWidget* make_source_row();
  QWidget* make_engine_row();
  void add_file_entry(QComboBox* box, const std::string& kind, const std::string& path);

  QComboBox* source_box_ = nullptr;
  QComboBox* viewer_box_ = nullptr;
  QComboBox* mode_box_ = nullptr;
  QPushButton* affine_switch_ = nullptr;
  QComboBox* display_box_ = nullptr;
  QDoubleSpinBox* thresholds_[kTermCount] = {};
  QComboBox* delta_box_ = nullptr;
  QComboBox* sampling_box_ = nullptr;
};

}  // namespace oflab
