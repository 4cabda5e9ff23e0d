// The run of what the animation and analysis views play: a source (player/animation_sources.h)
// with the engine settings, played by its Animator (core/engine/animator.h) up to the plane
// panel's frame, with one record per frame. Every source plays through the same Animator
// calls. The desktop's animation model (gui/models/animation_model.h) and the headless lab
// (player/lab.h) hold one. Plain C++.
//
// Frames. The panel's frame is the frame shown: the run follows it on demand, so the engine
// runs only while someone asks. Seeking forward advances the animator frame by frame;
// seeking backward restarts from frame 0 (animators keep no undo state), so every frame shown
// is exactly what an uninterrupted run shows.
#pragma once

#include <iosfwd>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "engine/animator.h"
#include "player/animation_sources.h"

namespace oflab {

class PlanePanel;

class RunPlayer {
 public:
  // Plays the panel's plane with default settings. `panel` must outlive the player.
  explicit RunPlayer(PlanePanel* panel);
  ~RunPlayer();

  PlanePanel& panel() const { return *panel_; }
  const SourceChoice& source() const { return source_; }
  const AnimationSourceKind& source_kind() const;
  const EngineSettings& settings() const { return settings_; }

  // "" when `choice` can be played with `settings` (its files read, its animator made and
  // started), else one line saying why not. Changes nothing.
  std::string source_problem(const SourceChoice& choice, const EngineSettings& settings) const;

  // Plays a source from frame 0: the panel goes to frame 0, and its loop becomes the
  // source's length unless the source follows the panel. "" or why not (nothing changes).
  std::string set_source(const SourceChoice& choice);
  // Applies engine settings (the run restarts): "" or why not (a limit, content_problem, a
  // source that cannot be played with them), changing nothing.
  std::string set_settings(const EngineSettings& settings);
  // The panel's plane, motion or texture changed: a source that follows the panel restarts
  // when next read. Returns true when the run depends on the panel.
  bool panel_changed();

  // The animator at the panel's frame (built and advanced on demand); nullptr only when
  // nothing can be played.
  Animator* animator();
  // Why the last rebuild on demand in animator() failed ("" when it did not), once: the
  // front-end reports it.
  std::string take_problem() { return std::exchange(problem_, std::string()); }
  // Records of frames 0 .. animator()->frame(), in order; empty when nothing plays.
  const std::vector<AnimationFrame>& history();
  // The current frame's record. Precondition: animator() is not nullptr.
  const AnimationFrame& current() { return history().back(); }

  // Writes the per-frame CSV of the whole source (animation_sources.h write_csv).
  // Throws std::runtime_error or std::invalid_argument when the source cannot be played.
  void write_csv(std::ostream& out) const;

 private:
  std::string start(const SourceChoice& choice, const EngineSettings& settings,
                    std::unique_ptr<Animator>* animator, AnimationFrame* first) const;
  std::string rebuild(const SourceChoice& choice, const EngineSettings& settings);
  void seek(int frame);

  PlanePanel* panel_;
  SourceChoice source_;
  EngineSettings settings_;
  std::unique_ptr<Animator> animator_;
  std::vector<AnimationFrame> history_;
  bool stale_ = true;  // the panel's plane changed: rebuild before the next use
  std::string problem_;
};

// Percent of the drawn layers of `frame` that were not re-rendered (0 when none is drawn).
double approximated_percent(const AnimationFrame& frame);

// The error level `level` (0 none .. 3 perspective) would leave at `record`, pixels: the
// carried books plus this frame's flow over the terms it neglects (core/engine/decision.h
// neglected_error, the quantity choose_level tests against thresholds[level]); NaN for frame
// 0 and for frames that did not update exactly one layer or drew nothing. The analysis
// view's budget charts, on the desktop and on the page.
double level_budget_at(const AnimationFrame& record, int level);

}  // namespace oflab
