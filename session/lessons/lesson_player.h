// The one lesson player: what showing a lesson's narrative or one of its steps does, as a
// teacher does it (the lesson's state, its frames played, then each step's actions in order:
// its state read over the previous one on the frame shown, its frame, its frames played).
// Every front-end plays lessons through it on its own stage: the desktop window
// (gui/app/main_window.h), the headless lab (player/lab.h, `oflab-cli lesson`), and the
// browser page (web/bindings.cpp), so a step shows the same state and frame everywhere.
// Plain C++.
#pragma once

#include <string>

#include "lessons/lessons.h"

namespace oflab {

// Where a lesson plays: a front-end's state with its frame clock.
class LessonStage {
 public:
  virtual ~LessonStage() = default;
  // The whole state shown now.
  virtual WindowState stage_state() const = 0;
  // Shows `state` whole: "" or why it was refused (nothing changed then).
  virtual std::string stage_apply(const WindowState& state) = 0;
  // Stops live play (the frame stays).
  virtual void stage_stop() = 0;
  // Goes to `frame` as the front-end's frame clock lands on it (player/plane_panel.h).
  virtual void stage_seek(int frame) = 0;
  // Frames in one loop of what plays now (player/plane_panel.h loop_frames): a step's frame
  // must be below it.
  virtual int stage_loop_frames() const = 0;
  // Plays `frames` frames, one at a time, as live play does.
  virtual void stage_play(int frames) = 0;
  // The lesson's step on screen is now `step` (0: its narrative).
  virtual void stage_set_step(int step) = 0;
};

// Performs step `step` (1 .. steps) of `lesson` on a stage showing step - 1: applies the
// step's state (if any) on the frame shown, not playing, with the stage's presentation mode;
// goes to its frame (if any); plays its frames. "" or why not, naming the lesson's file
// ("NAME.json: step K: problem"; "NAME.json: step K: field 'do.frame': 1000 is beyond the
// last frame, 89, of what plays" when the frame is not in the loop of what plays after the
// step's state); nothing is done for a step out of range (then "step K does not exist").
std::string perform_lesson_step(LessonStage& stage, const Lesson& lesson, int step);

// Shows `lesson` from its start up to step `step` (0: the narrative): its state with the
// stage's presentation mode (playing only at step 0 when the lesson plays and `live`), its
// frames played when it does not play live, then steps 1 .. step performed in order.
std::string go_to_lesson_step(LessonStage& stage, const Lesson& lesson, int step,
                              bool live = false);

}  // namespace oflab
