#include "player/run_player.h"

#include <cmath>

#include "engine/decision.h"
#include "player/plane_panel.h"
#include "player/stage_times.h"
#include "state/window_state.h"

namespace oflab {

double approximated_percent(const AnimationFrame& frame) {
  const int drawn = frame.drawn();
  if (drawn == 0) return 0.0;
  const int rerendered = frame.levels[static_cast<size_t>(Level::kRerender)];
  return 100.0 * (drawn - rerendered) / drawn;
}

double level_budget_at(const AnimationFrame& record, int level) {
  if (record.drawn() == 0 || record.layer_reports.size() != 1 || record.frame == 0) {
    return std::nan("");
  }
  const FrameReport& books = record.layer_reports.front();
  return neglected_error(books.carried, books.flow, Level(level));
}

RunPlayer::RunPlayer(PlanePanel* panel) : panel_(panel) {}

RunPlayer::~RunPlayer() = default;

const AnimationSourceKind& RunPlayer::source_kind() const {
  return *find_animation_source_kind(source_.kind);
}

std::string RunPlayer::start(const SourceChoice& choice, const EngineSettings& settings,
                             std::unique_ptr<Animator>* animator, AnimationFrame* first) const {
  const AnimationSourceKind* kind = find_animation_source_kind(choice.kind);
  if (!kind) {
    return "unknown source kind '" + choice.kind + "' (known: " + animation_source_kind_names() +
           ")";
  }
  try {
    *animator = kind->make(choice, *panel_, settings);
    *first = (*animator)->start();
  } catch (const std::exception& e) {  // unreadable files, sources that cannot be played
    return e.what();
  }
  return "";
}

std::string RunPlayer::source_problem(const SourceChoice& choice,
                                      const EngineSettings& settings) const {
  std::unique_ptr<Animator> animator;
  AnimationFrame first;
  return start(choice, settings, &animator, &first);
}

std::string RunPlayer::rebuild(const SourceChoice& choice, const EngineSettings& settings) {
  std::unique_ptr<Animator> animator;
  AnimationFrame first;
  const std::string problem = start(choice, settings, &animator, &first);
  if (!problem.empty()) return problem;
  animator_ = std::move(animator);
  history_.assign(1, first);
  source_ = choice;
  settings_ = settings;
  stale_ = false;
  return "";
}

std::string RunPlayer::set_source(const SourceChoice& choice) {
  const std::string problem = rebuild(choice, settings_);
  if (!problem.empty()) return problem;
  panel_->set_loop_override(source_kind().follows_scene_panel ? 0 : animator_->frame_count());
  panel_->set_frame(0);
  return "";
}

std::string RunPlayer::set_settings(const EngineSettings& settings) {
  const std::string limits_problem = settings_state_problem(settings);
  if (!limits_problem.empty()) return limits_problem;
  const std::string content = content_problem(settings.content);
  if (!content.empty()) return "content: " + content;
  return rebuild(source_, settings);
}

bool RunPlayer::panel_changed() {
  if (!source_kind().follows_scene_panel) return false;
  stale_ = true;
  return true;
}

Animator* RunPlayer::animator() {
  if (stale_ || !animator_) {
    const std::string problem = rebuild(source_, settings_);
    if (!problem.empty()) {
      problem_ = problem;
      return animator_.get();
    }
  }
  if (animator_) seek(panel_->frame() % animator_->frame_count());
  return animator_.get();
}

const std::vector<AnimationFrame>& RunPlayer::history() {
  static const std::vector<AnimationFrame> kNone;
  return animator() ? history_ : kNone;
}

void RunPlayer::seek(int frame) {
  const StageTimer timer(FrameStage::kEngine);
  if (frame < animator_->frame()) history_.assign(1, animator_->start());
  while (animator_->frame() < frame) history_.push_back(animator_->advance());
}

void RunPlayer::write_csv(std::ostream& out) const {
  source_kind().write_csv(source_, *panel_, settings_, out);
}

}  // namespace oflab
