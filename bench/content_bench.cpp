// Content cases of oflab-bench (see content_bench.h).
#include "content_bench.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "content/layer_content.h"
#include "engine/engine.h"
#include "flow/motion.h"
#include "image/warp.h"

namespace oflab::bench {
namespace {

using Clock = std::chrono::steady_clock;

double ms_between(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

void run_case(benchmark::State& state, ContentKind kind) {
  const Camera camera = make_camera(500.0, 640, 480);
  PlanePose pose;
  pose.point = Vec3(0.0, 0.0, 4.0);
  pose.size = Vec2(2.0, 1.5);
  pose.texture_size = glm::ivec2(256, 192);
  const Mat3 turn = rotation_matrix(Vec3(0.0, 30.0 * M_PI / 180.0, 0.0));
  pose.normal = turn * pose.normal;
  pose.up = turn * pose.up;
  Image texels(256, 192);
  for (int y = 0; y < 192; ++y) {
    for (int x = 0; x < 256; ++x) texels.at(x, y) = Pixel{uint8_t(x), uint8_t(y), 90, 255};
  }
  const Layer texture = make_layer(std::move(texels));
  const Mat3 exact = exact_texture_warp(camera, pose);
  const ConvexPolygon region = transform(texture.polygon, exact);
  const LayerContent content{kind, 4, Vec3(-0.4, -0.6, -1.0)};
  WarpedLayer rendered, warped;
  std::vector<double> render_ms, warp_ms;
  double units = 0.0, pixels = 0.0;
  for (auto _ : state) {
    const auto t0 = Clock::now();
    const ContentStats s = render_content(content, camera, pose, texture.polygon, region, rendered);
    const auto t1 = Clock::now();
    warp_layer_reusing(texture, exact, warped);
    const auto t2 = Clock::now();
    benchmark::DoNotOptimize(rendered.layer.image.pixels().data());
    benchmark::DoNotOptimize(warped.layer.image.pixels().data());
    render_ms.push_back(ms_between(t0, t1));
    warp_ms.push_back(ms_between(t1, t2));
    units = static_cast<double>(s.work_units);
    pixels = static_cast<double>(warped.stats.pixels_written);
    state.SetIterationTime(1e-3 * ms_between(t0, t1));
  }
  const double unit_ns = 1e6 * median(render_ms) / std::max(1.0, units);
  const double warp_ns = 1e6 * median(warp_ms) / std::max(1.0, pixels);
  state.counters["render_ms"] = median(render_ms);
  state.counters["warp_ms"] = median(warp_ms);
  state.counters["unit_ns"] = unit_ns;
  state.counters["warp_ns"] = warp_ns;
  state.counters["unit_cost"] = warp_ns > 0.0 ? unit_ns / warp_ns : 0.0;
}

}  // namespace

void register_content_cases(int repetitions) {
  for (ContentKind kind : {ContentKind::kShaded, ContentKind::kImpostor}) {
    const std::string name = std::string("content/") + content_name(kind) + "/cost-per-unit";
    benchmark::RegisterBenchmark(name.c_str(),
                                 [kind](benchmark::State& state) { run_case(state, kind); })
        ->UseManualTime()
        ->Repetitions(repetitions)
        ->ReportAggregatesOnly(true)
        ->Unit(benchmark::kMillisecond);
  }
}

}  // namespace oflab::bench
