// The dissertation's published figures (chapter 6 and appendix A.2), as read from its
// text; manual/experiments.md says where each number comes from. Percentages are percent
// of frames (or of polygons), 0..100.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "engine/decision.h"
#include "flow/decomposition.h"

namespace oflab {

// Section 6.4.8: percent of frames per update level (none, translate, affine,
// perspective, re-render) and the time saved against re-rendering every frame.
struct PublishedScriptResult {
  std::string script;  // oflab's shipped script name ("translation-1")
  std::string title;   // the dissertation's row label ("2: Translation 1")
  std::array<double, kLevelCount> level_percent{};
  double time_saved_percent = 0.0;
};
const std::vector<PublishedScriptResult>& published_experiment1();
// nullptr when the script has no published row.
const PublishedScriptResult* published_experiment1_row(const std::string& script);

// Section 6.5.1: the loop script with affine warps only.
struct PublishedAffineLoop {
  std::array<double, kLevelCount> level_percent{};  // perspective is 0 by construction
  double time_vs_perspective = 0.0;  // "about one third of the time" of the full algorithm
};
const PublishedAffineLoop& published_affine_loop();

// Section 6.3 (Fig. 20): the Delta comparison was published as graphs and statements, not
// numbers; these are the statements, one per DeltaPolicy (fourth-root was not tried).
struct PublishedDeltaStatement {
  DeltaPolicy policy;
  std::string statement;
};
const std::vector<PublishedDeltaStatement>& published_delta_statements();

// Appendix A.2: milliseconds per warp on a 132 MHz R4600 Indy, point sampling.
struct PublishedWarpTiming {
  std::string size;    // "243x198"
  std::string matrix;  // "identity", "rot45", "M"
  double affine_ms = 0.0;
  double perspective_ms = 0.0;
};
const std::vector<PublishedWarpTiming>& published_warp_timings();

// Section 6.4.8: cost ratios the text gives.
constexpr double kPublishedPerspectiveOverAffine = 2.1;      // "approximately twice"
constexpr double kPublishedPerspectiveOverTranslate = 35.0;  // "approximately 35 times"

// Section 6.7.3: four cubes, compound script: percent of polygons per level.
const std::array<double, kLevelCount>& published_four_cubes_levels();

}  // namespace oflab
