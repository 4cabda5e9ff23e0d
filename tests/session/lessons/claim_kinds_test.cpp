// The claim-kind registry (session/lessons/claim_kinds.h): a lesson naming an unknown kind,
// a misspelt field or a value its kind cannot measure is refused when it is read, naming the
// file, the claim and the field; the manual lists exactly the registry's kinds.
#include "lessons/claim_kinds.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "lesson_read_error.h"
#include "lessons/lessons.h"
#include "state/window_state_file.h"

namespace oflab {
namespace {

namespace fs = std::filesystem;

// The error of reading a lesson "x.json" whose only step has `claim` (JSON text).
std::string error_of_claim(const std::string& claim) {
  return test::lesson_read_error(
      "claims", R"("steps": [{"say": "s"}, {"say": "t", "claims": [)" + claim + "]}]}");
}

TEST(ClaimKinds, AnUnknownKindIsRefusedNamingFileClaimAndField) {
  const std::string error =
      error_of_claim(R"({"says": "a", "claim": "max_errors", "of": "engine", "at_most": 1})");
  EXPECT_EQ(error.rfind("x.json: step 2, claim 1: field 'claim': 'max_errors' is not one of", 0),
            0u)
      << error;
}

TEST(ClaimKinds, AMisspeltFieldIsRefusedNamingIt) {
  const std::string error =
      error_of_claim(R"({"says": "a", "claim": "max_error", "off": "engine", "at_most": 1})");
  EXPECT_EQ(error.rfind("x.json: step 2, claim 1: field 'off': unknown field", 0), 0u) << error;
}

TEST(ClaimKinds, WhatAKindCannotMeasureIsRefused) {
  EXPECT_NE(error_of_claim(R"({"says": "a", "claim": "max_error", "of": "afine", "at_most": 1})")
                .find("field 'of': 'afine' is neither engine nor a reuse policy"),
            std::string::npos);
  EXPECT_NE(error_of_claim(R"({"says": "a", "claim": "max_error", "at_most": 1})")
                .find("field 'of': this kind needs it"),
            std::string::npos);
  EXPECT_NE(error_of_claim(R"({"says": "a", "claim": "cut_texts", "of": "x", "at_most": 0})")
                .find("field 'of': this kind takes none"),
            std::string::npos);
  EXPECT_NE(error_of_claim(R"({"says": "a", "claim": "level_share", "of": "engine",
                               "level": "sideways", "at_most": 1})")
                .find("field 'level': unknown level 'sideways'"),
            std::string::npos);
  EXPECT_NE(error_of_claim(R"({"says": "a", "claim": "cut_texts", "at_least": 2, "at_most": 1})")
                .find("field 'at_least': more than at_most"),
            std::string::npos);
  EXPECT_EQ(error_of_claim(R"({"says": "a", "claim": "coefficient", "of": "j11", "at_most": 1})"),
            "");
}

// A state's study.open names a shipped study (datasets/studies/): an unknown one is refused
// when the lesson is read, naming the file and the field; the study kinds' fields likewise.
TEST(ClaimKinds, AStudyTheLessonOpensOrMeasuresIsAShippedOne) {
  const std::string unknown = test::lesson_read_error(
      "study", R"("steps": [{"say": "s", "do": {"state": {"study": {"open": "nope"}}}}]})");
  EXPECT_EQ(unknown.rfind("x.json: study: field 'open': unknown study 'nope' (one of ", 0), 0u)
      << unknown;
  EXPECT_NE(unknown.find("lesson"), std::string::npos) << unknown;
  EXPECT_EQ(
      test::lesson_read_error(
          "study", R"("steps": [{"say": "s", "do": {"state": {"study": {"open": "lesson"}}}}]})"),
      "");
  EXPECT_NE(error_of_claim(R"({"says": "a", "claim": "study_setup", "of": "nope", "at_least": 1})")
                .find("field 'of': 'nope' is not one of"),
            std::string::npos);
  EXPECT_NE(error_of_claim(R"({"says": "a", "claim": "study_recovery", "of": "one", "at_most": 1})")
                .find("field 'of': 'one' is not a threshold in pixels"),
            std::string::npos);
  EXPECT_NE(error_of_claim(R"({"says": "a", "claim": "study_recovery", "of": "500", "at_most": 1})")
                .find("field 'of': '500' is not a threshold in pixels"),
            std::string::npos);
  EXPECT_NE(error_of_claim(R"({"says": "a", "claim": "study_errors", "of": "mid", "at_most": 1})")
                .find("field 'of': 'mid' is not one of min, max"),
            std::string::npos);
  EXPECT_EQ(
      error_of_claim(R"({"says": "a", "claim": "study_recovery", "of": "0.8", "at_most": 1})"), "");
}

TEST(ClaimKinds, EveryShippedLessonReads) {
  EXPECT_GE(lessons().size(), 16u);
  for (const Lesson& lesson : lessons()) {
    for (const LessonStep& step : lesson.steps) {
      for (const LessonClaim& claim : step.claims) {
        EXPECT_EQ(claim_problem(claim), "") << lesson.name;
      }
    }
  }
}

TEST(ClaimKinds, TheManualListsExactlyTheRegistrysKinds) {
  std::ifstream in(OFLAB_SOURCE_DIR "/manual/lessons.md");
  std::stringstream page;
  page << in.rdbuf();
  const std::string text = page.str();
  const std::string begin = "<!-- claim-kinds: oflab-cli lesson kinds --markdown -->\n";
  const size_t from = text.find(begin), to = text.find("<!-- /claim-kinds -->");
  ASSERT_NE(from, std::string::npos) << "manual/lessons.md lacks the kinds table's markers";
  ASSERT_NE(to, std::string::npos);
  EXPECT_EQ(text.substr(from + begin.size(), to - from - begin.size()), claim_kinds_markdown());
}

}  // namespace
}  // namespace oflab
