#include "runs/statistics.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace oflab {

double median_of(std::vector<double> values) {
  values.erase(
      std::remove_if(values.begin(), values.end(), [](double v) { return !std::isfinite(v); }),
      values.end());
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double percent(long part, long whole) { return whole ? 100.0 * part / whole : 0.0; }

}  // namespace oflab
