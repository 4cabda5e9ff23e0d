// `oflab-cli animate --scene NAME|FILE --script NAME|FILE --mode scene-shifting
// [--epsilon E]`: the scene-shifting renderer (core/scene_shifting/scene_shifting_renderer.h) with
// the same summary, JSON and CSV as the other scene modes (manual/scene-shifting.md).
#pragma once

#include <iosfwd>

#include "cli/cli_args.h"

namespace oflab {

// Returns the exit code: 0, or 2 for bad input (one line on `err` naming the option or the
// file). Throws UsageError for bad options (the caller prints it).
int animate_scene_shifting(const CliArgs& args, std::ostream& out, std::ostream& err);

}  // namespace oflab
