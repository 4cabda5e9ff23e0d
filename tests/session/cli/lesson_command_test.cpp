// `oflab-cli lesson` (session/cli/lesson_command.h), run in process through oflab-cli's
// command table: the list, the state of a step as the headless lab shows it, the engine
// claims checked (exit 0, 1 for a false claim) and lesson files refused at read time (exit 2)
// naming the file, the claim and the field.
#include "cli/lesson_command.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "cli/cli_run.h"
#include "formats/datasets.h"
#include "lessons/lesson_player.h"
#include "lessons/lessons.h"
#include "player/engine_claims.h"
#include "player/lab.h"
#include "state/window_state_file.h"

namespace oflab {
namespace {

namespace fs = std::filesystem;

using testing::CliRun;

CliRun lesson(const CommandArgs& args) {
  return testing::run_session_command(lesson_command(), args);
}

// A lesson file "NAME.json" in a fresh folder, whose only step has `claim`.
std::string lesson_file(const std::string& name, const std::string& claim) {
  const fs::path dir = fs::temp_directory_path() / ("oflab-lesson-cli-" + std::to_string(getpid()));
  fs::create_directories(dir);
  const fs::path file = dir / (name + ".json");
  std::ofstream(file) << R"({"format": "oflab-lesson", "version": 1, "name": ")" << name
                      << R"(", "order": 99, "title": "T", "narrative": "n", "state": {},
    "steps": [{"say": "s", "do": {"play": 5}, "claims": [)"
                      << claim << "]}]}";
  return file.string();
}

// A lesson file "NAME.json" in a fresh folder with `state` and `steps` (JSON text).
std::string lesson_with_steps(const std::string& name, const std::string& state,
                              const std::string& steps) {
  const fs::path dir = fs::temp_directory_path() / ("oflab-lesson-cli-" + std::to_string(getpid()));
  fs::create_directories(dir);
  const fs::path file = dir / (name + ".json");
  std::ofstream(file) << R"({"format": "oflab-lesson", "version": 1, "name": ")" << name
                      << R"(", "order": 99, "title": "T", "narrative": "n", "state": )" << state
                      << R"(, "steps": )" << steps << "}";
  return file.string();
}

// A refusal as the issue asks: exit 2 and one line (ending in a newline) holding `needle`.
void expect_one_line_refusal(const CliRun& r, const std::string& needle) {
  EXPECT_EQ(r.code, 2) << r.out << r.err;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << r.err;
  EXPECT_NE(r.err.find(needle), std::string::npos) << r.err;
}

TEST(LessonCommand, ListsEveryLesson) {
  const CliRun r = lesson({"list"});
  EXPECT_EQ(r.code, 0) << r.err;
  for (const Lesson& l : lessons()) EXPECT_NE(r.out.find(l.name), std::string::npos) << l.name;
}

TEST(LessonCommand, StateIsWhatTheLabShowsAtThatStep) {
  const CliRun r = lesson({"state", "affine-vs-perspective", "--step", "2"});
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  Lab lab(shipped_default_texture());
  LabStage stage(&lab);
  ASSERT_EQ(go_to_lesson_step(stage, *find_lesson("affine-vs-perspective"), 2), "");
  EXPECT_EQ(j["frame"], lab.panel().frame());
  EXPECT_EQ(j["step"], 2);
  EXPECT_EQ(j["state"], window_state_object(lab.state()));
  EXPECT_EQ(lesson({"state", "affine-vs-perspective", "--step", "9"}).code, 2);
}

TEST(LessonCommand, CheckMeasuresEngineClaimsAndFailsOnAFalseOne) {
  const CliRun good = lesson({"check", "flow-of-a-plane"});
  EXPECT_EQ(good.code, 0) << good.out << good.err;
  EXPECT_NE(good.out.find("all hold"), std::string::npos) << good.out;
  const CliRun bad = lesson({"check", lesson_file("false-claim", R"({"says": "no error at all",
      "claim": "max_error", "of": "affine", "at_most": 0})")});
  EXPECT_EQ(bad.code, 1) << bad.out << bad.err;
  EXPECT_NE(bad.out.find("FALSE"), std::string::npos) << bad.out;
}

TEST(LessonCommand, ALessonFileWithAnUnknownKindIsRefusedAtReadTime) {
  const CliRun r = lesson({"check", lesson_file("unknown-kind", R"({"says": "x",
      "claim": "max_errors", "of": "engine", "at_most": 1})")});
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("unknown-kind.json: step 1, claim 1: field 'claim': 'max_errors'"),
            std::string::npos)
      << r.err;
  const CliRun misspelt = lesson({"check", lesson_file("misspelt", R"({"says": "x",
      "claim": "max_error", "of": "engine", "at_mots": 1})")});
  EXPECT_EQ(misspelt.code, 2);
  EXPECT_NE(misspelt.err.find("misspelt.json: step 1, claim 1: field 'at_mots': unknown field"),
            std::string::npos)
      << misspelt.err;
}

TEST(LessonCommand, AnUnknownOfOrAnEmptyRangeIsRefusedAtReadTimeNotMeasured) {
  // Refused by the claim-kind registry when the file is read: never "measured nan".
  const CliRun of = lesson({"check", lesson_file("unknown-of", R"({"says": "x",
      "claim": "max_error", "of": "afine", "at_most": 1})")});
  expect_one_line_refusal(
      of, "unknown-of.json: step 1, claim 1: field 'of': 'afine' is neither engine nor a reuse");
  EXPECT_EQ(of.out.find("nan"), std::string::npos) << of.out;
  const CliRun range = lesson({"check", lesson_file("empty-range", R"({"says": "x",
      "claim": "max_error", "of": "engine", "at_least": 2, "at_most": 1})")});
  expect_one_line_refusal(range,
                          "empty-range.json: step 1, claim 1: field 'at_least': more than at_most");
  EXPECT_EQ(range.out.find("nan"), std::string::npos) << range.out;
}

TEST(LessonCommand, ALessonPathThatCannotBeReadIsAOneLineRefusalNamingIt) {
  const fs::path dir =
      fs::temp_directory_path() / ("oflab-lesson-path-" + std::to_string(getpid()));
  fs::create_directories(dir);
  fs::create_symlink(dir / "loop.json", dir / "loop.json");  // a link to itself
  const std::string loop = (dir / "loop.json").string();
  expect_one_line_refusal(lesson({"state", loop}),
                          loop + ": cannot open the file (Too many levels of symbolic links)");
  const std::string long_name(5000, 'a');
  expect_one_line_refusal(lesson({"check", long_name}),
                          ": cannot open the file (File name too long)");
  expect_one_line_refusal(lesson({"state", "/dev/zero"}),
                          "/dev/zero: is not a regular file (a FIFO, device or socket)");
  expect_one_line_refusal(lesson({"state", dir.string()}), dir.string() + ": is a directory");
  // A plain word that names nothing is still an unknown lesson.
  expect_one_line_refusal(lesson({"state", "no-such-lesson"}), "unknown lesson 'no-such-lesson'");
  fs::remove_all(dir);
}

TEST(LessonCommand, AStepFrameBeyondWhatPlaysIsRefusedNamingTheFileTheStepAndTheField) {
  // The zoom script plays 90 frames: frames 0 .. 89.
  const std::string file = lesson_with_steps("far-frame", R"({"script": "zoom"})",
                                             R"([{"say": "s", "do": {"frame": 89}},
                                                 {"say": "t", "do": {"frame": 900}}])");
  EXPECT_EQ(lesson({"state", file, "--step", "1"}).code, 0);
  expect_one_line_refusal(lesson({"state", file, "--step", "2"}),
                          "far-frame.json: step 2: field 'do.frame': 900 is beyond the last "
                          "frame, 89, of what plays");
}

TEST(LessonCommand, AFileTheLessonNamesIsFoundBesideItAndItsProblemNamesTheLesson) {
  const fs::path dir =
      fs::temp_directory_path() / ("oflab-lesson-beside-" + std::to_string(getpid()));
  fs::create_directories(dir);
  fs::copy_file(default_texture_path(), dir / "tex.png", fs::copy_options::overwrite_existing);
  const std::string beside = lesson_with_steps("beside", R"({"texture": "tex.png"})", "[]");
  fs::rename(beside, dir / "beside.json");
  const CliRun r = lesson({"state", (dir / "beside.json").string()});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["state"]["texture"], (dir / "tex.png").string());
  // A texture that is nowhere: the message starts with the lesson's file, then the field.
  const std::string missing =
      lesson_with_steps("missing-texture", R"({"texture": "none.png"})", "[]");
  expect_one_line_refusal(lesson({"state", missing}), "missing-texture.json: texture: none.png");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace oflab
