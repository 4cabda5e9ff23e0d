#include "experiments/experiments_runs.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "formats/datasets.h"
#include "formats/script_file.h"

namespace oflab {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

std::vector<MeasuredRun> measure_interleaved(
    const MotionScript& script, const Layer& texture, const std::vector<EngineSettings>& settings,
    const RunSpec& spec, const std::function<void(const std::string&)>& progress) {
  std::vector<MeasuredRun> runs;
  const SourceKind& plane = source_kind("plane");
  RunSource source;
  source.script = script;
  source.texture = texture.image;
  for (const EngineSettings& s : settings) {
    if (progress) {
      progress(std::string(s.policy->name) + " mode, " +
               (spec.max_frames > 0 ? "at most " + std::to_string(spec.max_frames)
                                    : std::to_string(script.frames.size())) +
               " frames, a warm-up and " + count_of(spec.repetitions, "timed repetition"));
    }
    source.settings.engine = s;
    PlayOptions options;  // the one timing of analysis/runs/run_driver.h, as the CLI's
    options.max_frames = spec.max_frames;
    options.warm_up = true;
    options.timing_repetitions = std::max(1, spec.repetitions);
    AnimationRun run = plane.play(source, options);
    MeasuredRun r;
    r.settings = s;
    for (const AnimationFrame& f : run.frames) {
      r.reports.push_back(f.layer_reports[0]);
      r.frame_ms.push_back(f.time_ms);
    }
    r.baseline_frame_ms = run.baseline_ms;
    r.psnr_db = spec.measure_psnr ? run.psnr_db : std::vector<double>(run.frames.size(), kNaN);
    r.summary = run.summary;
    runs.push_back(std::move(r));
  }
  return runs;
}

std::vector<ScriptRuns> measure_scripts(const std::vector<std::string>& scripts,
                                        const Layer& texture, std::vector<EngineSettings> settings,
                                        const RunSpec& spec,
                                        const std::function<void(const std::string&)>& progress) {
  EngineSettings baseline;
  baseline.policy = &reuse_policy("rerender");
  settings.push_back(baseline);
  std::vector<ScriptRuns> result;
  for (const std::string& name : scripts) {
    const MotionScript script = read_script_file(resolve_script_path(name));
    ScriptRuns r;
    r.script = name;
    r.runs = measure_interleaved(script, texture, settings, spec, [&](const std::string& line) {
      if (progress) progress(name + ": " + line);
    });
    r.baseline = std::move(r.runs.back());
    r.runs.pop_back();
    result.push_back(std::move(r));
  }
  return result;
}

double time_saved(const MeasuredRun& run) {
  return run.summary.baseline_time_ms > 0 ? run.summary.time_saved : kNaN;
}

double work_saved(const MeasuredRun& run, const MeasuredRun& baseline) {
  return baseline.summary.pixels > 0 ? 1.0 - static_cast<double>(run.summary.pixels) /
                                                 static_cast<double>(baseline.summary.pixels)
                                     : kNaN;
}

std::array<double, kLevelCount> level_percent_after_first(const MeasuredRun& run) {
  std::array<double, kLevelCount> percent{};
  const size_t n = run.reports.size();
  if (n < 2) return percent;
  for (size_t i = 1; i < n; ++i) percent[static_cast<int>(run.reports[i].level)] += 1.0;
  for (double& p : percent) p *= 100.0 / static_cast<double>(n - 1);
  return percent;
}

double relative_level_cost(const MeasuredRun& run, Level level) {
  double engine = 0.0, rerender = 0.0;
  int frames = 0;
  const size_t n =
      std::min({run.reports.size(), run.frame_ms.size(), run.baseline_frame_ms.size()});
  for (size_t i = 1; i < n; ++i) {
    if (run.reports[i].level != level) continue;
    engine += run.frame_ms[i];
    rerender += run.baseline_frame_ms[i];
    ++frames;
  }
  return frames > 0 && rerender > 0 ? engine / rerender : kNaN;
}

std::array<double, kTermCount + 1> median_flow_px(const MeasuredRun& run) {
  std::array<std::vector<double>, kTermCount + 1> values;
  for (size_t i = 1; i < run.reports.size(); ++i) {
    const FrameReport& r = run.reports[i];
    if (!r.visible) continue;
    double sum = 0.0;
    for (int t = 0; t < kTermCount; ++t) {
      values[t].push_back(r.flow[t]);
      sum += r.flow[t];
    }
    values[kTermCount].push_back(sum);
  }
  std::array<double, kTermCount + 1> medians{};
  for (int t = 0; t <= kTermCount; ++t) medians[t] = median_of(values[t]);
  return medians;
}

int sampling_limit_rerenders(const MeasuredRun& run) {
  int count = 0;
  for (size_t i = 1; i < run.reports.size(); ++i) {
    const FrameReport& r = run.reports[i];
    if (r.level == Level::kRerender && r.note.find("sampling limit") != std::string::npos) ++count;
  }
  return count;
}

std::string level_mix_reading(const std::array<double, kLevelCount>& published,
                              const std::array<double, kLevelCount>& measured) {
  std::array<int, kLevelCount> order{};
  for (int l = 0; l < kLevelCount; ++l) order[l] = l;
  std::array<double, kLevelCount> diff{};
  for (int l = 0; l < kLevelCount; ++l) diff[l] = measured[l] - published[l];
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return std::abs(diff[a]) > std::abs(diff[b]); });
  std::string text;
  for (int k = 0; k < 2; ++k) {
    const int l = order[k];
    if (std::abs(diff[l]) < 5.0) break;
    if (!text.empty()) text += ", ";
    text += std::string(diff[l] > 0 ? "more " : "fewer ") + level_title(Level(l)) + " (" +
            signed_fixed(diff[l], 0) + ")";
  }
  return text.empty() ? "level mix within 5 points" : text;
}

std::vector<std::string> level_header(const std::string& first,
                                      const std::vector<std::string>& rest) {
  std::vector<std::string> header = {first};
  for (int l = 0; l < kLevelCount; ++l) header.push_back(level_title(Level(l)));
  header.insert(header.end(), rest.begin(), rest.end());
  return header;
}

std::string fixed(double value, int decimals) {
  if (!std::isfinite(value)) return "n/a";
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(decimals);
  s << value;
  return s.str();
}

std::string count_of(int count, const std::string& noun) {
  return std::to_string(count) + " " + noun + (count == 1 ? "" : "s");
}

std::string signed_fixed(double value, int decimals) {
  if (!std::isfinite(value)) return "n/a";
  std::string text = fixed(value, decimals);
  if (text.find_first_not_of("-0.") == std::string::npos) text = fixed(0.0, decimals);
  return text[0] == '-' ? text : "+" + text;
}

std::string percent(double fraction, int decimals) {
  if (!std::isfinite(fraction)) return "n/a";
  return fixed(100.0 * fraction, decimals) + "%";
}

}  // namespace oflab
