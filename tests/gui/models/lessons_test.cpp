// Lessons are files: every shipped lesson reads, the menu order is theirs, and the manual's
// list of lessons is exactly the files (a lesson in the manual without a file, or a file
// the manual misses, fails here).
#include "lessons/lessons.h"

#include <gtest/gtest.h>

#include <QTemporaryDir>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <set>

#include "formats/datasets.h"
#include "state/window_state_file.h"

namespace oflab {
namespace {

std::string error_of(const std::string& path) {
  try {
    read_lesson_file(path);
  } catch (const SessionError& e) {
    return e.what();
  }
  return "";
}

TEST(Lessons, EveryShippedLessonFileIsALessonInTeachingOrder) {
  const std::vector<std::string> files = shipped_names("lessons");
  ASSERT_EQ(lessons().size(), files.size());
  EXPECT_EQ(files.size(), 19u);
  std::set<std::string> names;
  for (size_t i = 0; i < lessons().size(); ++i) {
    const Lesson& lesson = lessons()[i];
    names.insert(lesson.name);
    EXPECT_EQ(lesson.state.lesson, lesson.name);
    EXPECT_EQ(window_state_problem(lesson.state), "") << lesson.name;
    EXPECT_FALSE(lesson.narrative.empty()) << lesson.name;
    if (i > 0) EXPECT_LT(lessons()[i - 1].order, lesson.order);
  }
  EXPECT_EQ(names, std::set<std::string>(files.begin(), files.end()));
  EXPECT_EQ(lessons().front().name, "flow-of-a-plane");
  EXPECT_EQ(find_lesson("flow-vs-talisman")->state.compared,
            (std::vector<std::string>{"perspective", "talisman"}));
  EXPECT_EQ(find_lesson("hierarchical-cache")->state.compared,
            (std::vector<std::string>{"perspective", "hierarchical-cache"}));
}

// manual/lessons.md has one section "## Title (`name`)" per lesson file, with its title.
TEST(Lessons, TheManualListsExactlyTheLessonFiles) {
  std::ifstream in(OFLAB_SOURCE_DIR "/manual/lessons.md");
  ASSERT_TRUE(in) << "manual/lessons.md";
  const std::regex heading(R"(^## (.+) \(`([a-z0-9-]+)`\)\s*$)");
  std::set<std::string> in_manual;
  std::string line;
  while (std::getline(in, line)) {
    std::smatch m;
    if (!std::regex_match(line, m, heading)) continue;
    in_manual.insert(m[2]);
    const Lesson* lesson = find_lesson(m[2]);
    EXPECT_NE(lesson, nullptr) << "manual/lessons.md names '" << m[2]
                               << "', which is not a file in datasets/lessons/";
    if (lesson) EXPECT_EQ(lesson->title, m[1].str()) << m[2];
  }
  for (const Lesson& lesson : lessons()) {
    EXPECT_EQ(in_manual.count(lesson.name), 1u) << "manual/lessons.md has no section \"## "
                                                << lesson.title << " (`" << lesson.name << "`)\"";
  }
}

// manual/lessons.md shows every step of every lesson with its picture, made by
// `oflab --check-lesson --step-shots` (tools/make-screenshots.sh), and the picture exists.
TEST(Lessons, TheManualShowsAPictureOfEveryStep) {
  std::ifstream in(OFLAB_SOURCE_DIR "/manual/lessons.md");
  ASSERT_TRUE(in) << "manual/lessons.md";
  const std::string manual((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const Lesson& lesson : lessons()) {
    for (size_t k = 1; k <= lesson.steps.size(); ++k) {
      const std::string image =
          "images/lesson-" + lesson.name + "-step-" + std::to_string(k) + ".png";
      EXPECT_NE(manual.find("(" + image + ")"), std::string::npos)
          << "manual/lessons.md does not show " << image;
      EXPECT_TRUE(std::filesystem::is_regular_file(OFLAB_SOURCE_DIR "/manual/" + image))
          << "manual/" << image << " is missing: run tools/make-screenshots.sh";
    }
  }
}

TEST(Lessons, ABrokenLessonFileIsRefusedNamingTheFileAndField) {
  QTemporaryDir dir;
  const auto write = [&](const std::string& name, const std::string& text) {
    const std::string path = dir.filePath(QString::fromStdString(name)).toStdString();
    std::ofstream(path) << text;
    return path;
  };
  const std::string head =
      R"({"format": "oflab-lesson", "version": 1, "order": 3, "title": "T", "narrative": "N", )";
  EXPECT_EQ(read_lesson_file(write("ok.json", head + R"("name": "ok", "state": {}})")).state.lesson,
            "ok");
  EXPECT_NE(error_of(write("a.json", head + R"("name": "b", "state": {}})")).find("field 'name'"),
            std::string::npos);
  EXPECT_NE(error_of(write("c.json", head + R"("name": "c", "state": {}, "quiz": []})"))
                .find("field 'quiz': unknown field"),
            std::string::npos);
  const std::string bad_view = error_of(write(
      "d.json", head + R"("name": "d", "state": {"animation": {"thresholds": [1, 1, 1, -1]}}})"));
  EXPECT_EQ(bad_view, "d.json: animation: field 'thresholds': threshold -1 is outside 0..100 px");
}

}  // namespace
}  // namespace oflab
