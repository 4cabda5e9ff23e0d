// OpenCV peer cases for oflab-bench (see opencv_peer.h).
#include "opencv_peer.h"

#include <benchmark/benchmark.h>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace oflab::bench {
namespace {

cv::Mat wrap(const Image& image) {
  return cv::Mat(image.height(), image.width(), CV_8UC4, const_cast<Pixel*>(image.pixels().data()));
}

// oflab's destination frame -> OpenCV's output pixel indices (centres at integers).
cv::Mat opencv_matrix(const WarpCase& c) {
  const Mat3 m = translation_matrix(-0.5 - c.origin_x, -0.5 - c.origin_y) * c.warp *
                 translation_matrix(0.5, 0.5);
  cv::Mat out(3, 3, CV_64F);
  for (int r = 0; r < 3; ++r) {
    for (int k = 0; k < 3; ++k) out.at<double>(r, k) = entry(m, r, k);
  }
  return out;
}

}  // namespace

void register_opencv_cases(const std::vector<WarpCase>& cases, bool bilinear_too, int repetitions) {
  cv::setNumThreads(1);
  for (const WarpCase& c : cases) {
    for (bool bilinear : {false, true}) {
      if (bilinear && !bilinear_too) continue;
      for (bool perspective : {false, true}) {
        if (!perspective && !c.affine) continue;
        const std::string name = std::string("opencv/") +
                                 (perspective ? "perspective/" : "affine/") +
                                 (bilinear ? "bilinear/" : "nearest/") + c.size + "/" + c.matrix;
        benchmark::RegisterBenchmark(
            name.c_str(),
            [c, bilinear, perspective](benchmark::State& state) {
              const cv::Mat source = wrap(c.source.image);
              Image result(c.output_width, c.output_height);
              cv::Mat output = wrap(result);  // OpenCV writes into oflab's image
              const cv::Mat m = opencv_matrix(c);
              const int flags = bilinear ? cv::INTER_LINEAR : cv::INTER_NEAREST;
              for (auto _ : state) {
                if (perspective) {
                  cv::warpPerspective(source, output, m, output.size(), flags, cv::BORDER_CONSTANT);
                } else {
                  cv::warpAffine(source, output, m.rowRange(0, 2), output.size(), flags,
                                 cv::BORDER_CONSTANT);
                }
                benchmark::DoNotOptimize(output.data);
                benchmark::ClobberMemory();
              }
              set_peer_counters(state, c, result,
                                bilinear ? Sampling::kBilinear : Sampling::kNearest);
            })
            ->Repetitions(repetitions)
            ->ReportAggregatesOnly(true)
            ->Unit(benchmark::kMillisecond);
      }
    }
  }
}

}  // namespace oflab::bench
