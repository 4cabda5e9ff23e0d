// Runs a viewer script through a scene with the scene-shifting renderer
// (core/scene_shifting/scene_shifting_renderer.h) and, frame by frame in the same run, its exact baseline
// (every slice rebuilt every frame). The result takes the scene runs' form
// (analysis/runs/scene_run.h), so its CSV and JSON summary are those of the other modes.
#pragma once

#include <functional>
#include <vector>

#include "runs/scene_run.h"
#include "scene_shifting/scene_shifting_renderer.h"

namespace oflab {

struct SceneShiftingRunOptions {
  SceneShiftingSettings settings;          // design_speed 0: script_design_speed of the script
  int max_frames = -1;                     // at most this many frames (-1: the whole script)
  bool run_baseline = true;                // the exact baseline, for time, work and PSNR
  std::function<void(int, int)> progress;  // (frames done, total)
  std::function<void(int, const Image&)> on_frame;  // each composited frame
};

struct SceneShiftingRun {
  std::vector<Slice> slices;  // as cut at the first frame
  std::vector<SceneShiftingFrameReport> frames;
  // The same frames as a scene run: a polygon counts as "rerender" in a frame its layer was
  // rebuilt, "translate" when its layer was shifted, "affine" when scaled, "none" when still.
  SceneRun scene_run;
  int turning_frames = 0;              // frames whose step turned the viewing direction
  int turning_frames_all_rebuilt = 0;  // of those, the frames that rebuilt every occupied slice
  long rebuilt_layers = 0;             // over the frames after the first
  long shifted_layers = 0;             // shifted or scaled, over the frames after the first
  double design_speed = 0.0;           // the |V| the slices were cut for
};

// Throws std::invalid_argument for a scene scene shifting cannot draw (see
// SceneShiftingRenderer::start) or settings out of range.
SceneShiftingRun run_scene_shifting(const Scene& scene, const ViewerScript& script,
                                    const SceneShiftingRunOptions& options);

}  // namespace oflab
