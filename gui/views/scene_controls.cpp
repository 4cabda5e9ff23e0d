#include "views/scene_controls.h"

#include <QComboBox>
#include <QGroupBox>
#include <QLabel>
#include <QVBoxLayout>

#include "flow/limits.h"
#include "models/scene_model.h"
#include "models/scene_parameters.h"
#include "views/slider_spin.h"

namespace oflab {

SceneControls::SceneControls(SceneModel* model, QWidget* parent) : QWidget(parent), model_(model) {
  setObjectName(QStringLiteral("scene_controls"));
  auto* layout = new QVBoxLayout(this);
  note_ = new QLabel(this);
  note_->setObjectName(QStringLiteral("scene_panel_note"));
  note_->setWordWrap(true);
  note_->setStyleSheet(
      QStringLiteral("QLabel { color: white; background: #0072B2; padding: 4px; }"));
  note_->hide();
  layout->addWidget(note_);
  groups_ = {make_motion_group(), make_plane_group(), make_camera_group()};
  for (QWidget* group : groups_) layout->addWidget(group);
  layout->addStretch(1);
  // The scene at time 0 changes with its source only, not with the frame: syncing on every
  // frame would rewrite a number the user is typing while the motion plays.
  connect(model_, &SceneModel::source_changed, this, &SceneControls::sync_from_model);
  connect(model_, &SceneModel::scene_rejected, this, &SceneControls::sync_from_model);
  sync_from_model();
}

void SceneControls::set_note(const QString& note) {
  note_->setText(note);
  note_->setVisible(!note.isEmpty());
  for (QWidget* group : groups_) group->setEnabled(note.isEmpty());
}

QString SceneControls::note() const { return note_->text(); }

SliderSpin* SceneControls::add_control(QWidget* group, const QString& name, const QString& label,
                                       const QString& what, const Range& range,
                                       std::function<double(const PlaneScene&)> get,
                                       std::function<void(PlaneScene&, double)> set) {
  auto* widget = new SliderSpin(label, range.minimum, range.maximum, range.step, range.decimals,
                                range.suffix, group);
  widget->setObjectName(name);
  widget->set_description(what);
  group->layout()->addWidget(widget);
  bindings_.push_back({widget, get, set});
  const Limit* limit = range.limit;
  connect(widget, &SliderSpin::edited, this, [this, set, label, limit](double v) {
    if (limit && !limit->allows(v)) {  // a value only this control has: its limit is here
      emit refused(tr("%1: %2").arg(label, QString::fromStdString(limit->problem(v))));
      sync_from_model();
      return;
    }
    propose([&](PlaneScene& s) { set(s, v); });
  });
  return widget;
}

QWidget* SceneControls::make_motion_group() {
  auto* group = new QGroupBox(tr("Motion (per second)"), this);
  new QVBoxLayout(group);
  const char* axes[3] = {"x", "y", "z"};
  const char* directions[3] = {"x (right)", "y (down)", "z (away from the eye)"};
  for (int i = 0; i < 3; ++i) {
    add_control(
        group, QStringLiteral("velocity_%1").arg(axes[i]), QStringLiteral("V %1").arg(axes[i]),
        tr("Velocity V of the plane along the camera's %1 axis").arg(directions[i]),
        {-3.0, 3.0, 0.01, 2, tr(" u/s")}, [i](const PlaneScene& s) { return s.motion.velocity[i]; },
        [i](PlaneScene& s, double v) { s.motion.velocity[i] = v; });
  }
  for (int i = 0; i < 3; ++i) {
    add_control(
        group, QStringLiteral("omega_%1").arg(axes[i]), QStringLiteral("Omega %1").arg(axes[i]),
        tr("Angular velocity Omega of the plane about the camera's %1 axis").arg(directions[i]),
        {-3.0, 3.0, 0.01, 2, tr(" rad/s")}, [i](const PlaneScene& s) { return s.motion.omega[i]; },
        [i](PlaneScene& s, double v) { s.motion.omega[i] = v; });
  }
  model_box_ = new QComboBox(group);
  model_box_->setObjectName(QStringLiteral("motion_model"));
  model_box_->addItem(tr("Screw (exact constant V, Omega)"), int(MotionModel::kScrew));
  model_box_->addItem(tr("Rotate, then translate"), int(MotionModel::kRotateThenTranslate));
  model_box_->addItem(tr("Spin about the plane centre (V = V_c)"),
                      int(MotionModel::kSpinAboutCentre));
  model_box_->setToolTip(tr("How V and Omega move the plane over time"));
  group->layout()->addWidget(model_box_);
  connect(model_box_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this](int) {
    const auto model = static_cast<MotionModel>(model_box_->currentData().toInt());
    propose([model](PlaneScene& s) { s.motion.model = model; });
  });
  return group;
}

QWidget* SceneControls::make_plane_group() {
  auto* group = new QGroupBox(tr("Plane"), this);
  new QVBoxLayout(group);
  add_control(
      group, QStringLiteral("turn"), tr("Turn"),
      tr("Turn of the plane's normal about the vertical axis at frame 0 (0 faces the eye)"),
      {-180.0, 180.0, 0.5, 1, tr(" deg"), &limits::kTurn},
      [](const PlaneScene& s) { return orientation_of(s.pose.normal).turn_deg; },
      [](PlaneScene& s, double v) {
        PlaneOrientation o = orientation_of(s.pose.normal);
        o.turn_deg = v;
        s.pose.normal = normal_of(o);
      });
  add_control(
      group, QStringLiteral("tilt"), tr("Tilt"),
      tr("Tilt of the plane's normal up or down at frame 0 (0 faces the eye)"),
      {-90.0, 90.0, 0.5, 1, tr(" deg"), &limits::kTilt},
      [](const PlaneScene& s) { return orientation_of(s.pose.normal).tilt_deg; },
      [](PlaneScene& s, double v) {
        PlaneOrientation o = orientation_of(s.pose.normal);
        o.tilt_deg = v;
        s.pose.normal = normal_of(o);
      });
  add_control(
      group, QStringLiteral("distance"), tr("Distance"),
      tr("Depth Z of the plane's centre in front of the eye at frame 0"),
      {0.05, 30.0, 0.05, 2, tr(" u")}, [](const PlaneScene& s) { return s.pose.point.z; },
      [](PlaneScene& s, double v) { s.pose = with_centre_depth(s.pose, v); });
  return group;
}

QWidget* SceneControls::make_camera_group() {
  auto* group = new QGroupBox(tr("Camera"), this);
  new QVBoxLayout(group);
  add_control(
      group, QStringLiteral("focal"), tr("Focal"),
      tr("Focal length of the camera: larger zooms in"), {10.0, 3000.0, 10.0, 0, tr(" px")},
      [](const PlaneScene& s) { return s.camera.focal_px; },
      [](PlaneScene& s, double v) { s.camera.focal_px = v; });
  return group;
}

SliderSpin* SceneControls::control(const QString& name) const {
  for (const Binding& b : bindings_) {
    if (b.widget->objectName() == name) return b.widget;
  }
  return nullptr;
}

void SceneControls::propose(const std::function<void(PlaneScene&)>& change) {
  PlaneScene candidate = model_->scene();
  change(candidate);
  model_->set_scene(candidate);  // on rejection the model emits scene_rejected -> sync
}

void SceneControls::sync_from_model() {
  const PlaneScene& scene = model_->scene();
  for (const Binding& b : bindings_) b.widget->set_value(b.get(scene));
  const QSignalBlocker block(model_box_);
  model_box_->setCurrentIndex(model_box_->findData(int(scene.motion.model)));
}

}  // namespace oflab
