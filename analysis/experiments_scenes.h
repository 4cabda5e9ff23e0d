// Experiment 2 (dissertation sections 6.6 and 6.7): many planes, moving viewer.
#pragma once

#include "analysis/experiments.h"

namespace oflab {

// The report section of Experiment 2.
ReportSection experiment2_section(ExperimentContext& context);

}  // namespace oflab
