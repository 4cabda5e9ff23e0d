// Rival reuse policies side by side (see analysis/experiments/experiments_policies.h).
#include "experiments/experiments_policies.h"

#include <cmath>
#include <limits>

#include "experiments/experiments_runs.h"
#include "experiments/experiments_single_plane.h"
#include "experiments/published_results.h"
#include "formats/datasets.h"
#include "formats/scene_file.h"
#include "formats/script_file.h"
#include "formats/viewer_script_file.h"

namespace oflab {
namespace {

// Every policy that plays a single plane as well as a scene: the node-image cache
// (hierarchical-cache) and motion-vector extrapolation (needs_scene) are compared in the
// reprojection section (experiments_reprojection.h) on scenes only.
std::vector<const ReusePolicy*> every_policy() {
  std::vector<const ReusePolicy*> all;
  for (const ReusePolicy& p : reuse_policies()) {
    if (!needs_scene(p)) all.push_back(&p);
  }
  return all;
}

const PolicyRun& run_of(const PoliciesSource& s, const char* policy) {
  for (const PolicyRun& r : s.runs) {
    if (std::string(r.policy->name) == policy) return r;
  }
  throw std::logic_error(std::string("no run of policy ") + policy);
}

// The published level mix of a source, or nullptr when there is none.
const std::array<double, kLevelCount>* published_levels(const PoliciesSource& s) {
  if (s.scene) return &published_four_cubes_levels();
  const PublishedScriptResult* row = published_experiment1_row(s.name);
  return row ? &row->level_percent : nullptr;
}

ReportTable policies_table(const PoliciesResult& r) {
  ReportTable t;
  t.caption =
      "Every policy on the same frames: percent of layer-frames per level (a plane's "
      "frames after the first; the scene's drawn polygons), work and time saved "
      "against the exact re-render of the same run, measured error, mean PSNR";
  t.header = level_header("source, policy", {"work saved", "time saved", "max error px",
                                             "mean error px", "mean PSNR dB"});
  for (const PoliciesSource& s : r.sources) {
    for (const PolicyRun& run : s.runs) {
      const PolicyRow row = policy_row(run);
      std::vector<std::string> cells = {s.name + ", " + row.name};
      for (double p : published_style_levels(s, run)) cells.push_back(fixed(p, 1));
      cells.push_back(percent(row.work_saved));
      cells.push_back(percent(row.time_saved));
      cells.push_back(fixed(row.max_measured_error_px, 2));
      cells.push_back(fixed(row.mean_measured_error_px, 3));
      cells.push_back(fixed(row.mean_psnr_db, 1));
      t.rows.push_back(cells);
    }
  }
  return t;
}

std::string gap_reading(const GapAttribution& g) {
  if (g.corrected_points < 0.5) {
    return "the corrected rule matches the published mix (within half a point)";
  }
  if (std::abs(g.explained) < 0.005) {
    return "the printed rule explains none of the gap: the reconstructed script (or the "
           "engine) does";
  }
  if (g.explained > 0.0) {
    return "the printed rule explains " + percent(std::min(1.0, g.explained), 0) +
           " of the gap; the rest is the reconstructed script and the engine";
  }
  return "the printed rule is further from the published mix than the corrected one, so the "
         "rule does not explain the gap: the reconstructed script (or something the text "
         "does not say) does";
}

ReportTable attribution_table(const PoliciesResult& r) {
  ReportTable t;
  t.caption =
      "The printed rule (dissertation) and the corrected rule (perspective) beside the "
      "published level mix; distance = half the sum over levels of |published - "
      "measured|, percentage points";
  t.header = level_header("source", {"distance to published", "reading"});
  for (const PoliciesSource& s : r.sources) {
    const std::array<double, kLevelCount>* pub = published_levels(s);
    if (!pub) continue;
    const auto corrected = published_style_levels(s, run_of(s, "perspective"));
    const auto printed = published_style_levels(s, run_of(s, "dissertation"));
    const GapAttribution g = attribute_gap(*pub, corrected, printed);
    const auto add = [&](const std::string& who, const std::array<double, kLevelCount>& mix,
                         const std::string& distance, const std::string& reading) {
      std::vector<std::string> cells = {s.name + ", " + who};
      for (double p : mix) cells.push_back(fixed(p, 1));
      cells.push_back(distance);
      cells.push_back(reading);
      t.rows.push_back(cells);
    };
    add("published", *pub, "", "");
    add("perspective (corrected)", corrected, fixed(g.corrected_points, 1), "");
    add("dissertation (printed)", printed, fixed(g.printed_points, 1), gap_reading(g));
  }
  return t;
}

ReportTable budget_table(const PoliciesResult& r) {
  ReportTable t;
  t.caption =
      "The budget policy on the four cubes (compound viewer script) at three pixel "
      "budgets per frame: frames over budget (the rule keeps none), starved "
      "layer-frames (the rule would have spent pixels on them and got none), the mean "
      "optimality gap of the greedy allocation against the optimum (dynamic "
      "programming over the whole-pixel budget, core/engine/budget.h) over the frames "
      "checked, and the quality bought";
  t.header = {"budget px/frame", "frames over budget", "starved layer-frames", "mean gap %",
              "frames checked",  "work saved",         "max error px",         "mean PSNR dB"};
  for (const BudgetRun& b : r.budgets) {
    const PolicyRow row = policy_row(b.run);
    t.rows.push_back({fixed(b.budget_pixels, 0), std::to_string(row.frames_over_budget),
                      std::to_string(row.starved_layer_frames),
                      std::isfinite(row.mean_optimality_gap)
                          ? fixed(100.0 * row.mean_optimality_gap, 2)
                          : std::string("not checked"),
                      std::to_string(row.gap_frames), percent(row.work_saved),
                      fixed(row.max_measured_error_px, 2), fixed(row.mean_psnr_db, 1)});
  }
  return t;
}

Chart error_work_chart(const PoliciesResult& r) {
  ChartPanel panel;
  panel.title = "measured error against work saved, one point per policy and source";
  panel.x_label = "work saved %";
  panel.y_label = "log10 max error px";
  panel.y_range = std::make_pair(-2.2, 1.8);
  int colour = 0;
  for (const ReusePolicy* p : every_policy()) {
    ChartSeries series{p->name, {}, {}, SeriesStyle::kPoints, chart_palette(colour++)};
    for (const PoliciesSource& s : r.sources) {
      const PolicyRow row = policy_row(run_of(s, p->name));
      series.x.push_back(100.0 * row.work_saved);
      series.y.push_back(std::log10(std::max(row.max_measured_error_px, 0.01)));
    }
    panel.series.push_back(series);
  }
  Chart chart;
  chart.panels = {panel};
  return chart;
}

}  // namespace

PoliciesSpec policies_spec(bool quick) {
  PoliciesSpec spec;
  spec.max_frames = quick ? 40 : -1;
  spec.repetitions = quick ? 1 : kDefaultTimingRepetitions;  // as `compare`, so it reproduces a row
  return spec;
}

PoliciesResult run_policies_experiment(const Layer& texture, const PoliciesSpec& spec,
                                       const std::function<void(const std::string&)>& progress) {
  PoliciesResult result;
  result.spec = spec;
  PlayOptions options;
  options.max_frames = spec.max_frames;
  options.warm_up = true;
  options.timing_repetitions = spec.repetitions;
  for (const std::string& name : experiment1_scripts()) {
    if (progress) progress(name + " under " + std::to_string(every_policy().size()) + " policies");
    RunSource source;
    source.script = read_script_file(resolve_script_path(name));
    source.texture = texture.image;
    result.sources.push_back(
        {name, false, run_policies(source_kind("plane"), source, every_policy(), options)});
  }
  if (progress) progress("four-cubes, compound script, under every policy");
  RunSource scene;
  scene.scene = std::make_shared<const Scene>(read_scene_file(resolve_scene_path("four-cubes")));
  scene.viewer = read_viewer_script_file(resolve_viewer_script_path("compound"));
  scene.settings.skip_hidden = false;  // every polygon in the frustum updated, as section 6.7.3
  result.sources.push_back(
      {"four-cubes", true, run_policies(source_kind("scene"), scene, every_policy(), options)});
  for (double pixels : kFourCubesBudgets) {
    if (progress) progress("four-cubes under budget, " + fixed(pixels, 0) + " px per frame");
    scene.settings.engine.budget = {FrameBudget::Unit::kPixels, pixels};
    result.budgets.push_back(
        {pixels,
         run_policies(source_kind("scene"), scene, {&reuse_policy("budget")}, options).at(0)});
  }
  return result;
}

std::array<double, kLevelCount> published_style_levels(const PoliciesSource& source,
                                                       const PolicyRun& run) {
  std::array<double, kLevelCount> percent{};
  if (source.scene) {
    const PolicyRow row = policy_row(run);
    for (int l = 0; l < kLevelCount; ++l) percent[l] = 100.0 * row.level_share[l];
    return percent;
  }
  const std::vector<AnimationFrame>& frames = run.run.frames;
  if (frames.size() < 2) return percent;
  for (size_t i = 1; i < frames.size(); ++i) {
    percent[static_cast<int>(frames[i].layer_reports.at(0).level)] += 1.0;
  }
  for (double& p : percent) p *= 100.0 / static_cast<double>(frames.size() - 1);
  return percent;
}

GapAttribution attribute_gap(const std::array<double, kLevelCount>& published,
                             const std::array<double, kLevelCount>& corrected,
                             const std::array<double, kLevelCount>& printed) {
  GapAttribution g;
  for (int l = 0; l < kLevelCount; ++l) {
    g.corrected_points += 0.5 * std::abs(published[l] - corrected[l]);
    g.printed_points += 0.5 * std::abs(published[l] - printed[l]);
  }
  g.explained = g.corrected_points > 0.0
                    ? (g.corrected_points - g.printed_points) / g.corrected_points
                    : std::numeric_limits<double>::quiet_NaN();
  return g;
}

ReportSection policies_section(const PoliciesResult& result, ExperimentContext& context) {
  ReportSection s;
  s.id = "policies";
  s.title = "Rival reuse policies side by side (beyond the dissertation)";
  s.paragraph(
      "Every Experiment 1 script and the four cubes (compound viewer script, every polygon in "
      "the frustum updated) under every policy of 'oflab-cli policies', each run as "
      "'oflab-cli compare' runs it: a warm-up and " +
      count_of(result.spec.repetitions, "timed repetition") +
      " interleaved with the exact "
      "re-render, " +
      (result.spec.max_frames > 0 ? "at most " + std::to_string(result.spec.max_frames) + " frames"
                                  : std::string("whole scripts")) +
      ". 'dissertation' is Algorithm 1 as printed (manual/policies.md lists each choice); "
      "'talisman' is Lengyel and Snyder's least-squares affine warp with its fiducials. Work "
      "saved and errors are deterministic; time saved depends on the machine's load.");
  s.table(policies_table(result));
  s.paragraph(
      "Attribution: the published level mix against the corrected rule (perspective) and "
      "the printed rule (dissertation) on the same reconstructed scripts. Whatever distance "
      "the printed rule removes is explained by the rule; what remains is the reconstructed "
      "scripts (and anything else the text leaves unsaid).");
  s.table(attribution_table(result));
  s.paragraph(
      "'budget' (section 7.5.2's future work, Horvitz and Lengyel's cost-benefit) spends a "
      "per-frame pixel budget where it removes the most error; in the table above it has the "
      "default budget, a quarter of the frame's pixels. Below, the four cubes at three "
      "budgets, with the greedy allocation checked against the optimum in every frame.");
  s.table(budget_table(result));
  s.figure(context.add_chart("policies-error-work", error_work_chart(result),
                             "Largest measured error (log10 px; an error of 0 px is drawn at "
                             "-2) against work saved, one point per policy and source (the "
                             "Experiment 1 scripts and four cubes)."));
  return s;
}

}  // namespace oflab
