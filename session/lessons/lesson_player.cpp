#include "lessons/lesson_player.h"

namespace oflab {

std::string perform_lesson_step(LessonStage& stage, const Lesson& lesson, int step) {
  if (step < 1 || step > int(lesson.steps.size())) {
    return "lesson " + lesson.name + ": step " + std::to_string(step) + " does not exist";
  }
  const LessonStep& s = lesson.steps[size_t(step - 1)];
  if (s.has_state) {
    const WindowState shown = stage.stage_state();
    WindowState state = s.state;
    state.frame = shown.frame;
    state.playing = false;
    state.presentation = shown.presentation;
    const std::string problem = stage.stage_apply(state);
    if (!problem.empty()) {
      return "lesson " + lesson.name + ", step " + std::to_string(step) + ": " + problem;
    }
  }
  stage.stage_stop();
  if (s.frame >= 0) stage.stage_seek(s.frame);
  stage.stage_play(s.play);
  stage.stage_set_step(step);
  return "";
}

std::string go_to_lesson_step(LessonStage& stage, const Lesson& lesson, int step, bool live) {
  if (step < 0 || step > int(lesson.steps.size())) {
    return "lesson " + lesson.name + ": step " + std::to_string(step) + " does not exist";
  }
  WindowState state = lesson.state;
  state.playing = step == 0 && lesson.state.playing && live;
  state.presentation = stage.stage_state().presentation;  // the teacher's look stays
  const std::string problem = stage.stage_apply(state);
  if (!problem.empty()) return "lesson " + lesson.name + ": " + problem;
  if (!state.playing) stage.stage_play(lesson.play);
  for (int k = 1; k <= step; ++k) {
    const std::string step_problem = perform_lesson_step(stage, lesson, k);
    if (!step_problem.empty()) return step_problem;
  }
  return "";
}

}  // namespace oflab
