#include "experiments/experiments.h"

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include "experiments/experiments_costs.h"
#include "experiments/experiments_delta.h"
#include "experiments/experiments_policies.h"
#include "experiments/experiments_reprojection.h"
#include "experiments/experiments_sampling.h"
#include "experiments/experiments_scene_shifting.h"
#include "experiments/experiments_scenes.h"
#include "experiments/experiments_single_plane.h"
#include "experiments/experiments_sweep.h"
#include "experiments/experiments_visible_warp.h"
#include "experiments/experiments_warp.h"
#include "formats/atomic_file.h"
#include "formats/datasets.h"
#include "formats/image_io.h"
#include "generators/fabric_texture.h"
#include "report/report_machine.h"

namespace oflab {
namespace {

namespace fs = std::filesystem;

std::string fixed_seconds(double seconds) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(1) << seconds << " s";
  return s.str();
}

struct Experiment {
  const char* name;
  const char* title;
  ReportSection (*run)(ExperimentContext& context);
};

ReportSection run_exp1(ExperimentContext& c) {
  const Experiment1Result r =
      run_experiment1(c.texture(), experiment1_spec(c.quick()), c.progress_for("exp1", ""));
  ReportSection section = experiment1_section(r, c);
  if (!c.video_format().empty()) {
    const std::vector<std::string> videos =
        write_experiment1_videos(c, experiment1_spec(c.quick()));
    std::string list;
    for (const std::string& v : videos) list += (list.empty() ? "" : ", ") + v;
    section.paragraph("Videos of the frames each mode showed (--videos " + c.video_format() + ", " +
                      std::to_string(kExperiment1VideoFps) +
                      " fps), one per script and mode: " + list + ".");
  }
  return section;
}

ReportSection run_delta(ExperimentContext& c) {
  const DeltaResult r =
      run_delta_comparison(c.texture(), delta_spec(c.quick()), c.progress_for("delta", ""));
  return delta_section(r, c);
}

ReportSection run_warp(ExperimentContext& c) {
  const WarpTimingResult r =
      run_warp_timing(warp_timing_spec(c.quick()), c.progress_for("warp", ""));
  return warp_timing_section(r, c);
}

ReportSection run_exp2(ExperimentContext& c) {
  const Experiment2Result r =
      run_experiment2(experiment2_spec(c.quick()), c.progress_for("exp2", ""));
  return experiment2_section(r, c);
}

ReportSection run_sweep(ExperimentContext& c) {
  const SweepResult r =
      run_threshold_sweep(c.texture(), sweep_spec(c.quick()), c.progress_for("sweep", ""));
  return sweep_section(r, c);
}

ReportSection run_costs(ExperimentContext& c) {
  const CostSweepResult r =
      run_cost_sweep(c.texture(), cost_sweep_spec(c.quick()), c.progress_for("costs", ""));
  return cost_sweep_section(r, c);
}

ReportSection run_reprojection(ExperimentContext& c) {
  const ReprojectionResult r =
      run_reprojection_experiment(reprojection_spec(c.quick()), c.progress_for("reprojection", ""));
  return reprojection_section(r, c);
}

ReportSection run_policies_comparison(ExperimentContext& c) {
  const PoliciesResult r = run_policies_experiment(c.texture(), policies_spec(c.quick()),
                                                   c.progress_for("policies", ""));
  return policies_section(r, c);
}

ReportSection run_sampling(ExperimentContext& c) {
  const SamplingComparison r =
      compare_samplings(make_layer(make_fabric_texture()), sampling_spec(c.quick()));
  for (const std::string& line : sampling_summary_lines(r)) c.progress("sampling", line);
  return sampling_section(r, c);
}

ReportSection run_visible_warp(ExperimentContext& c) {
  const VisibleWarpResult r =
      run_visible_warp_experiment(visible_warp_spec(c.quick()), c.progress_for("visible-warp", ""));
  for (const std::string& line : visible_warp_summary_lines(r)) c.progress("visible-warp", line);
  return visible_warp_section(r, c);
}

const std::vector<Experiment>& experiments() {
  static const std::vector<Experiment> list = {
      {"exp1", "Experiment 1 (6.4, 6.5)", run_exp1},
      {"delta", "Delta comparison (6.3)", run_delta},
      {"warp", "warp timing (A.2)", run_warp},
      {"exp2", "Experiment 2 (6.6, 6.7)", run_exp2},
      {"sweep", "threshold sweep", run_sweep},
      {"costs", "when reuse pays (re-render cost sweep)", run_costs},
      {"policies", "rival reuse policies side by side", run_policies_comparison},
      {"scene-shifting", "scene shifting (chapter 3)", scene_shifting_section},
      {"reprojection", "today's reprojection beside optic flow", run_reprojection},
      {"sampling", "mipmap against bilinear on a receding plane (7.5.5)", run_sampling},
      {"visible-warp", "warping what shows: whole against visible-only warps (7.5.3)",
       run_visible_warp},
  };
  return list;
}

bool selected(const ExperimentsOptions& options, const std::string& name) {
  if (options.only.empty()) return true;
  for (const std::string& n : options.only) {
    if (n == name) return true;
  }
  return false;
}

ReportSection about_section(const ExperimentsOptions& options, const MachineInfo& machine,
                            const std::vector<std::string>& ran, double seconds) {
  ReportSection s;
  s.id = "about";
  s.title = "About this run";
  std::string list;
  for (const std::string& n : ran) list += (list.empty() ? "" : ", ") + n;
  s.paragraph(std::string(options.quick ? "A quick run (--quick): short versions of every "
                                          "experiment; its timings are indicative only. "
                                        : "A full run. ") +
              "Experiments: " + list + ". Total time " + fixed_seconds(seconds) + ".");
  s.paragraph("To reproduce, run under an X display (xvfb-run -a on a headless machine):");
  s.code(options.command_line);
  ReportTable t;
  t.caption = "Machine and build";
  t.header = {"", ""};
  for (const auto& [label, value] : machine_facts(machine)) t.rows.push_back({label, value});
  s.table(t);
  s.paragraph(
      "Published figures come from the dissertation's chapter 6 and appendix A.2, "
      "measured on a 132 MHz R4600 SGI Indy. Timings depend on the machine and its load; "
      "level counts, pixel counts and errors do not. Every table puts the published "
      "figure beside oflab's and gives a reading generated from the numbers.");
  return s;
}

}  // namespace

const std::vector<std::string>& experiment_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const Experiment& e : experiments()) n.push_back(e.name);
    return n;
  }();
  return names;
}

ExperimentContext::ExperimentContext(std::string out_dir, bool quick, std::ostream* progress)
    : out_dir_(std::move(out_dir)),
      quick_(quick),
      progress_(progress),
      start_(std::chrono::steady_clock::now()) {}

const Layer& ExperimentContext::texture() const {
  if (texture_.empty()) texture_ = make_layer(read_image(default_texture_path()));
  return texture_;
}

void ExperimentContext::progress(const std::string& experiment, const std::string& line) const {
  if (!progress_) return;
  const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  *progress_ << "experiments [" << std::fixed << std::setprecision(1) << std::setw(6) << t << " s] "
             << experiment << ": " << line << "\n"
             << std::flush;
}

std::function<void(const std::string&)> ExperimentContext::progress_for(
    const std::string& experiment, const std::string& prefix) const {
  return
      [this, experiment, prefix](const std::string& line) { progress(experiment, prefix + line); };
}

ReportFigure ExperimentContext::add_chart(const std::string& name, const Chart& chart,
                                          const std::string& caption) {
  const std::string png = "charts/" + name + ".png";
  const std::string csv = "data/" + name + ".csv";
  write_chart_png(chart, (fs::path(out_dir_) / png).string());
  std::ostringstream out;
  write_chart_csv(chart, out);
  write_file_inside((fs::path(out_dir_) / csv).string(), out.str(), csv);
  ++charts_;
  return {png, csv, caption};
}

ExperimentsOutcome run_experiments(const ExperimentsOptions& options, std::ostream& progress) {
  const auto start = std::chrono::steady_clock::now();
  if (const std::string problem = chart_display_problem(); !problem.empty())
    throw ChartError(problem);
  for (const char* sub : {"charts", "data"})
    fs::create_directories(fs::path(options.out_dir) / sub);
  ExperimentContext context(options.out_dir, options.quick, &progress);
  context.set_video_format(options.video_format);
  const MachineInfo machine = collect_machine_info();
  ExperimentsOutcome outcome;
  outcome.report.title = "oflab experiments: the dissertation's results beside oflab's";
  std::vector<std::string> ran;
  for (const Experiment& e : experiments()) {
    if (!selected(options, e.name)) continue;
    context.progress(e.name, std::string("starting ") + e.title);
    outcome.report.sections.push_back(e.run(context));
    ran.push_back(e.name);
  }
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  outcome.report.sections.insert(outcome.report.sections.begin(),
                                 about_section(options, machine, ran, outcome.seconds));
  write_report(outcome.report, options.out_dir);
  outcome.charts = context.charts_written();
  context.progress("report", "wrote report.html and report.md");
  return outcome;
}

}  // namespace oflab
