#include "views/number_box.h"

namespace oflab {

NumberBox::NumberBox(double usual_minimum, double usual_maximum, QWidget* parent)
    : QDoubleSpinBox(parent), usual_minimum_(usual_minimum), usual_maximum_(usual_maximum) {
  setRange(-kEntryLimit, kEntryLimit);
  setKeyboardTracking(false);
}

QSize NumberBox::sizeHint() const {
  // The size a field of the usual range would ask for, in this field's font and format.
  QDoubleSpinBox probe;
  probe.setFont(font());
  probe.setStyle(style());
  probe.setDecimals(decimals());
  probe.setPrefix(prefix());
  probe.setSuffix(suffix());
  probe.setRange(usual_minimum_, usual_maximum_);
  return probe.sizeHint();
}

QSize NumberBox::minimumSizeHint() const { return sizeHint(); }

}  // namespace oflab
