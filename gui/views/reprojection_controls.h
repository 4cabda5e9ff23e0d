// The settings of today's reprojection policies (core/engine/reuse_policy.h, manual/
// policies.md "Today's reprojection"), in the animation control bar's "Reprojection" menu:
// the cadence of the policies on a fixed cadence (render every N-th frame, limits::kCadence),
// and the stabilized-plane policy's plane: the automatic fit to the visible depth, or a
// plane given by a point and a normal in world coordinates (EngineSettings::stabilization).
// Like the other controls it only edits values: any number can be typed, and the model
// refuses one outside its limit (core/flow/limits.h) with a banner.
#pragma once

#include <QToolButton>

#include "engine/engine.h"

class QComboBox;
class QSpinBox;

namespace oflab {

class NumberBox;

class ReprojectionControls : public QToolButton {
  Q_OBJECT

 public:
  explicit ReprojectionControls(QWidget* parent = nullptr);

  // Copies the cadence and the stabilization plane shown into `settings`, leaving its other
  // fields as they are.
  void read_into(EngineSettings& settings) const;
  // Shows the cadence and the plane of `settings`; emits nothing.
  void show_settings(const EngineSettings& settings);

  // The button's tooltip: the cadence and which plane, in words ("... render every 2nd
  // frame and warp the frames between; the stabilized-plane policy's plane: automatic fit to
  // the depth"). The button itself says "Reprojection", short enough for a 1024-pixel bar.
  static QString summary(const EngineSettings& settings);
  // Which plane the stabilized-plane policy uses, for its panel's caption: "plane: automatic
  // fit to the depth" or "plane through (0, 0, -7), normal (0, 0, 1)".
  static QString plane_text(const StabilizationPlane& plane);

 signals:
  void edited();

 private:
  void show_plane_fields();  // the point and normal fields only for a given plane

  QSpinBox* cadence_box_ = nullptr;
  QComboBox* plane_box_ = nullptr;
  NumberBox* point_[3] = {};
  NumberBox* normal_[3] = {};
};

}  // namespace oflab
