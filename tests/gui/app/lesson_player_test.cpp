// The same lesson is the same lesson everywhere: every step of every shipped lesson shows
// the same state and frame in the desktop window as on the headless lab that
// `oflab-cli lesson state` plays (session/player/lab.h), both through the one lesson player
// (session/lessons/lesson_player.h). The browser page is held to the same states by
// tests/web/web_test.js. The desktop measures every claim kind of the registry.
#include "lessons/lesson_player.h"

#include <gtest/gtest.h>

#include <set>

#include "app/lesson_check.h"
#include "lessons/claim_kinds.h"
#include "player/engine_claims.h"
#include "player/lab.h"
#include "state/window_state_file.h"
#include "window_fixture.h"

namespace oflab::test {
namespace {

class LessonPlayerTest : public WindowTest {};

TEST_F(LessonPlayerTest, EveryStepOfEveryLessonShowsTheHeadlessLabsStateAndFrame) {
  window().set_external_clock(true);
  int parts = 0;
  for (const Lesson& lesson : lessons()) {
    Lab lab(shipped_default_texture());
    LabStage stage(&lab);
    ASSERT_TRUE(window().go_to_lesson_step(lesson, 0)) << lesson.name;
    ASSERT_EQ(go_to_lesson_step(stage, lesson, 0), "") << lesson.name;
    for (int step = 0; step <= int(lesson.steps.size()); ++step) {
      if (step > 0) {
        ASSERT_TRUE(window().perform_lesson_step(lesson, step)) << lesson.name << " " << step;
        ASSERT_EQ(perform_lesson_step(stage, lesson, step), "") << lesson.name << " " << step;
      }
      const WindowState desktop = window().model()->state();
      EXPECT_EQ(window_state_object(desktop).dump(1), window_state_object(lab.state()).dump(1))
          << lesson.name << ", step " << step;
      EXPECT_EQ(desktop.frame, lab.panel().frame()) << lesson.name << ", step " << step;
      ++parts;
    }
  }
  EXPECT_GE(parts, 14 + 30);
}

// Each kind of the registry is measured on the desktop: the engine's on the window's lab,
// the screen's by a measure of the window.
TEST(LessonClaimKinds, TheDesktopMeasuresEveryKindOfTheRegistry) {
  std::set<std::string> screen_kinds, screen_measures;
  for (const ClaimKind& kind : claim_kinds()) {
    if (kind.source == ClaimSource::kScreen) screen_kinds.insert(kind.name);
    if (kind.source == ClaimSource::kEngine) {
      EXPECT_EQ(engine_claim_measures().count(kind.name), 1u) << kind.name;
    }
  }
  for (const auto& [name, measure] : screen_claim_measures()) screen_measures.insert(name);
  EXPECT_EQ(screen_kinds, screen_measures);
}

}  // namespace
}  // namespace oflab::test
