#include "flow/limits.h"

#include <cmath>
#include <sstream>

namespace oflab {
namespace {

std::string number_text(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

}  // namespace

bool Limit::allows(double value) const {
  if (!std::isfinite(value) || value < minimum || value > maximum) return false;
  return !whole || value == std::floor(value);
}

std::string Limit::range_text() const {
  std::string text = number_text(minimum) + ".." + number_text(maximum);
  if (unit[0] != '\0') text += std::string(" ") + unit;
  return text;
}

std::string Limit::problem(double value) const {
  if (allows(value)) return "";
  if (!std::isfinite(value)) return number_text(value) + " is not a finite number";
  if (value < minimum || value > maximum) {
    return number_text(value) + " is outside " + range_text();
  }
  return number_text(value) + " is not a whole number (" + range_text() + ")";
}

}  // namespace oflab
