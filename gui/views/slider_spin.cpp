#include "views/slider_spin.h"

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSlider>
#include <cmath>

#include "views/number_box.h"

namespace oflab {

SliderSpin::SliderSpin(const QString& label, double minimum, double maximum, double step,
                       int decimals, const QString& suffix, QWidget* parent)
    : QWidget(parent), minimum_(minimum), step_(step), suffix_(suffix.trimmed()) {
  auto* row = new QHBoxLayout(this);
  row->setContentsMargins(0, 0, 0, 0);
  auto* name = new QLabel(label, this);
  name->setMinimumWidth(70);
  slider_ = new QSlider(Qt::Horizontal, this);
  slider_->setRange(0, slider_position(maximum));
  slider_->setMinimumWidth(110);
  // Any number can be typed: the model refuses one outside its limit with a message.
  spin_ = new NumberBox(minimum, maximum, this);
  spin_->setSingleStep(step);
  spin_->setDecimals(decimals);
  spin_->setSuffix(suffix);
  spin_->setMinimumWidth(105);
  row->addWidget(name);
  row->addWidget(slider_, 1);
  row->addWidget(spin_);
  connect(slider_, &QSlider::valueChanged, this, [this](int position) {
    const double v = minimum_ + position * step_;
    const QSignalBlocker block(spin_);
    spin_->setValue(v);
    emit edited(v);
  });
  connect(spin_, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, [this](double v) {
    const QSignalBlocker block(slider_);
    slider_->setValue(slider_position(v));  // a value beyond the slider's span pegs it at an end
    emit edited(v);
  });
}

int SliderSpin::slider_position(double value) const {
  return static_cast<int>(std::lround((value - minimum_) / step_));
}

double SliderSpin::value() const { return spin_->value(); }

void SliderSpin::set_value(double value) {
  if (std::abs(spin_->value() - value) < 0.5 * std::pow(10.0, -spin_->decimals())) return;
  const QSignalBlocker b1(slider_), b2(spin_);
  spin_->setValue(value);
  slider_->setValue(slider_position(value));
}

void SliderSpin::set_description(const QString& what) {
  const QString tip = suffix_.isEmpty() ? what : tr("%1, in %2").arg(what, suffix_);
  setToolTip(tip);
  for (QWidget* part : findChildren<QWidget*>(QString(), Qt::FindDirectChildrenOnly)) {
    part->setToolTip(tip);
  }
}

}  // namespace oflab
