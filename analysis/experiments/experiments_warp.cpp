#include "experiments/experiments_warp.h"

#include <cmath>

#include "engine/wall_clock.h"
#include "experiments/experiments_runs.h"
#include "experiments/published_results.h"
#include "formats/datasets.h"
#include "formats/image_io.h"
#include "generators/butterfly.h"
#include "image/warp.h"

namespace oflab {
namespace {

constexpr double kPi = 3.14159265358979323846;

Mat3 rotation_about_centre(double degrees, double w, double h) {
  const double t = degrees * kPi / 180.0;
  return translation_matrix(0.5 * w, 0.5 * h) *
         mat3_from_rows({std::cos(t), -std::sin(t), 0.0}, {std::sin(t), std::cos(t), 0.0},
                        {0.0, 0.0, 1.0}) *
         translation_matrix(-0.5 * w, -0.5 * h);
}

// Pixel -> normalised image units: centre at the origin, one unit = the image width.
Mat3 to_normalised(double w, double h) {
  return mat3_from_rows({1.0 / w, 0.0, -0.5}, {0.0, 1.0 / w, -0.5 * h / w}, {0.0, 0.0, 1.0});
}

Mat3 matrix_for(const std::string& name, bool affine_kernel, double w, double h) {
  if (name == "identity") return Mat3(1.0);
  if (name == "rot45") return rotation_about_centre(45.0, w, h);
  Mat3 m = mat3_from_rows({0.8, 0.6, 0.0}, {-0.4, 0.8, 0.0}, {0.1, -0.3, 1.0});
  if (affine_kernel) {
    entry(m, 2, 0) = 0.0;
    entry(m, 2, 1) = 0.0;
  }
  const Mat3 n = to_normalised(w, h);
  return glm::inverse(n) * m * n;
}

WarpTiming time_case(const std::string& size, const Layer& source, const std::string& matrix,
                     bool affine_kernel, int repetitions) {
  const double w = source.image.width();
  const double h = source.image.height();
  const Mat3 warp = matrix_for(matrix, affine_kernel, w, h);
  const WarpedLayer box = warp_layer(source, warp);
  Image output(box.layer.image.width(), box.layer.image.height());
  const auto run = [&] {
    return affine_kernel ? warp_affine_into(source, warp, output, box.offset_x, box.offset_y,
                                            Sampling::kNearest)
                         : warp_perspective_into(source, warp, output, box.offset_x, box.offset_y,
                                                 Sampling::kNearest);
  };
  WarpTiming t{size, matrix, affine_kernel ? "affine" : "perspective", 0.0, 0, repetitions};
  for (int i = 0; i < 20; ++i) t.pixels_written = run().pixels_written;  // warm-up
  std::vector<double> ms;
  ms.reserve(repetitions);
  for (int i = 0; i < repetitions; ++i) {
    const auto start = WallClock::now();
    run();
    ms.push_back(ms_since(start));
  }
  t.median_ms = median_of(ms);
  return t;
}

const PublishedWarpTiming* published(const std::string& size, const std::string& matrix) {
  for (const PublishedWarpTiming& p : published_warp_timings()) {
    if (p.size == size && p.matrix == matrix) return &p;
  }
  return nullptr;
}

std::string signed_percent(double fraction) { return signed_fixed(100.0 * fraction, 0) + "%"; }

std::string ratio_text(double a, double b) { return b > 0 ? fixed(a / b, 2) + "x" : "n/a"; }

std::string row_reading(const WarpTimingResult& r, const WarpTiming& aff, const WarpTiming& per,
                        const PublishedWarpTiming* pub) {
  std::string text = "perspective/affine " + ratio_text(per.median_ms, aff.median_ms);
  if (pub) text += " (published " + ratio_text(pub->perspective_ms, pub->affine_ms) + ")";
  if (aff.matrix == "rot45") {
    const WarpTiming* ia = r.find(aff.size, "identity", "affine");
    const WarpTiming* ip = r.find(aff.size, "identity", "perspective");
    if (ia && ip) {
      text += "; vs identity " + signed_percent(aff.median_ms / ia->median_ms - 1.0) + " affine, " +
              signed_percent(per.median_ms / ip->median_ms - 1.0) + " perspective, writing " +
              signed_percent(static_cast<double>(aff.pixels_written) /
                                 static_cast<double>(ia->pixels_written) -
                             1.0) +
              " pixels (published +17%, +8%, put down to the empty pixels of its bounding box)";
    }
  }
  if (aff.size == "121x99" && aff.matrix == "M") {
    const WarpTiming* big = r.find("243x198", "M", "perspective");
    if (big) {
      text += "; " + fixed(100.0 * per.median_ms / big->median_ms, 0) +
              "% of the 243x198 time for 25% of the pixels (published 23%)";
    }
  }
  if (pub) {
    text += "; " + fixed(pub->perspective_ms / per.median_ms, 0) + "x faster than the Indy";
  }
  return text;
}

ReportTable timing_table(const WarpTimingResult& r) {
  ReportTable t;
  t.caption = "Warp timing: median milliseconds per warp, nearest sampling (appendix A.2)";
  t.header = {"image",
              "matrix",
              "affine: dissertation",
              "affine: oflab",
              "perspective: dissertation",
              "perspective: oflab",
              "pixels written (affine / perspective)",
              "reading"};
  for (size_t i = 0; i + 1 < r.timings.size(); i += 2) {
    const WarpTiming& aff = r.timings[i];
    const WarpTiming& per = r.timings[i + 1];
    const PublishedWarpTiming* pub = published(aff.size, aff.matrix);
    t.rows.push_back(
        {aff.size, aff.matrix, pub ? fixed(pub->affine_ms, 2) : "-", fixed(aff.median_ms, 4),
         pub ? fixed(pub->perspective_ms, 2) : "-", fixed(per.median_ms, 4),
         std::to_string(aff.pixels_written) + " / " + std::to_string(per.pixels_written),
         row_reading(r, aff, per, pub)});
  }
  return t;
}

Chart timing_chart(const WarpTimingResult& r) {
  ChartSeries aff{"affine kernel", {}, {}, SeriesStyle::kBars, chart_palette(0)};
  ChartSeries per{"perspective kernel", {}, {}, SeriesStyle::kBars, chart_palette(1)};
  ChartSeries ratio{"oflab", {}, {}, SeriesStyle::kBars, chart_palette(2)};
  ChartSeries pub_ratio{"dissertation", {}, {}, SeriesStyle::kBars, chart_palette(3)};
  std::vector<AxisTick> ticks;
  for (size_t i = 0; i + 1 < r.timings.size(); i += 2) {
    const double x = static_cast<double>(i / 2);
    const WarpTiming& a = r.timings[i];
    const WarpTiming& p = r.timings[i + 1];
    ticks.push_back({x, a.size + " " + a.matrix});
    aff.x.push_back(x);
    aff.y.push_back(1000.0 * a.median_ms);
    per.x.push_back(x);
    per.y.push_back(1000.0 * p.median_ms);
    ratio.x.push_back(x);
    ratio.y.push_back(p.median_ms / a.median_ms);
    const PublishedWarpTiming* pub = published(a.size, a.matrix);
    pub_ratio.x.push_back(x);
    pub_ratio.y.push_back(pub ? pub->perspective_ms / pub->affine_ms : NAN);
  }
  const auto range = std::make_pair(-0.6, static_cast<double>(ticks.size()) - 0.4);
  ChartPanel times{
      "oflab: median time per warp", "case", "microseconds", {aff, per}, range, {}, ticks, {}};
  ChartPanel ratios{
      "perspective / affine time", "case", "ratio", {ratio, pub_ratio}, range, {}, ticks, {}};
  Chart chart;
  chart.panels = {times, ratios};
  return chart;
}

}  // namespace

WarpTimingSpec warp_timing_spec(bool quick) { return WarpTimingSpec{quick ? 200 : 5000}; }

const WarpTiming* WarpTimingResult::find(const std::string& size, const std::string& matrix,
                                         const std::string& kernel) const {
  for (const WarpTiming& t : timings) {
    if (t.size == size && t.matrix == matrix && t.kernel == kernel) return &t;
  }
  return nullptr;
}

WarpTimingResult run_warp_timing(const WarpTimingSpec& spec,
                                 const std::function<void(const std::string&)>& progress) {
  const Layer full = make_layer(read_image(default_texture_path()));
  const Layer half = make_layer(make_butterfly(121, 99));
  WarpTimingResult result;
  for (const auto& [size, source] : {std::pair<std::string, const Layer*>{"243x198", &full},
                                     std::pair<std::string, const Layer*>{"121x99", &half}}) {
    for (const char* matrix : {"identity", "rot45", "M"}) {
      if (progress)
        progress(size + " " + matrix + ", " + std::to_string(spec.repetitions) +
                 " warps per kernel");
      for (bool affine : {true, false}) {
        result.timings.push_back(time_case(size, *source, matrix, affine, spec.repetitions));
      }
    }
  }
  return result;
}

ReportSection warp_timing_section(const WarpTimingResult& result, ExperimentContext& context) {
  ReportSection s;
  s.id = "warp-timing";
  s.title = "Warp timing (appendix A.2)";
  const int reps = result.timings.empty() ? 0 : result.timings.front().repetitions;
  s.paragraph(
      "The butterfly texture (243 x 198, RGBA) and its half-size version (121 x 99, drawn at that "
      "size), warped by the affine and the perspective kernel with nearest sampling into an "
      "output sized to the warped polygon's bounding box: median of " +
      std::to_string(reps) +
      " timed calls after 20 warm-up calls. M is applied in normalised image units (pixel "
      "coordinates minus the image centre, divided by the image width); the affine kernel runs "
      "M's upper two rows. The dissertation measured 3000-5000 calls on a 132 MHz R4600 Indy "
      "(24-bit images) and averaged them.");
  s.table(timing_table(result));
  s.figure(context.add_chart("warp-timing", timing_chart(result),
                             "Median time per warp for each case and kernel (top) and the "
                             "perspective/affine time ratio against the published one (bottom)."));
  return s;
}

}  // namespace oflab
