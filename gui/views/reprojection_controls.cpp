#include "views/reprojection_controls.h"

#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QMenu>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QWidgetAction>

#include "flow/limits.h"
#include "views/number_box.h"

namespace oflab {
namespace {

// "every frame", "every 2nd frame", "every 3rd frame", "every 4th frame", ...
QString cadence_text(int cadence) {
  if (cadence <= 1) return QObject::tr("every frame");
  const char* suffix = cadence == 2 ? "nd" : cadence == 3 ? "rd" : "th";
  return QObject::tr("every %1%2 frame").arg(cadence).arg(QString::fromLatin1(suffix));
}

QString vector_text(const Vec3& v) {
  return QStringLiteral("(%1, %2, %3)").arg(v.x, 0, 'g', 4).arg(v.y, 0, 'g', 4).arg(v.z, 0, 'g', 4);
}

}  // namespace

ReprojectionControls::ReprojectionControls(QWidget* parent) : QToolButton(parent) {
  setObjectName(QStringLiteral("animation_reprojection"));
  setPopupMode(QToolButton::InstantPopup);
  auto* menu = new QMenu(this);
  auto* form_widget = new QWidget(menu);
  auto* form = new QFormLayout(form_widget);
  cadence_box_ = new QSpinBox(form_widget);
  cadence_box_->setObjectName(QStringLiteral("animation_cadence"));
  // Any whole number can be typed; the model refuses one outside limits::kCadence.
  cadence_box_->setRange(0, 1000);
  cadence_box_->setKeyboardTracking(false);
  cadence_box_->setSuffix(tr(" frames"));
  cadence_box_->setToolTip(tr("Render every N-th frame and warp the frames between (%1)")
                               .arg(QString::fromStdString(limits::kCadence.range_text())));
  form->addRow(tr("Render every"), cadence_box_);
  plane_box_ = new QComboBox(form_widget);
  plane_box_->setObjectName(QStringLiteral("animation_stabilization"));
  plane_box_->addItem(tr("automatic fit to the visible depth"), true);
  plane_box_->addItem(tr("a point and a normal"), false);
  plane_box_->setToolTip(
      tr("The stabilized-plane policy's plane: the least-squares fit of the visible inverse "
         "depth at each render, or a plane given in world coordinates"));
  form->addRow(tr("Stabilization plane"), plane_box_);
  const auto vector_row = [&](NumberBox*(&boxes)[3], const QString& name, const QString& label) {
    auto* row = new QWidget(form_widget);
    auto* layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    for (int k = 0; k < 3; ++k) {
      boxes[k] = new NumberBox(-100.0, 100.0, row);
      boxes[k]->setObjectName(QStringLiteral("animation_stabilization_%1_%2").arg(name).arg(k));
      boxes[k]->setDecimals(3);
      boxes[k]->setSingleStep(0.5);
      boxes[k]->setToolTip(
          tr("The %1's %2 of the given stabilization plane (%3)")
              .arg(name)
              .arg(QChar(char16_t(u'x' + k)))
              .arg(QString::fromStdString(limits::kStabilizationPlane.range_text())));
      layout->addWidget(boxes[k]);
      connect(boxes[k], QOverload<double>::of(&QDoubleSpinBox::valueChanged), this,
              [this] { emit edited(); });
    }
    form->addRow(label, row);
  };
  vector_row(point_, QStringLiteral("point"), tr("Point (world units)"));
  vector_row(normal_, QStringLiteral("normal"), tr("Normal"));
  auto* action = new QWidgetAction(menu);
  action->setDefaultWidget(form_widget);
  menu->addAction(action);
  setMenu(menu);
  connect(cadence_box_, QOverload<int>::of(&QSpinBox::valueChanged), this,
          [this] { emit edited(); });
  connect(plane_box_, QOverload<int>::of(&QComboBox::activated), this, [this] {
    show_plane_fields();
    emit edited();
  });
  show_settings(EngineSettings{});
}

void ReprojectionControls::read_into(EngineSettings& settings) const {
  settings.cadence = cadence_box_->value();
  settings.stabilization.automatic = plane_box_->currentData().toBool();
  for (int k = 0; k < 3; ++k) {
    settings.stabilization.point[k] = point_[k]->value();
    settings.stabilization.normal[k] = normal_[k]->value();
  }
}

void ReprojectionControls::show_settings(const EngineSettings& settings) {
  const QSignalBlocker b0(cadence_box_), b1(plane_box_);
  cadence_box_->setValue(settings.cadence);
  plane_box_->setCurrentIndex(settings.stabilization.automatic ? 0 : 1);
  for (int k = 0; k < 3; ++k) {
    const QSignalBlocker b2(point_[k]), b3(normal_[k]);
    point_[k]->setValue(settings.stabilization.point[k]);
    normal_[k]->setValue(settings.stabilization.normal[k]);
  }
  show_plane_fields();
  setText(tr("Reprojection"));
  setToolTip(summary(settings));
}

void ReprojectionControls::show_plane_fields() {
  const bool given = !plane_box_->currentData().toBool();
  for (int k = 0; k < 3; ++k) {
    point_[k]->setEnabled(given);
    normal_[k]->setEnabled(given);
  }
}

QString ReprojectionControls::summary(const EngineSettings& settings) {
  return tr("Today's reprojection policies (timewarp, stabilized-plane, depth-reprojection, "
            "cadence) render %1 and warp the frames between; the stabilized-plane policy's %2")
      .arg(cadence_text(settings.cadence), plane_text(settings.stabilization));
}

QString ReprojectionControls::plane_text(const StabilizationPlane& plane) {
  return plane.automatic ? tr("plane: automatic fit to the depth")
                         : tr("plane through %1, normal %2")
                               .arg(vector_text(plane.point), vector_text(plane.normal));
}

}  // namespace oflab
