// Long work in the window can be stopped (gui/app/main_window.h play_frames,
// cancel_long_work): Escape and closing the window stop frames playing, a lesson step's
// frames (what Page Down performs) included, and an exception escaping an event handler
// (app/app_runner.h GuardedApplication) becomes the window's message, never the end of the
// program. The test program runs under GuardedApplication, as oflab does.
#include <QApplication>
#include <QTemporaryDir>
#include <QTimer>
#include <fstream>
#include <new>
#include <stdexcept>

#include "lessons/lessons.h"
#include "models/scene_model.h"
#include "window_fixture.h"

namespace oflab {
namespace {

using LongWorkTest = test::WindowTest;

// Escape pressed while frames play stops them after the frame drawn; the frame stays. The
// control: once cleared, frames play to the end.
TEST_F(LongWorkTest, EscapeStopsFramesPlaying) {
  QTimer::singleShot(300, &window(), [this] { QTest::keyClick(&window(), Qt::Key_Escape); });
  window().play_frames(1000);
  const int stopped = window().model()->scene()->frame();
  EXPECT_TRUE(window().cancelled());
  EXPECT_GT(stopped, 0);
  EXPECT_LT(stopped, 1000);
  window().clear_cancel();
  window().play_frames(3);
  EXPECT_EQ(window().model()->scene()->frame(), stopped + 3);
}

// A lesson step that plays 1000 frames (what Page Down performs): the frames play with
// events processed, so Escape stops them; the step shows with the frame reached.
TEST_F(LongWorkTest, EscapeStopsTheFramesOfALessonStep) {
  QTemporaryDir dir;
  const std::string path = dir.filePath("long-step.json").toStdString();
  std::ofstream(path) << R"({"format": "oflab-lesson", "version": 1, "name": "long-step",
    "order": 1, "title": "Long step", "narrative": "n", "state": {},
    "steps": [{"say": "a", "do": {"play": 1000}}, {"say": "b"}]})";
  const Lesson& lesson = add_lesson(read_lesson_file(path));
  ASSERT_TRUE(window().go_to_lesson_step(lesson, 0));
  QTimer::singleShot(300, &window(), [this] { QTest::keyClick(&window(), Qt::Key_Escape); });
  EXPECT_TRUE(window().perform_lesson_step(lesson, 1));
  EXPECT_EQ(window().model()->lesson_step(), 1);
  EXPECT_GT(window().model()->scene()->frame(), 0);
  EXPECT_LT(window().model()->scene()->frame(), 1000);
  EXPECT_FALSE(window().playing_frames());
}

// Closing the window stops frames playing: nothing goes on after it.
TEST_F(LongWorkTest, ClosingTheWindowStopsFramesPlaying) {
  QTimer::singleShot(300, &window(), [this] { window().close(); });
  window().play_frames(1000);
  EXPECT_LT(window().model()->scene()->frame(), 1000);
  EXPECT_TRUE(window().cancelled());
}

// An engine running out of memory in an event handler (here a timer's, as live play's) is
// shown in the window's banner with its frame, playing stops, and the window stays usable.
TEST_F(LongWorkTest, AnExceptionInAnEventHandlerBecomesTheWindowsMessage) {
  window().play_frames(2);
  window().model()->set_playing(true);
  QTimer::singleShot(0, &window(), [] { throw std::bad_alloc(); });
  QTest::qWait(100);
  EXPECT_TRUE(window().message().contains("out of memory at frame"))
      << window().message().toStdString();
  EXPECT_FALSE(window().model()->playing());
  QTimer::singleShot(0, &window(), [] { throw std::runtime_error("layer too large"); });
  QTest::qWait(100);
  EXPECT_TRUE(window().message().contains("the engine failed at frame"));
  EXPECT_TRUE(window().message().contains("layer too large"));
  window().clear_cancel();
  const int frame = window().model()->scene()->frame();
  window().play_frames(2);  // and it still plays
  EXPECT_EQ(window().model()->scene()->frame(), frame + 2);
}

}  // namespace
}  // namespace oflab
