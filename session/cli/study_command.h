// `oflab-cli study`: threshold studies without a window, through the teaching layer
// (session/study/, manual/study.md).
//   study list                          every shipped study: name, method, trials, conditions
//   study simulate --study NAME|FILE --observer-threshold PX [--observer-slope S]
//         [--observer-lapse L] [--sessions N] [--seed S] [--method M|all] [--replicates B]
//         [--late-fraction F] [--shown engine|requested] [--json]
//                                       simulated observers through the real trial loop and
//                                       analysis: per condition and method the fraction of
//                                       sessions whose threshold is within 10 %, the 95 %
//                                       interval's coverage and the median trials
//   study session --study NAME|FILE --observer-threshold PX --csv FILE [--observer NAME]
//         [--method M] [--seed S] [--ppi P] [--force]
//                                       one simulated session (errors shown by the engine)
//                                       written as a per-trial CSV
//   study analyse CSV... [--replicates B] [--seed S] [--slope S] [--lapse L] [--json]
//                                       thresholds with 95 % intervals per observer, condition
//                                       and method; several observers add class rows
//   study ladder --study NAME|FILE [--json]
//                                       each condition's clip played at the ladder of
//                                       thresholds: the error the engine measured at each
// A study file or CSV that cannot be used is refused (exit 2) naming the file, the place and
// the limit.
#pragma once

#include <iosfwd>

#include "cli/commands.h"

namespace oflab {

// The command's entry for oflab-cli's table (cli/commands.h add_command).
Command study_command();

int run_study_command(const CommandArgs& args, std::ostream& out, std::ostream& err);

}  // namespace oflab
