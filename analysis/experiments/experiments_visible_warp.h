// Warping what shows (dissertation section 7.5.3, beyond its experiments): the scene engine
// warps each layer whole ("even if that polygon turns out to be partially or totally
// occluded") or only the pixels the frame will show (EngineSettings::warp_area,
// core/engine/engine.h; manual/animation.md "What of a layer is warped"). Both play the same
// viewer script through the same scene under the same reuse policy; the figures are the
// pixels the warps computed per frame (AnimationFrame::pixels_written - pixels_not_warped),
// their totals and the drop, every frame of the two compared byte for byte, and the median
// frame time of each. `oflab-cli experiments --only visible-warp` prints them; the report's
// chapter charts them.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "experiments/experiments.h"

namespace oflab {

// One scene walked by one viewer script, frames first .. first + frames - 1 of the script.
struct VisibleWarpSource {
  std::string scene;   // a shipped scene's name ("four-cubes")
  std::string viewer;  // a shipped viewer script's name ("compound")
  int first_frame = 0;
  int frames = -1;  // -1: to the script's end
};

struct VisibleWarpSpec {
  std::vector<VisibleWarpSource> sources;
  std::string policy = "perspective";  // the reuse policy (core/engine/reuse_policy.h)
  int camera_divisor = 1;              // every script's camera shrunk by this (small frames)
};

// Full: four cubes under compound (400 frames, 640 x 480) and the street under walk (150
// frames, 1280 x 720), whole scripts at their size; quick: the first 60 frames of compound
// and the whole walk, at half the size.
VisibleWarpSpec visible_warp_spec(bool quick);

// Per frame of one source, the whole warp's and the visible-only warp's figures.
struct VisibleWarpRun {
  VisibleWarpSource source;
  int width = 0, height = 0;          // the frames' size, pixels
  std::vector<std::int64_t> written;  // pixels written per frame (the same under both)
  std::vector<std::int64_t> whole;    // pixels the whole warp computed per frame
  std::vector<std::int64_t> visible;  // pixels the visible-only warp computed per frame
  std::vector<double> whole_ms;       // each frame's time (AnimationFrame::time_ms)
  std::vector<double> visible_ms;
  int differing_frames = 0;  // frames whose images differ in any byte

  std::int64_t total_whole() const;
  std::int64_t total_visible() const;
  // 1 - total_visible / total_whole (0 when the whole warp computed nothing).
  double drop() const;
};

struct VisibleWarpResult {
  VisibleWarpSpec spec;
  std::vector<VisibleWarpRun> runs;  // one per source, in order
};

// Plays every source of `spec` twice, whole and visible-only, with every other setting the
// default of `animate --scene`. Throws std::invalid_argument for an unknown policy, and what
// the scene and viewer-script readers throw for a file they cannot read.
VisibleWarpResult run_visible_warp_experiment(
    const VisibleWarpSpec& spec, const std::function<void(const std::string&)>& progress);

// One line per source: its pixels warped whole and visible-only, the drop and the frames
// compared (what `experiments --only visible-warp` prints as progress, and the section's text).
std::vector<std::string> visible_warp_summary_lines(const VisibleWarpResult& result);

// The report's chapter: the pixels warped per frame of each source, whole against
// visible-only (one panel per source, with the pixels left out), and the table of totals.
ReportSection visible_warp_section(const VisibleWarpResult& result, ExperimentContext& context);

}  // namespace oflab
