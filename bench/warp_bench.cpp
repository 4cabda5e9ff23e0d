// oflab-bench: Google Benchmark timings of the warp kernels (manual/warping.md).
//
// Case names: warp/<kernel>/<sampling>/<size>/<matrix>, copy/<size>/<matrix> (memcpy of
// the same number of output bytes: the memory-bandwidth floor), when OpenCV is available
// opencv/<kernel>/<sampling>/<size>/<matrix>, when pixman is available
// pixman/<sampling>/<size>/<matrix>, and the engine cases of engine_bench.h
// (engine/<script>/<mode>), and mipmap-vs-bilinear/... (mipmap_bench.h). Every warp case reports
// aggregates over repetitions (median included) and a Mpx/s counter: output pixels inside the
// warped polygon per second. Everything runs on one thread. Usual Google Benchmark flags work, e.g.
// --benchmark_filter=1024x768 --benchmark_format=json.
#include <benchmark/benchmark.h>

#include <cstring>
#include <string>
#include <vector>

#include "content_bench.h"
#include "engine_bench.h"
#include "image/warp.h"
#include "mipmap_bench.h"
#include "scene_bench.h"
#include "warp_cases.h"
#ifdef OFLAB_BENCH_WITH_OPENCV
#include "opencv_peer.h"
#endif
#ifdef OFLAB_BENCH_WITH_PIXMAN
#include "pixman_peer.h"
#endif

namespace oflab::bench {
namespace {

constexpr int kRepetitions = 9;

void set_rate(benchmark::State& state, std::int64_t pixels) {
  state.counters["Mpx/s"] = benchmark::Counter(static_cast<double>(pixels) * 1e-6,
                                               benchmark::Counter::kIsIterationInvariantRate);
}

void register_warp(const WarpCase& c, WarpKernel kernel, Sampling sampling) {
  const std::string name =
      std::string("warp/") + (kernel == WarpKernel::kAffine ? "affine/" : "perspective/") +
      (sampling == Sampling::kNearest ? "nearest/" : "bilinear/") + c.size + "/" + c.matrix;
  benchmark::RegisterBenchmark(name.c_str(),
                               [c, kernel, sampling](benchmark::State& state) {
                                 Image output(c.output_width, c.output_height);
                                 const WarpOptions options{sampling, kernel};
                                 std::int64_t written = 0;
                                 for (auto _ : state) {
                                   written = warp_layer_into(c.source, c.warp, output, c.origin_x,
                                                             c.origin_y, options)
                                                 .pixels_written;
                                   benchmark::DoNotOptimize(output.pixels().data());
                                   benchmark::ClobberMemory();
                                 }
                                 if (written != c.polygon_pixels) {
                                   state.SkipWithError("unexpected pixel count");
                                 }
                                 set_rate(state, c.polygon_pixels);
                               })
      ->Repetitions(kRepetitions)
      ->ReportAggregatesOnly(true)
      ->Unit(benchmark::kMillisecond);
}

void register_copy(const WarpCase& c) {
  const std::string name = "copy/" + c.size + "/" + c.matrix;
  benchmark::RegisterBenchmark(name.c_str(),
                               [c](benchmark::State& state) {
                                 const std::size_t bytes =
                                     static_cast<std::size_t>(c.polygon_pixels) * sizeof(Pixel);
                                 std::vector<unsigned char> from(bytes, 1);
                                 std::vector<unsigned char> to(bytes);
                                 for (auto _ : state) {
                                   std::memcpy(to.data(), from.data(), bytes);
                                   benchmark::DoNotOptimize(to.data());
                                   benchmark::ClobberMemory();
                                 }
                                 set_rate(state, c.polygon_pixels);
                               })
      ->Repetitions(kRepetitions)
      ->ReportAggregatesOnly(true)
      ->Unit(benchmark::kMillisecond);
}

void register_all() {
  const std::vector<WarpCase> table = appendix_a2_cases();
  for (const WarpCase& c : table) {
    if (c.affine) register_warp(c, WarpKernel::kAffine, Sampling::kNearest);
    register_warp(c, WarpKernel::kPerspective, Sampling::kNearest);
    register_copy(c);
  }
  const std::vector<WarpCase> frames = frame_cases();
  for (const WarpCase& c : frames) {
    for (Sampling sampling : {Sampling::kNearest, Sampling::kBilinear}) {
      if (c.affine) register_warp(c, WarpKernel::kAffine, sampling);
      register_warp(c, WarpKernel::kPerspective, sampling);
    }
    register_copy(c);
  }
#ifdef OFLAB_BENCH_WITH_OPENCV
  register_opencv_cases(table, false, kRepetitions);
  register_opencv_cases(frames, true, kRepetitions);
#endif
#ifdef OFLAB_BENCH_WITH_PIXMAN
  register_pixman_cases(table, false, kRepetitions);
  register_pixman_cases(frames, true, kRepetitions);
#endif
  register_mipmap_cases(kRepetitions);
  register_engine_cases(kRepetitions);
  register_content_cases(kRepetitions);
  register_scene_cases(1);
}

}  // namespace
}  // namespace oflab::bench

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  oflab::bench::register_all();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
