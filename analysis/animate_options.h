// Options shared by both forms of `oflab-cli animate` (one plane, analysis/animate_command.cpp;
// a scene, analysis/animate_scene.cpp).
#pragma once

#include <string>

#include "analysis/cli_args.h"
#include "core/engine.h"

namespace oflab {

// --mode, --threshold / --thresholds, --delta, --sampling. Throws UsageError naming the
// option for a bad value.
EngineSettings read_engine_settings(const CliArgs& args);

// Creates DIR, or accepts an existing empty one; a non-empty DIR needs `force`. Throws
// UsageError naming --out.
void prepare_out_dir(const std::string& dir, bool force);

}  // namespace oflab
