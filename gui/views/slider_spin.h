// A labelled slider with a numeric spin box showing the same value: drag for a quick
// change, type for an exact one. Only user edits emit `edited`; set_value is silent, so
// the scene can push values back (for instance after rejecting an impossible one).
#pragma once

#include <QWidget>

class QDoubleSpinBox;
class QSlider;

namespace oflab {

class SliderSpin : public QWidget {
  Q_OBJECT

 public:
  // The slider spans `minimum` to `maximum` in steps of `step`; the field shows the value
  // with `decimals` decimals and the unit `suffix` (e.g. " rad/s") and takes any number typed
  // (views/number_box.h): the model checks it against its limit, and a value beyond the
  // slider's span is shown in the field with the slider at its end.
  SliderSpin(const QString& label, double minimum, double maximum, double step, int decimals,
             const QString& suffix, QWidget* parent = nullptr);

  double value() const;
  // Emits nothing. A value equal to the shown one (to the shown decimals) leaves the field
  // alone, so a number being typed survives the scene pushing its values back every frame.
  void set_value(double value);
  // The tooltip of the label, slider and field: what the value means; the unit is added.
  void set_description(const QString& what);
  QDoubleSpinBox* spin_box() const { return spin_; }
  QSlider* slider() const { return slider_; }

 signals:
  void edited(double value);

 private:
  int slider_position(double value) const;

  QSlider* slider_;
  QDoubleSpinBox* spin_;
  double minimum_, step_;
  QString suffix_;
};

}  // namespace oflab
