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

#include "lessons/lesson_player.h"
#include "lessons/lessons.h"
#include "player/engine_claims.h"
#include "player/lab.h"
#include "state/window_state_file.h"

namespace oflab {
namespace {

namespace fs = std::filesystem;

struct CliRun {
  int code = 0;
  std::string out, err;
};

CliRun lesson(const CommandArgs& args) {
  static const bool added = [] {
    add_command(lesson_command());
    return true;
  }();
  (void)added;
  CommandArgs all = {"lesson"};
  all.insert(all.end(), args.begin(), args.end());
  std::ostringstream out, err;
  CliRun r;
  r.code = run_cli(all, out, err);
  r.out = out.str();
  r.err = err.str();
  return r;
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

}  // namespace
}  // namespace oflab
