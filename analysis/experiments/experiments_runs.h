// Measured engine runs for the experiments: a script played under several engine
// settings, each interleaved frame by frame with the re-render baseline so that both see
// the same machine load, timed as `oflab-cli animate` times (analysis/runs/run_driver.h: an
// untimed warm-up pass, then per-frame medians over the timed passes). Level choices,
// pixel counts and errors are deterministic and taken from the first pass.
#pragma once

#include <array>
#include <functional>
#include <string>
#include <vector>

#include "runs/source_kinds.h"
#include "runs/statistics.h"

namespace oflab {

struct RunSpec {
  int max_frames = -1;        // play at most this many frames (-1: the whole script)
  int repetitions = 1;        // timed passes (>= 1); timings are medians over these
  bool measure_psnr = false;  // keep the PSNR against the exact render (else NaN)
};

struct MeasuredRun {
  EngineSettings settings;
  std::vector<FrameReport> reports;  // first repetition
  std::vector<double> psnr_db;       // per frame; NaN when not measured or not visible
  std::vector<double> frame_ms;      // per frame: median over the timed passes
  // Per frame: the re-render baseline interleaved with this run, median over the passes.
  std::vector<double> baseline_frame_ms;
  RunSummary summary;  // of the run driver: time_ms = sum of frame_ms, baseline_time_ms =
                       // sum of baseline_frame_ms, time_saved, pixels, errors, PSNR
};

// Plays `script` under each of `settings` in turn through the plane's source kind, with
// the re-render baseline interleaved, a warm-up pass and spec.repetitions timed passes.
// `progress` (may be empty) receives a short line before each setting. Returns one
// MeasuredRun per setting, in order.
std::vector<MeasuredRun> measure_interleaved(
    const MotionScript& script, const Layer& texture, const std::vector<EngineSettings>& settings,
    const RunSpec& spec, const std::function<void(const std::string&)>& progress);

// One shipped script measured under several settings and the re-render baseline.
struct ScriptRuns {
  std::string script;
  std::vector<MeasuredRun> runs;  // one per setting, in order
  MeasuredRun baseline;           // re-render mode, default settings
};

// Measures each shipped script named in `scripts` (datasets/scripts) under `settings` and
// the re-render baseline through measure_interleaved; `progress` lines are prefixed with
// the script's name. Throws ScriptError or std::runtime_error for a missing script.
std::vector<ScriptRuns> measure_scripts(const std::vector<std::string>& scripts,
                                        const Layer& texture, std::vector<EngineSettings> settings,
                                        const RunSpec& spec,
                                        const std::function<void(const std::string&)>& progress);

// 1 - time / baseline time, over the same frames (sums of the per-frame medians of the run
// and of the re-render interleaved with it); NaN without a baseline time.
double time_saved(const MeasuredRun& run);
// 1 - pixels written / baseline pixels written.
double work_saved(const MeasuredRun& run, const MeasuredRun& baseline);

// Percent of frames at each level over frames 1..N-1: frame 0 is the initial render in
// every mode and the dissertation's percentages describe the updates after it.
std::array<double, kLevelCount> level_percent_after_first(const MeasuredRun& run);

// What the frames after the first at `level` cost relative to re-rendering the same frames:
// sum of run.frame_ms over them / sum of run.baseline_frame_ms over them. NaN if there is
// none.
double relative_level_cost(const MeasuredRun& run, Level level);

// Median over the frames after the first of each term's per-frame flow measure (pixels),
// and of their sum (index kTermCount).
std::array<double, kTermCount + 1> median_flow_px(const MeasuredRun& run);

// Re-renders after frame 0 whose note names the sampling limit.
int sampling_limit_rerenders(const MeasuredRun& run);

// One clause describing how a level mix differs from a reference mix, in percentage
// points: "level mix within 5 points" or e.g. "more translate (+24), fewer none (-26)"
// (the two largest differences of 5 points or more).
std::string level_mix_reading(const std::array<double, kLevelCount>& published,
                              const std::array<double, kLevelCount>& measured);

// A table header: `first`, one column per level titled level_title ("none" .. "re-render"),
// then `rest`.
std::vector<std::string> level_header(const std::string& first,
                                      const std::vector<std::string>& rest);

// Number formatting for report tables: fixed decimals; "n/a" for non-finite values.
std::string fixed(double value, int decimals);
std::string percent(double fraction, int decimals = 1);  // 0.123 -> "12.3%"
// "1 repetition", "3 repetitions": the count and the noun, plural with an "s" unless one.
std::string count_of(int count, const std::string& noun);
// With an explicit sign; a value that rounds to zero is "+0.0" (never "-0.0").
std::string signed_fixed(double value, int decimals);

}  // namespace oflab
