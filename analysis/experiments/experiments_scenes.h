// Experiment 2 (dissertation sections 6.6 and 6.7): many planes, moving viewer. The scene
// animator (core/scene/scene_animator.h) plays the shipped scenes (datasets/scenes, Fig. 25) with
// the compound viewer script of section 6.7.1 (datasets/viewer-scripts/compound.json);
// analysis/runs/run_driver.h times, frame by frame in the same run, the exact re-render of every
// visible polygon and the conventional VTK renderer (analysis/runs/vtk_scene_renderer.h).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "experiments/experiments.h"
#include "runs/source_kinds.h"

namespace oflab {

struct Experiment2Spec {
  int max_frames = -1;          // frames of the compound script (-1: all 401)
  int repetitions = 5;          // timings are per-frame medians over these
  std::vector<int> grid_cubes;  // the scale generator's sizes (analysis/generators/cube_grid.h)
  int grid_max_frames = -1;
  int grid_repetitions = 3;
  int conventional_repetitions = 1;  // of those, how many also time the VTK renderer
  int grid_conventional_repetitions = 1;
};
// Full: the whole compound script, 5 repetitions (the first with the VTK renderer); grids
// of 1, 2, 4, 9, 16 and 25 cubes (5 to 125 polygons), 3 repetitions (the first with VTK).
// Quick: 80 frames, 1 repetition; grids of 1, 4 and 9 cubes over 40 frames without VTK.
Experiment2Spec experiment2_spec(bool quick);

// One scene played with one setting: the first repetition's reports, and per frame the
// median time over the repetitions of the engine, the exact re-render and VTK.
struct SceneMeasurement {
  std::string scene;
  int polygons = 0;
  AnimationRun run;
  std::vector<double> engine_ms;
  std::vector<double> rerender_ms;
  std::vector<double> conventional_ms;
  double mean_engine_ms() const;
  double mean_rerender_ms() const;
  double mean_conventional_ms() const;
};

struct Experiment2Result {
  Experiment2Spec spec;
  SceneMeasurement four_cubes;           // every polygon in the frustum updated (as 6.7.3)
  SceneMeasurement four_cubes_skipping;  // oflab's default: hidden polygons not updated
  std::vector<SceneMeasurement> small;   // 1, 2 and 5 polygons (6.7.1, 6.7.2)
  std::vector<SceneMeasurement> grid;    // time against polygon count
};

// Needs an X display (the conventional renderer). Throws what the scene kind's play throws.
Experiment2Result run_experiment2(const Experiment2Spec& spec,
                                  const std::function<void(const std::string&)>& progress);

ReportSection experiment2_section(const Experiment2Result& result, ExperimentContext& context);

}  // namespace oflab
