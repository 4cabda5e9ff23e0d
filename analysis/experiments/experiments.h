// `oflab-cli experiments`: re-runs the dissertation's experiments (chapter 6 and appendix
// A.2) and writes a report that puts the published figures beside oflab's
// (manual/experiments.md). This header holds what the experiments share: the run's
// context (output directory, size of the run, progress) and the driver.
#pragma once

#include <chrono>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "image/layer.h"
#include "report/charts.h"
#include "report/report.h"

namespace oflab {

// The experiments --only accepts, in the order the report lists them:
// "exp1" (section 6.4, 6.5), "delta" (6.3), "warp" (appendix A.2), "exp2" (6.6, 6.7),
// "sweep" (thresholds 0.25..4 px, section 7.5.1's question), "costs" (time saved against
// the re-render's cost, break-even), "policies" (rival reuse policies side by side),
// "scene-shifting" (chapter 3), "reprojection" (today's reprojection beside optic flow),
// "sampling" (mipmap against bilinear on a receding plane, section 7.5.5), "visible-warp"
// (whole against visible-only warps on four cubes and the street, section 7.5.3).
const std::vector<std::string>& experiment_names();

// What an experiment needs while it runs. Files go to DIR/charts/NAME.png and
// DIR/data/NAME.csv; progress lines go to the progress stream (stderr for the CLI).
class ExperimentContext {
 public:
  ExperimentContext(std::string out_dir, bool quick, std::ostream* progress);

  bool quick() const { return quick_; }
  const std::string& out_dir() const { return out_dir_; }
  // The Experiment 1 texture: datasets/textures/butterfly.png (243 x 198).
  const Layer& texture() const;

  // One progress line, prefixed with the experiment's name and the elapsed time.
  void progress(const std::string& experiment, const std::string& line) const;
  // A progress callback bound to one experiment and a prefix, for measure_interleaved.
  std::function<void(const std::string&)> progress_for(const std::string& experiment,
                                                       const std::string& prefix) const;

  // Draws `chart` into charts/NAME.png, writes its numbers to data/NAME.csv and returns
  // the report figure. Throws ChartError or std::runtime_error naming the file.
  ReportFigure add_chart(const std::string& name, const Chart& chart, const std::string& caption);
  int charts_written() const { return charts_; }

  // The format of the videos of Experiment 1's runs ("mp4", "gif", "ogv", by
  // formats/video_file.h), written to DIR/videos; empty (the default) for none.
  const std::string& video_format() const { return video_format_; }
  void set_video_format(std::string format) { video_format_ = std::move(format); }

 private:
  std::string out_dir_;
  bool quick_ = false;
  std::ostream* progress_ = nullptr;
  std::chrono::steady_clock::time_point start_;
  mutable Layer texture_;
  int charts_ = 0;
  std::string video_format_;
};

struct ExperimentsOptions {
  std::string out_dir;
  std::vector<std::string> only;  // experiment names; empty runs them all
  bool quick = false;
  std::string video_format;  // --videos mp4|gif|ogv: Experiment 1's runs as videos; empty: none
  std::string command_line;  // as typed, for the report's "how to reproduce"
};

struct ExperimentsOutcome {
  Report report;
  double seconds = 0.0;
  int charts = 0;
};

// Runs the selected experiments, writes DIR/report.md, DIR/report.html, the charts and
// their CSVs. Preconditions: out_dir exists; every name in `only` is an experiment name.
// Throws ChartError (no display) or std::runtime_error (files) on failure.
ExperimentsOutcome run_experiments(const ExperimentsOptions& options, std::ostream& progress);

}  // namespace oflab
