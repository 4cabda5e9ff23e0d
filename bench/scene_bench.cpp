// Scene cases of oflab-bench (see scene_bench.h).
#include "scene_bench.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include "engine/reuse_policy.h"
#include "formats/scene_file.h"
#include "formats/viewer_script_file.h"
#include "image/thread_pool.h"
#include "scene/scene_animator.h"

namespace oflab::bench {
namespace {

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

// The four runs of one pass: engine and re-render, each on 1 and on 2 threads.
constexpr int kRuns = 4;
constexpr std::array<int, kRuns> kThreads = {1, 1, 2, 2};
constexpr std::array<bool, kRuns> kRerender = {false, true, false, true};

// A scene, a viewer script and the engine's policy, timed against the exact re-render.
struct SceneCase {
  const char* name;
  const char* scene;
  const char* viewer;
  const char* policy;
};

// The street walked under optic flow (the engine of chapter 6), and the four cubes passed
// under depth reprojection (each pixel splatted by its own depth: the holes lesson).
constexpr std::array<SceneCase, 2> kCases = {
    SceneCase{"scene/street/walk/threads", "street", "walk", "perspective"},
    SceneCase{"scene/four-cubes/translate/depth-reprojection/threads", "four-cubes", "translate",
              "depth-reprojection"}};

// One pass over the viewer script; appends each run's frame times (after frame 0) to `ms`.
void play_pass(const SceneCase& c, const std::shared_ptr<const Scene>& scene,
               const ViewerScript& walk, std::array<std::vector<double>, kRuns>& ms) {
  std::array<std::unique_ptr<SceneScriptAnimator>, kRuns> runs;
  for (int r = 0; r < kRuns; ++r) {
    SceneSettings settings;
    settings.engine.policy = &reuse_policy(kRerender[r] ? "rerender" : c.policy);
    // The scene's own content detail, as `oflab-cli animate --scene street` plays it.
    settings.engine.content.quality =
        scene_content_quality(*scene, settings.engine.content.quality);
    runs[r] = make_scene_animator(scene, walk, settings);
  }
  // Blocks of frames in turn, so that the thread counts meet the same load: the pool is
  // resized between blocks, not between frames (a worker just made starts cold).
  constexpr std::size_t kBlock = 10;
  for (std::size_t first = 0; first < walk.frames.size(); first += kBlock) {
    const std::size_t last = std::min(first + kBlock, walk.frames.size());
    for (int r = 0; r < kRuns; ++r) {
      if (r == 0 || kThreads[r] != kThreads[r - 1]) set_worker_threads(kThreads[r]);
      for (std::size_t frame = first; frame < last; ++frame) {
        const AnimationFrame f = frame == 0 ? runs[r]->start() : runs[r]->advance();
        benchmark::DoNotOptimize(runs[r]->image().pixels().data());
        if (frame > 0) ms[r].push_back(f.time_ms);
      }
    }
  }
  set_worker_threads(1);
}

void run_case(benchmark::State& state, const SceneCase& c) {
  std::shared_ptr<const Scene> scene;
  ViewerScript walk;
  try {
    scene = std::make_shared<const Scene>(read_scene_file(resolve_scene_path(c.scene)));
    walk = read_viewer_script_file(resolve_viewer_script_path(c.viewer));
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  std::array<std::vector<double>, kRuns> ms;
  for (auto _ : state) {
    const std::size_t before = ms[2].size();
    play_pass(c, scene, walk, ms);
    double engine_2t = 0.0;
    for (std::size_t k = before; k < ms[2].size(); ++k) engine_2t += ms[2][k];
    state.SetIterationTime(1e-3 * engine_2t);
  }
  std::array<double, kRuns> m{};
  for (int r = 0; r < kRuns; ++r) m[r] = median(ms[r]);
  const auto ratio = [](double a, double b) { return b > 0.0 ? a / b : 0.0; };
  state.counters["engine_1t_ms"] = m[0];
  state.counters["rerender_1t_ms"] = m[1];
  state.counters["engine_2t_ms"] = m[2];
  state.counters["rerender_2t_ms"] = m[3];
  state.counters["engine_scaling"] = ratio(m[0], m[2]);
  state.counters["rerender_scaling"] = ratio(m[1], m[3]);
  state.counters["engine/rerender_1t"] = ratio(m[0], m[1]);
  state.counters["engine/rerender_2t"] = ratio(m[2], m[3]);
}

}  // namespace

void register_scene_cases(int repetitions) {
  for (const SceneCase& c : kCases) {
    benchmark::RegisterBenchmark(c.name, [&c](benchmark::State& state) { run_case(state, c); })
        ->UseManualTime()
        ->Iterations(1)
        ->Repetitions(repetitions)
        ->ReportAggregatesOnly(repetitions > 1)
        ->Unit(benchmark::kMillisecond);
  }
}

}  // namespace oflab::bench
