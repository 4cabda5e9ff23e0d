// The threshold study on the page (manual/study.md, manual/web.md): the desktop window's loop
// (session/study/trial_clips.h TrialRunner) behind the page's study panel. The page opens a
// study (a shipped name or a file's text), plays each request's two clips from clip_frame
// on requestAnimationFrame, and answers; a simulated observer runs the same loop headlessly.
// Methods return "" or the error as one line, and change nothing on error. Plain C++.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "study/trial_clips.h"

namespace oflab {

class WebStudy {
 public:
  // The shipped studies as a JSON array of {name, title, description, method, trials,
  // conditions (names)}.
  static std::string shipped_json();

  // Opens `name` (a shipped study) or, when `file_text` is not empty, the study file's text
  // (read as a file called `name`) with `method` ("" the study's) and `seed` (< 0 the
  // study's): plays its ladders and draws the first request.
  std::string open(const std::string& name, const std::string& file_text, const std::string& method,
                   double seed);
  bool is_open() const { return runner_ != nullptr; }
  bool finished() const { return !runner_ || runner_->finished(); }
  // The request on screen as JSON: {condition (its name), answered (trials answered, late
  // ones not counted), total, late (presentations late so far)}; which clip is distorted is
  // left out (the page must not know). "{}" when none.
  std::string request_json() const;
  // Frames per clip, their width and height.
  int clip_length() const;
  // Clip `clip` (1 or 2) frame `frame`'s RGBA bytes (opaque, kClipWidth x kClipHeight),
  // valid until the next call. Precondition: an open, unfinished study; 0 <= frame <
  // clip_length().
  const std::vector<Pixel>& clip_frame(int clip, int frame);
  // The observer named clip `chosen` (1, 2) as distorted; `late`: a frame was late.
  std::string answer(int chosen, bool late);
  // A simulated observer of threshold `threshold_px` (the study's assumed slope and lapse,
  // seeded by the study's seed as opened) answers the rest of the study.
  std::string simulate(double threshold_px);
  // The trials as the per-trial CSV's text, answered by `observer` on a screen of `ppi`.
  std::string csv(const std::string& observer, double ppi) const;
  // The analysis of those rows (session/study/study_analysis.h, the default settings) as a
  // JSON array of threshold_result_json objects, as `oflab-cli study analyse --json` gives.
  std::string results_json(const std::string& observer, double ppi) const;
  // The class view: the per-trial CSV files in `files_json` (a JSON array of {name, text})
  // analysed together as `oflab-cli study analyse` does (a row per observer and condition,
  // then the class's pooled rows), with the study they come from (study_of_rows), which the
  // results' plot and curve() then use. JSON {"study": study_json, "results": [...]}, or
  // {"problem": the reader's message naming the file, the line and the column}.
  std::string class_results_json(const std::string& files_json);
  // The psychometric function (session/study/psychometric.h) with threshold `threshold_px`
  // and the shown study's assumed slope and lapse (the open study, or the class files'):
  // the proportion correct at `n` (2..1000) errors log-spaced over its error range. Empty
  // when no study is shown.
  std::vector<double> curve(double threshold_px, int n) const;
  // The open study as JSON: {name, title, min_px, max_px, assumed_slope, assumed_lapse,
  // conditions: [names]}; "{}" when none.
  std::string study_json() const;

 private:
  std::unique_ptr<TrialRunner> runner_;
  std::uint64_t seed_ = 0;
  std::unique_ptr<Study> shown_;  // the study of the results shown
};

}  // namespace oflab
