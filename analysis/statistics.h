// Small statistics shared by the runs and reports of analysis/.
#pragma once

#include <vector>

namespace oflab {

// Median of the finite values of `values` (NaN and infinities are left out; the mean of
// the two middle values for an even count); NaN when there is none.
double median_of(std::vector<double> values);

}  // namespace oflab
