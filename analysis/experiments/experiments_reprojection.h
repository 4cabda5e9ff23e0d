// Today's reprojection beside optic flow (beyond the dissertation; manual/policies.md
// "Today's reprojection"): timewarp, one stabilization plane, per-pixel depth, frame generation
// along motion vectors and the plane per layer on a fixed cadence, with optic flow's threshold rule
// (`perspective`) for reference, on every Experiment 2 scene under each of its viewer scripts
// (translate, zoom, rotate), on the street and on the city block: measured error, hole pixels,
// work, latency; a chart of error against work; the vendors' published figures quoted as theirs.
// Beside them the dissertation's named rivals: Talisman and Shade et al.'s hierarchical image
// cache, with the cache's nodes, renders by cause, seams and per-pixel error in a table of their
// own.
#pragma once

#include <string>
#include <vector>

#include "experiments/experiments.h"
#include "runs/policy_runs.h"

namespace oflab {

struct ReprojectionSpec {
  int max_frames = 40;  // per source (the first frames of each viewer script)
  int cadence = 2;      // EngineSettings::cadence: spacewarp's half rate
  bool ssim = true;     // measure each frame's SSIM (RunOptions::measure_ssim); quick: false
};
// Full: 40 frames per source with SSIM; quick: 12 without. Both at cadence 2, one timed pass
// without warm-up (the figures reported are deterministic), so the whole section takes seconds.
ReprojectionSpec reprojection_spec(bool quick);

struct ReprojectionSource {
  std::string scene;
  std::string script;
  std::vector<PolicyRun> runs;  // one per policy of reprojection_policies(), in that order
};

struct ReprojectionResult {
  ReprojectionSpec spec;
  std::vector<ReprojectionSource> sources;
};

// The policies compared: timewarp, stabilized-plane, depth-reprojection, cadence, frame
// generation's mv-extrapolation with and without inpainting, perspective, and the
// dissertation's two named rivals, talisman and hierarchical-cache.
std::vector<const ReusePolicy*> reprojection_policies();

// The Experiment 2 scenes (single-1, two, five-collinear, four-cubes) under translate, zoom
// and rotate, then the street under walk and the city block under city-flyby. Throws what
// the readers and runs throw.
ReprojectionResult run_reprojection_experiment(
    const ReprojectionSpec& spec, const std::function<void(const std::string&)>& progress);

ReportSection reprojection_section(const ReprojectionResult& result, ExperimentContext& context);

}  // namespace oflab
