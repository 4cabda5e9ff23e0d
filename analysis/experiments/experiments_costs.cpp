#include "experiments/experiments_costs.h"

#include <cmath>
#include <limits>
#include <memory>

#include "experiments/experiments_runs.h"
#include "experiments/experiments_single_plane.h"
#include "experiments/published_results.h"
#include "formats/datasets.h"
#include "formats/scene_file.h"
#include "formats/script_file.h"
#include "formats/viewer_script_file.h"
#include "runs/source_kinds.h"

namespace oflab {
namespace {

constexpr const char* kStreet = "street/walk";

EngineSettings with_content(const LayerContent& content) {
  EngineSettings s;
  s.content = content;
  return s;
}

CostPoint point_of(const LayerContent& content, const RunSummary& summary) {
  const double pixels = static_cast<double>(summary.baseline_pixels);
  return {content, pixels > 0 ? summary.baseline_model_work / pixels : 0.0, summary};
}

PlayOptions play_options(const CostSweepSpec& spec, int frames) {
  PlayOptions options;
  options.max_frames = frames;
  options.warm_up = true;
  options.timing_repetitions = spec.repetitions;
  return options;
}

CostScript measure_plane(const std::string& name, const Layer& texture, const CostSweepSpec& spec,
                         const std::function<void(const std::string&)>& progress) {
  RunSource source;
  source.script = read_script_file(resolve_script_path(name));
  source.texture = texture.image;
  CostScript out{name, {}};
  for (const LayerContent& c : spec.contents) {
    if (progress) progress(name + ", " + content_label(c));
    source.settings.engine = with_content(c);
    const AnimationRun run = source_kind("plane").play(source, play_options(spec, spec.max_frames));
    out.points.push_back(point_of(c, run.summary));
  }
  return out;
}

// The street with every polygon showing the same content: the same knob as the planes.
CostScript measure_street(const CostSweepSpec& spec,
                          const std::function<void(const std::string&)>& progress) {
  RunSource source;
  const Scene scene = read_scene_file(resolve_scene_path("street"));
  source.viewer = read_viewer_script_file(resolve_viewer_script_path("walk"));
  CostScript out{kStreet, {}};
  for (const LayerContent& c : spec.contents) {
    if (progress) progress(std::string(kStreet) + ", " + content_label(c));
    Scene same = scene;
    for (ScenePolygon& p : same.polygons) p.content = c.kind;
    source.scene = std::make_shared<const Scene>(std::move(same));
    source.settings.engine = with_content(c);
    const AnimationRun run =
        source_kind("scene").play(source, play_options(spec, spec.street_frames));
    out.points.push_back(point_of(c, run.summary));
  }
  return out;
}

std::string break_even_text(double cost) {
  if (std::isnan(cost)) return "not reached in the sweep";
  if (cost == 0.0) return "pays already at the cheapest content";
  return fixed(cost, 1) + " warp pixels per pixel";
}

// The published time saved beside the first point that costs at least ten warps.
std::string published_reading(const CostScript& s, std::size_t k) {
  const PublishedScriptResult* pub = published_experiment1_row(s.script);
  if (!pub) return "";
  const CostPoint& p = s.points[k];
  const bool first_ten = p.render_cost >= 10.0 && (k == 0 || s.points[k - 1].render_cost < 10.0);
  if (!first_ten) return "";
  const double published = pub->time_saved_percent / 100.0;
  return "published " + percent(published) +
         (p.summary.time_saved >= published ? ": reached" : ": not reached");
}

ReportTable cost_table(const CostSweepResult& r) {
  ReportTable t;
  t.caption = "Time saved against the re-render cost (perspective mode)";
  t.header = {"script",           "content",      "re-render cost",        "time saved",
              "model work saved", "max error px", "max photometric error", "mean PSNR dB",
              "beside published"};
  for (const CostScript& s : r.scripts) {
    for (std::size_t k = 0; k < s.points.size(); ++k) {
      const CostPoint& p = s.points[k];
      t.rows.push_back({s.script, content_label(p.content), fixed(p.render_cost, 1),
                        percent(p.summary.time_saved), percent(p.summary.model_work_saved),
                        fixed(p.summary.max_measured_error_px, 2),
                        fixed(p.summary.max_photometric_error, 1), fixed(p.summary.mean_psnr_db, 1),
                        published_reading(s, k)});
    }
  }
  return t;
}

ReportTable break_even_table(const CostSweepResult& r) {
  ReportTable t;
  t.caption = "Break-even: the re-render cost from which reuse saves time (perspective mode)";
  t.header = {"script", "break-even (measured time)", "time saved at the dearest content"};
  for (const CostScript& s : r.scripts) {
    t.rows.push_back({s.script, break_even_text(break_even_cost(s)),
                      percent(s.points.back().summary.time_saved)});
  }
  return t;
}

ChartPanel saved_panel(const CostSweepResult& r, const std::string& title, bool modelled) {
  ChartPanel panel;
  panel.title = title;
  panel.x_label = "re-render cost (perspective-warp pixels per pixel)";
  panel.y_label = "%";
  int colour = 0;
  for (const CostScript& s : r.scripts) {
    ChartSeries series{s.script, {}, {}, SeriesStyle::kLine, chart_palette(colour++)};
    for (const CostPoint& p : s.points) {
      series.x.push_back(p.render_cost);
      series.y.push_back(100.0 * (modelled ? p.summary.model_work_saved : p.summary.time_saved));
    }
    panel.series.push_back(series);
  }
  ChartSeries zero{"break-even",
                   {0.0, r.scripts.empty() ? 1.0 : r.scripts[0].points.back().render_cost},
                   {0.0, 0.0},
                   SeriesStyle::kLine,
                   chart_palette(colour)};
  panel.series.push_back(zero);
  return panel;
}

}  // namespace

std::string content_label(const LayerContent& c) {
  switch (c.kind) {
    case ContentKind::kTexture:
      return "texture";
    case ContentKind::kImpostor:
      return "impostor " + std::to_string(c.quality);
    case ContentKind::kShaded:
      break;
  }
  return "shaded " + std::to_string(c.quality) + " spp";
}

CostSweepSpec cost_sweep_spec(bool quick) {
  CostSweepSpec spec;
  const LayerContent texture{};
  const auto make = [](ContentKind kind, int quality) {
    LayerContent c;
    c.kind = kind;
    c.quality = quality;
    return c;
  };
  spec.contents = {texture, make(ContentKind::kImpostor, 1)};
  if (!quick) spec.contents.push_back(make(ContentKind::kImpostor, 3));
  spec.contents.push_back(make(ContentKind::kShaded, 1));
  if (!quick) spec.contents.push_back(make(ContentKind::kShaded, 2));
  spec.max_frames = quick ? 12 : 150;
  spec.street_frames = quick ? 4 : 60;
  spec.repetitions = 1;
  return spec;
}

double break_even_cost(const CostScript& s) {
  if (s.points.empty()) return std::numeric_limits<double>::quiet_NaN();
  if (s.points[0].summary.time_saved >= 0.0) return 0.0;
  for (std::size_t k = 1; k < s.points.size(); ++k) {
    const CostPoint &a = s.points[k - 1], &b = s.points[k];
    if (b.summary.time_saved < 0.0) continue;
    const double f = -a.summary.time_saved / (b.summary.time_saved - a.summary.time_saved);
    return a.render_cost + f * (b.render_cost - a.render_cost);
  }
  return std::numeric_limits<double>::quiet_NaN();
}

CostSweepResult run_cost_sweep(const Layer& texture, const CostSweepSpec& spec,
                               const std::function<void(const std::string&)>& progress) {
  CostSweepResult result;
  result.spec = spec;
  for (const std::string& name : experiment1_scripts()) {
    result.scripts.push_back(measure_plane(name, texture, spec, progress));
  }
  result.scripts.push_back(measure_street(spec, progress));
  return result;
}

ReportSection cost_sweep_section(const CostSweepResult& result, ExperimentContext& context) {
  ReportSection s;
  s.id = "costs";
  s.title = "When reuse pays: time saved against the re-render's cost (beyond the dissertation)";
  s.paragraph(
      "Every Experiment 1 script (at most " + std::to_string(result.spec.max_frames) +
      " frames) and the street scene's walk (at most " + std::to_string(result.spec.street_frames) +
      " frames, every polygon showing the same content) with each content in turn: the texture "
      "(a re-render is one perspective warp), the facade impostor (lit, depth-tested boxes; "
      "detail 1 and 3) and the shaded brick (lit per sample; 1 and 2 samples per pixel), "
      "perspective mode, 1 px thresholds, a warm-up and " +
      count_of(result.spec.repetitions, "timed repetition") +
      ". The re-render cost is the cost model's work of the run's re-render baseline per pixel "
      "it wrote (manual/costs.md), in perspective-warp pixels: one impostor fragment counts " +
      fixed(content_unit_cost(ContentKind::kImpostor), 1) + ", one shaded sample " +
      fixed(content_unit_cost(ContentKind::kShaded), 1) +
      ", as measured by oflab-bench. Time saved is measured against re-rendering the same content "
      "in the same run; model work saved is the dissertation's cost model (perspective warp 1, "
      "affine 1/2.1, translation 1/35 of the layer, re-render at the content's cost). The "
      "dissertation's bitmap re-render cost about 2.1-3 affine warps (section 6.4.4), that is "
      "1-1.4 here: the left end of the chart. The photometric error is the staleness of the "
      "shading a warp keeps, in grey levels. Times come from a shared, busy machine.");
  s.table(cost_table(result));
  s.table(break_even_table(result));
  Chart chart;
  chart.panels = {saved_panel(result, "time saved (measured)", false),
                  saved_panel(result, "work saved (cost model)", true)};
  s.figure(context.add_chart("costs-break-even", chart,
                             "Time saved (top, measured) and work saved (bottom, cost model) "
                             "against the re-render's cost, per script; reuse pays above the "
                             "zero line."));
  return s;
}

}  // namespace oflab
