// Shrinking without shimmering: the samplings of the warps on a receding plane against an
// exact supersampled render (dissertation section 7.5.5; experiments_sampling.h).
#include "experiments/experiments_sampling.h"

#include <cmath>

#include "experiments/experiments_runs.h"

namespace oflab {
namespace {

// The PSNR per frame of each sampling, and below it the minification of the shown layer.
Chart sampling_chart(const SamplingComparison& c) {
  Chart chart;
  ChartPanel psnr{"PSNR against the 16-sample exact render", "frame", "dB", {}, {}, {}, {}, {}};
  ChartPanel scale{"minification of the shown layer (1: a re-render)",
                   "frame",
                   "times smaller",
                   {},
                   {},
                   {},
                   {},
                   {}};
  for (std::size_t k = 0; k < c.runs.size(); ++k) {
    ChartSeries series{sampling_name(c.runs[k].sampling),
                       {},
                       {},
                       SeriesStyle::kLine,
                       chart_palette(static_cast<int>(k))};
    for (const SamplingFrame& f : c.runs[k].frames) {
      series.x.push_back(f.frame);
      series.y.push_back(f.psnr_db);
    }
    psnr.series.push_back(std::move(series));
  }
  ChartSeries minification{"minification", {}, {}, SeriesStyle::kPoints, chart_palette(3)};
  for (const SamplingFrame& f : c.runs[0].frames) {
    minification.x.push_back(f.frame);
    minification.y.push_back(std::isfinite(f.minification) ? f.minification : 1.0);
  }
  scale.series.push_back(std::move(minification));
  chart.panels = {psnr, scale};
  return chart;
}

}  // namespace

std::vector<std::string> sampling_summary_lines(const SamplingComparison& c) {
  std::vector<std::string> lines;
  lines.push_back("script " + c.spec.script + ", policy " + c.spec.policy + ", " +
                  std::to_string(c.frames) + " frames, " + std::to_string(c.minified_frames) +
                  " reused frames minified more than " + fixed(kMinifiedFactor, 1) + "x");
  for (const SamplingRun& r : c.runs) {
    lines.push_back(std::string(sampling_name(r.sampling)) + ": PSNR over the minified frames " +
                    fixed(r.minified_psnr_db, 2) +
                    " dB against the 16-sample exact render, "
                    "median warp " +
                    fixed(r.median_warp_ms, 3) + " ms");
  }
  lines.push_back("mipmap gains " + fixed(c.mipmap_gain_db(), 2) + " dB over bilinear there, at " +
                  fixed(c.warp_time_ratio(), 2) + "x its warp time");
  return lines;
}

ReportSection sampling_section(const SamplingComparison& c, ExperimentContext& context) {
  ReportSection s;
  s.id = "sampling";
  s.title = "Shrinking without shimmering: mipmap sampling (7.5.5)";
  s.paragraph(
      "A frontal plane with a finely woven texture (a chequer of 2-texel cells under the "
      "butterfly, datasets/textures/fabric.png) recedes from Z = 2 to Z = 8 (script " +
      c.spec.script + ", policy " + c.spec.policy + ", " + std::to_string(c.frames) +
      " frames): a reused layer is shown smaller and smaller, up to a quarter of the size it was "
      "made at. Nearest and bilinear sampling then skip texels and the detail shimmers; "
      "mipmap samples a pyramid of box-filtered levels of the layer at the level of each "
      "pixel's footprint. Every frame is compared with an exact render of 16 samples per pixel "
      "(a 4 x 4 box), which is what the minified plane should look like.");
  const Chart chart = sampling_chart(c);
  s.figure(context.add_chart(
      "sampling-psnr", chart,
      "PSNR per frame of nearest, bilinear and mipmap sampling on " + c.spec.script +
          " against the 16-sample exact render; below, how much smaller the shown layer is "
          "than when it was made. Mipmap's warps take " +
          fixed(c.warp_time_ratio(), 2) + "x bilinear's time (median per reused frame)."));
  ReportTable t;
  t.caption = "The reused frames minified more than " + fixed(kMinifiedFactor, 1) + "x (" +
              std::to_string(c.minified_frames) + " frames)";
  t.header = {"sampling", "mean PSNR (dB)", "gain over bilinear (dB)", "median warp (ms)",
              "time / bilinear"};
  const SamplingRun& bilinear = c.run(Sampling::kBilinear);
  for (const SamplingRun& r : c.runs) {
    t.rows.push_back({sampling_name(r.sampling), fixed(r.minified_psnr_db, 2),
                      signed_fixed(r.minified_psnr_db - bilinear.minified_psnr_db, 2),
                      fixed(r.median_warp_ms, 3),
                      fixed(r.median_warp_ms / bilinear.median_warp_ms, 2)});
  }
  s.table(t);
  return s;
}

}  // namespace oflab
