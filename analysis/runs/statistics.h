// Small statistics shared by the runs and reports of analysis/.
#pragma once

#include <vector>

namespace oflab {

// Median of the finite values of `values` (NaN and infinities are left out; the mean of
// the two middle values for an even count); NaN when there is none.
double median_of(std::vector<double> values);

// 100 * part / whole; 0 when whole is 0.
double percent(long part, long whole);

}  // namespace oflab
