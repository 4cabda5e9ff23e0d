// oflab-bench's mipmap cases: see mipmap_bench.h.
#include "mipmap_bench.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <vector>

#include "image/mip_pyramid.h"
#include "image/warp.h"
#include "warp_cases.h"

namespace oflab::bench {
namespace {

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values.empty() ? 0.0 : values[values.size() / 2];
}

// A 1024 x 768 layer of random texels shown 2.5 times smaller, turned by 20 degrees (affine),
// or the same with a perspective row that makes one side 1.6 times smaller than the other.
struct MinifyingCase {
  std::string kernel;
  std::string matrix;
  Mat3 warp;
};

std::vector<MinifyingCase> minifying_cases() {
  const double t = 20.0 * 3.14159265358979323846 / 180.0, s = 1.0 / 2.5;
  const Mat3 linear = mat3_from_rows({s * std::cos(t), -s * std::sin(t), 0.0},
                                     {s * std::sin(t), s * std::cos(t), 0.0}, {0.0, 0.0, 1.0});
  const Mat3 affine = translation_matrix(300.0, 200.0) * linear * translation_matrix(-512, -384);
  Mat3 tilt(1.0);
  entry(tilt, 2, 0) = 0.6 / 1024.0;
  return {{"affine", "shrink2.5-rot20", affine},
          {"perspective", "shrink2.5-tilt",
           affine * translation_matrix(512, 384) * tilt * translation_matrix(-512, -384)}};
}

void register_case(const Layer& source, const MipPyramid& pyramid, const MinifyingCase& c,
                   int repetitions) {
  const std::string name = "mipmap-vs-bilinear/" + c.kernel + "/1024x768/" + c.matrix;
  const WarpKernel kernel = c.kernel == "affine" ? WarpKernel::kAffine : WarpKernel::kPerspective;
  benchmark::RegisterBenchmark(
      name.c_str(),
      [&source, &pyramid, c, kernel](benchmark::State& state) {
        Image output(600, 400);
        const WarpOptions bilinear{Sampling::kBilinear, kernel};
        const WarpOptions mipmap{Sampling::kMipmap, kernel, kDefaultHorizonEpsilon, &pyramid};
        std::vector<double> bilinear_ms, mipmap_ms;
        using Clock = std::chrono::steady_clock;
        const auto ms = [](Clock::time_point a, Clock::time_point b) {
          return std::chrono::duration<double, std::milli>(b - a).count();
        };
        for (auto _ : state) {
          const auto t0 = Clock::now();
          warp_layer_into(source, c.warp, output, 0, 0, bilinear);
          benchmark::ClobberMemory();
          const auto t1 = Clock::now();
          warp_layer_into(source, c.warp, output, 0, 0, mipmap);
          benchmark::ClobberMemory();
          const auto t2 = Clock::now();
          bilinear_ms.push_back(ms(t0, t1));
          mipmap_ms.push_back(ms(t1, t2));
        }
        const double b = median(bilinear_ms), m = median(mipmap_ms);
        state.counters["bilinear_ms"] = b;
        state.counters["mipmap_ms"] = m;
        state.counters["ratio"] = b > 0.0 ? m / b : 0.0;
      })
      ->Repetitions(repetitions)
      ->ReportAggregatesOnly(true)
      ->Unit(benchmark::kMillisecond);
}

}  // namespace

void register_mipmap_cases(int repetitions) {
  static const Layer source = [] {
    Image image(1024, 768);
    unsigned state = 12345u;
    for (Pixel& p : image.pixels()) {
      state = state * 1664525u + 1013904223u;
      const auto v = static_cast<std::uint8_t>(state >> 24);
      p = Pixel{v, static_cast<std::uint8_t>(255 - v), static_cast<std::uint8_t>(v / 2), 255};
    }
    return make_layer(std::move(image));
  }();
  static MipPyramid pyramid;
  build_mip_pyramid(source.image, pyramid);
  for (const MinifyingCase& c : minifying_cases()) register_case(source, pyramid, c, repetitions);
}

}  // namespace oflab::bench
