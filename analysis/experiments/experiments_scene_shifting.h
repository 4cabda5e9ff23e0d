// Scene shifting against optic flow (dissertation chapter 3) on the train-window scene:
// the comparison behind `oflab-cli experiments --only scene-shifting`.
#pragma once

#include <string>
#include <vector>

#include "experiments/experiments.h"
#include "runs/source_kinds.h"

namespace oflab {

// One approach on one script: layer (or polygon) updates, work and error over the frames.
struct ApproachFigures {
  int frames = 0;
  long updates = 0;         // polygon-frames drawn at a level other than none
  long rerendered = 0;      // polygon-frames rendered again from the texture
  std::int64_t pixels = 0;  // written by the warp kernels
  double work_saved = 0.0;  // against the exact re-render of the same frames
  double max_measured_error_px = 0.0;
};

struct SceneShiftingComparison {
  std::string script;
  std::vector<Slice> slices;  // scene shifting's slices
  ApproachFigures scene_shifting;
  ApproachFigures optic_flow;  // the scene animator, mode perspective
  int turning_frames = 0;
  int turning_frames_all_rebuilt = 0;  // frames where scene shifting rebuilt every slice
};

// Runs scene shifting (epsilon_px) and the optic-flow engine (thresholds epsilon_px) on the
// same scene and script. Throws as the two kinds' play (analysis/runs/source_kinds.h).
SceneShiftingComparison compare_scene_shifting(const Scene& scene, const ViewerScript& script,
                                               double epsilon_px, int max_frames = -1);

// The report section: the train-window slices and the comparison for train-sideways and
// train-turning.
ReportSection scene_shifting_section(ExperimentContext& context);

}  // namespace oflab
