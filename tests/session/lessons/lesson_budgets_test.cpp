// The lesson budgets (session/lessons/lessons.h, core/flow/limits.h kLessonSteps and
// kLessonFrames): a lesson file at a budget reads, one a step or a frame over it is refused
// when it is read, naming the file, the step and the limit; the shipped lessons are within
// both.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "flow/limits.h"
#include "lesson_read_error.h"
#include "lessons/lessons.h"
#include "state/window_state_file.h"

namespace oflab {
namespace {

namespace fs = std::filesystem;

// Reads a lesson "x.json" with the top-level fields `top` (JSON text, ending in a comma or
// empty) and the steps `steps` (JSON text of the list's items); the error, "" when read.
std::string error_of_lesson(const std::string& top, const std::string& steps) {
  return test::lesson_read_error("budgets", top + R"( "steps": [)" + steps + "]}");
}

// `n` steps, each `step` (JSON text of one step).
std::string repeated(const std::string& step, int n) {
  std::string text;
  for (int i = 0; i < n; ++i) text += (i ? ", " : "") + step;
  return text;
}

TEST(LessonBudgets, SixtyFourStepsReadAndSixtyFiveAreRefusedAtTheSixtyFifth) {
  EXPECT_EQ(error_of_lesson("", repeated(R"({"say": "s"})", 64)), "");
  EXPECT_EQ(error_of_lesson("", repeated(R"({"say": "s"})", 65)),
            "x.json: step 65: the lesson has 65 steps, more than 64 (the lesson steps limit)");
}

// The frames played add up in playing order: the lesson's play, then each step's frame
// (reached by playing forward) and play. 1000 in all read; one more is refused at the step
// and the field that passes the budget.
TEST(LessonBudgets, FramesPlayedAddUpOverTheLessonAndItsSteps) {
  const std::string steps = R"({"say": "a", "do": {"frame": 300, "play": 200}},
                               {"say": "b", "do": {"play": 400}})";
  EXPECT_EQ(error_of_lesson(R"("play": 100,)", steps), "");
  EXPECT_EQ(error_of_lesson(R"("play": 101,)", steps),
            "x.json: step 2: field 'play': the lesson plays 1001 frames up to here, more than "
            "1000 (the lesson frames limit)");
  EXPECT_EQ(error_of_lesson(R"("play": 100,)", R"({"say": "a", "do": {"frame": 901}})"),
            "x.json: step 1: field 'frame': the lesson plays 1001 frames up to here, more than "
            "1000 (the lesson frames limit)");
  EXPECT_EQ(error_of_lesson(R"("play": 1001,)", ""),
            "x.json: field 'play': the lesson plays 1001 frames up to here, more than 1000 (the "
            "lesson frames limit)");
}

TEST(LessonBudgets, EveryShippedLessonIsWithinBothBudgets) {
  for (const Lesson& lesson : lessons()) {
    int played = lesson.play;
    for (const LessonStep& step : lesson.steps) played += std::max(step.frame, 0) + step.play;
    EXPECT_TRUE(limits::kLessonFrames.allows(played)) << lesson.name << ": " << played;
    EXPECT_TRUE(limits::kLessonSteps.allows(double(lesson.steps.size()))) << lesson.name;
  }
}

}  // namespace
}  // namespace oflab
