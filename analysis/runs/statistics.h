// Small statistics shared by the runs and reports of analysis/.
#pragma once

#include <cstdint>
#include <vector>

namespace oflab {

// Median of the finite values of `values` (NaN and infinities are left out; the mean of
// the two middle values for an even count); NaN when there is none.
double median_of(std::vector<double> values);

// 100 * part / whole; 0 when whole is 0.
double percent(long part, long whole);

// The nearest-rank `percent` percentile of `values` (0 < percent <= 100): sorted ascending,
// the value of rank ceil(percent / 100 x n) (1-based), that is the smallest value that at
// least `percent` percent of the values do not exceed. 0 for no values.
std::int64_t nearest_rank_percentile(std::vector<std::int64_t> values, double percent);

}  // namespace oflab
