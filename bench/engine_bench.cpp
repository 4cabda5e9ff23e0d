// Engine cases of oflab-bench (see engine_bench.h).
#include "engine_bench.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <exception>
#include <string>
#include <vector>

#include "engine/engine.h"
#include "engine/reuse_policy.h"
#include "formats/datasets.h"
#include "formats/image_io.h"
#include "formats/script_file.h"
#include "image/warp.h"

namespace oflab::bench {
namespace {

constexpr const char* kScripts[] = {"rotation", "translation-1", "zoom"};

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

// Per-frame figures of the passes so far (frames after the first).
struct Samples {
  std::vector<double> engine_ms, kernel_ms;
  double engine_px = 0.0, kernel_px = 0.0;
};

// One pass: the engine over the script, the bare kernel drawing each frame's exact warp
// right after the engine's frame. Returns the engine's timed milliseconds of the pass.
double play_pass(const MotionScript& script, const Layer& texture, const EngineSettings& settings,
                 Image& frame, Samples* samples) {
  PlaneEngine engine(script.camera, texture, settings);
  double total_ms = engine.start(script.frames[0].pose).time_ms;
  WarpOptions options;
  options.sampling = settings.sampling;
  for (std::size_t k = 1; k < script.frames.size(); ++k) {
    const ScriptFrame& previous = script.frames[k - 1];
    const FrameReport r = engine.advance(previous.pose, previous.motion, script.frames[k].pose);
    total_ms += r.time_ms;
    PlanePose pose = script.frames[k].pose;
    pose.texture_size = glm::ivec2(texture.image.width(), texture.image.height());
    const Mat3 exact = exact_texture_warp(script.camera, pose);
    const auto t0 = std::chrono::steady_clock::now();
    const WarpStats stats = warp_layer_into(texture, exact, frame, 0, 0, options);
    const auto t1 = std::chrono::steady_clock::now();
    benchmark::DoNotOptimize(frame.pixels().data());
    if (!samples) continue;
    samples->engine_ms.push_back(r.time_ms);
    samples->kernel_ms.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    samples->engine_px += static_cast<double>(r.pixels_written);
    samples->kernel_px += static_cast<double>(stats.pixels_written);
  }
  return total_ms;
}

void run_case(benchmark::State& state, const std::string& script_name, const ReusePolicy* policy) {
  MotionScript script;
  Layer texture;
  try {
    script = read_script_file(resolve_script_path(script_name));
    texture = make_layer(read_image(default_texture_path()));
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());
    return;
  }
  EngineSettings settings;
  settings.policy = policy;
  Image frame(script.camera.width, script.camera.height);
  play_pass(script, texture, settings, frame, nullptr);  // warm-up, untimed
  Samples samples;
  for (auto _ : state) {
    state.SetIterationTime(1e-3 * play_pass(script, texture, settings, frame, &samples));
  }
  const double n = static_cast<double>(std::max<std::size_t>(1, samples.engine_ms.size()));
  const double frame_ms = median(samples.engine_ms), kernel_ms = median(samples.kernel_ms);
  state.counters["frame_ms"] = frame_ms;
  state.counters["kernel_ms"] = kernel_ms;
  state.counters["engine/kernel"] = kernel_ms > 0.0 ? frame_ms / kernel_ms : 0.0;
  state.counters["engine_px"] = samples.engine_px / n;
  state.counters["kernel_px"] = samples.kernel_px / n;
}

}  // namespace

void register_engine_cases(int repetitions) {
  for (const char* script : kScripts) {
    for (const ReusePolicy& policy : reuse_policies()) {
      const std::string name = std::string("engine/") + script + "/" + policy.name;
      benchmark::RegisterBenchmark(
          name.c_str(), [script = std::string(script),
                         p = &policy](benchmark::State& state) { run_case(state, script, p); })
          ->UseManualTime()
          ->Repetitions(repetitions)
          ->ReportAggregatesOnly(true)
          ->Unit(benchmark::kMillisecond);
    }
  }
}

}  // namespace oflab::bench
