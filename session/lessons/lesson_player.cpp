#include "lessons/lesson_player.h"

namespace oflab {
namespace {

// Where a lesson's problems are: its file (the lesson's name is the file's stem), as the
// lesson reader names it.
std::string lesson_file(const Lesson& lesson) { return lesson.name + ".json"; }

}  // namespace

std::string perform_lesson_step(LessonStage& stage, const Lesson& lesson, int step) {
  if (step < 1 || step > int(lesson.steps.size())) {
    return lesson_file(lesson) + ": step " + std::to_string(step) + " does not exist";
  }
  const std::string where = lesson_file(lesson) + ": step " + std::to_string(step) + ": ";
  const LessonStep& s = lesson.steps[size_t(step - 1)];
  if (s.has_state) {
    const WindowState shown = stage.stage_state();
    WindowState state = s.state;
    state.frame = shown.frame;
    state.playing = false;
    state.presentation = shown.presentation;
    const std::string problem = stage.stage_apply(state);
    if (!problem.empty()) return where + problem;
  }
  const int loop = stage.stage_loop_frames();
  if (s.frame >= loop) {
    return where + "field 'do.frame': " + std::to_string(s.frame) + " is beyond the last frame, " +
           std::to_string(loop - 1) + ", of what plays";
  }
  stage.stage_stop();
  if (s.frame >= 0) stage.stage_seek(s.frame);
  stage.stage_play(s.play);
  stage.stage_set_step(step);
  return "";
}

std::string go_to_lesson_step(LessonStage& stage, const Lesson& lesson, int step, bool live) {
  if (step < 0 || step > int(lesson.steps.size())) {
    return lesson_file(lesson) + ": step " + std::to_string(step) + " does not exist";
  }
  WindowState state = lesson.state;
  state.playing = step == 0 && lesson.state.playing && live;
  state.presentation = stage.stage_state().presentation;  // the teacher's look stays
  const std::string problem = stage.stage_apply(state);
  if (!problem.empty()) return lesson_file(lesson) + ": " + problem;
  if (!state.playing) stage.stage_play(lesson.play);
  for (int k = 1; k <= step; ++k) {
    const std::string step_problem = perform_lesson_step(stage, lesson, k);
    if (!step_problem.empty()) return step_problem;
  }
  return "";
}

}  // namespace oflab
