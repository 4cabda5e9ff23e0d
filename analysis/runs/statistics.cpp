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

std::int64_t nearest_rank_percentile(std::vector<std::int64_t> values, double percent) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const double n = static_cast<double>(values.size());
  const auto rank = static_cast<std::size_t>(std::ceil(percent * n / 100.0));
  return values[std::clamp<std::size_t>(rank, 1, values.size()) - 1];
}

}  // namespace oflab
