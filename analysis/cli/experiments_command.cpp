// `oflab-cli experiments`: runs the dissertation's experiments and writes the report
// (analysis/experiments/experiments.h, manual/experiments.md).
#include <algorithm>
#include <filesystem>
#include <ostream>

#include "cli/cli_args.h"
#include "cli/commands.h"
#include "experiments/experiments.h"
#include "formats/video_file.h"
#include "report/charts.h"

namespace oflab {
namespace {

namespace fs = std::filesystem;

constexpr const char* kDefaultOutDir = "oflab-experiments";

// Takes "--only NAME..." out of `args` (every following argument not starting with "--",
// commas also separate names) and checks the names.
std::vector<std::string> take_only(CommandArgs& args) {
  std::vector<std::string> names;
  for (size_t i = 0; i < args.size(); ++i) {
    if (args[i] != "--only") continue;
    if (!names.empty()) throw UsageError("--only: given more than once");
    size_t end = i + 1;
    for (; end < args.size() && args[end].rfind("--", 0) != 0; ++end) {
      std::string list = args[end];
      for (size_t start = 0; start <= list.size();) {
        const size_t comma = std::min(list.find(',', start), list.size());
        if (comma > start) names.push_back(list.substr(start, comma - start));
        start = comma + 1;
      }
    }
    if (names.empty()) throw UsageError("--only: expects at least one experiment name");
    args.erase(args.begin() + static_cast<std::ptrdiff_t>(i),
               args.begin() + static_cast<std::ptrdiff_t>(end));
    --i;
  }
  const std::vector<std::string>& known = experiment_names();
  for (const std::string& n : names) {
    if (std::find(known.begin(), known.end(), n) == known.end()) {
      std::string list;
      for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
      throw UsageError("--only: '" + n + "' is not one of " + list);
    }
  }
  return names;
}

// --videos mp4|gif|ogv: the video format of Experiment 1's runs; empty without it. Throws
// UsageError for another format or when --only leaves Experiment 1 out.
std::string read_videos_option(const CliArgs& a, const std::vector<std::string>& only) {
  if (!a.has("--videos")) return "";
  const std::string format = a.values("--videos").at(0);
  if (format != "mp4" && format != "gif" && format != "ogv") {
    throw UsageError("--videos: '" + format + "' is not one of " + video_format_list());
  }
  if (!only.empty() && std::find(only.begin(), only.end(), "exp1") == only.end()) {
    throw UsageError("--videos: the videos are of Experiment 1's runs; --only leaves out exp1");
  }
  return format;
}

std::string command_line(const CommandArgs& original) {
  std::string line = "oflab-cli experiments";
  for (const std::string& a : original) line += " " + a;
  return line;
}

}  // namespace

int run_experiments_command(const CommandArgs& original_args, std::ostream& out,
                            std::ostream& err) {
  try {
    CommandArgs args = original_args;
    ExperimentsOptions options;
    options.only = take_only(args);
    const CliArgs a(args, {{"--out", 1}, {"--quick", 0}, {"--force", 0}, {"--videos", 1}});
    options.out_dir = a.text_or("--out", kDefaultOutDir);
    options.quick = a.has("--quick");
    options.video_format = read_videos_option(a, options.only);
    options.command_line = command_line(original_args);
    if (const std::string problem = chart_display_problem(); !problem.empty()) {
      throw ChartError(problem);
    }
    const std::shared_ptr<AtomicDir> dir = open_out_dir(options.out_dir, a.has("--force"));
    ExperimentsOptions into = options;
    into.out_dir = dir->path();  // the report is written whole, then renamed into place
    const ExperimentsOutcome outcome = run_experiments(into, err);
    dir->commit();
    out << "wrote " << (fs::path(options.out_dir) / "report.html").string() << " and report.md ("
        << outcome.charts << " charts) in " << static_cast<int>(outcome.seconds + 0.5) << " s\n";
    return 0;
  } catch (const UsageError&) {
    throw;  // run_cli reports it (exit code 2); not a failure while running
  } catch (const ChartError& e) {
    err << "oflab-cli experiments: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    err << "oflab-cli experiments: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace oflab
