// A number field that takes any number typed (magnitudes up to kEntryLimit), so a value
// outside its control's limit (core/flow/limits.h) reaches the model and is refused there
// with a banner naming the field, the value and the range, instead of being cut silently to
// the field's own range. It is sized for the numbers of its usual range, and applies a value
// when typing ends (Enter or focus change), not at every keystroke.
#pragma once

#include <QDoubleSpinBox>

namespace oflab {

class NumberBox : public QDoubleSpinBox {
 public:
  static constexpr double kEntryLimit = 1e9;

  // `usual_minimum` .. `usual_maximum`: the values the field is sized for (its arrows and
  // wheel step within the entry range).
  NumberBox(double usual_minimum, double usual_maximum, QWidget* parent = nullptr);

  QSize sizeHint() const override;
  QSize minimumSizeHint() const override;

 private:
  double usual_minimum_, usual_maximum_;
};

}  // namespace oflab
