// The scene panel: sliders and numeric fields for the motion (V, Omega, motion model), the
// plane (two tilt angles and distance, see gui/models/scene_parameters.h) and the camera's focal
// length. Every edit proposes a whole new PlaneScene to the SceneModel; when the model rejects
// it the panel snaps back to the model's scene, so the panel never shows a state the views
// do not draw.
#pragma once

#include <QWidget>
#include <functional>
#include <vector>

#include "flow/plane_scene.h"

class QComboBox;
class QLabel;

namespace oflab {

class SceneModel;
struct Limit;
class SliderSpin;

class SceneControls : public QWidget {
  Q_OBJECT

 public:
  // The model must outlive the panel.
  explicit SceneControls(SceneModel* model, QWidget* parent = nullptr);

  // The control for a parameter by its object name ("velocity_x", "omega_z", "turn",
  // "tilt", "distance", "focal", ...), or nullptr.
  SliderSpin* control(const QString& name) const;

  // Shows the model's scene in every control (without emitting edits).
  void sync_from_model();

  // Empty: the controls apply to the view in front and are enabled. Otherwise `note` (what
  // that view plays instead) is shown above the controls, which are disabled.
  void set_note(const QString& note);
  QString note() const;

 signals:
  // A typed value was refused (one line naming the control, the value and its range); the
  // controls show the scene's values again.
  void refused(const QString& message);

 private:
  struct Binding {
    SliderSpin* widget;
    std::function<double(const PlaneScene&)> get;
    std::function<void(PlaneScene&, double)> set;
  };
  QWidget* make_motion_group();
  QWidget* make_plane_group();
  QWidget* make_camera_group();
  // A control's slider span: from minimum to maximum in steps, shown with decimals and
  // unit. Its field takes any number: the scene model checks the plane's values against
  // their limits (core/flow/limits.h); a value the scene does not hold (turn, tilt) is
  // checked against `limit` here.
  struct Range {
    double minimum, maximum, step;
    int decimals;
    QString suffix;
    const Limit* limit = nullptr;
  };
  // `what` is the control's tooltip: what it means (its unit is added).
  SliderSpin* add_control(QWidget* group, const QString& name, const QString& label,
                          const QString& what, const Range& range,
                          std::function<double(const PlaneScene&)> get,
                          std::function<void(PlaneScene&, double)> set);
  void propose(const std::function<void(PlaneScene&)>& change);

  SceneModel* model_;
  std::vector<Binding> bindings_;
  QComboBox* model_box_ = nullptr;
  QLabel* note_ = nullptr;
  std::vector<QWidget*> groups_;  // motion, plane, camera
};

}  // namespace oflab
