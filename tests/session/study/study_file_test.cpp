// Study files (session/study/study_file.h): the shipped studies read, and every kind of bad
// file refused with one message naming the file, the part, the field and the limit.
#include "study/study_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace oflab {
namespace {

namespace fs = std::filesystem;

constexpr const char* kCondition =
    R"({"name": "a", "policy": "affine", "speed_deg_s": 20, "texture": "butterfly", "viewing_distance_cm": 60})";

// The error of reading "x.json" made of the top fields `top` (JSON members, without braces,
// ending with a comma or empty) and the conditions list `conditions`; "" when it reads.
std::string study_error(const std::string& top, const std::string& conditions = "") {
  const fs::path dir = fs::temp_directory_path() / ("oflab-study-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path file = dir / "x.json";
  std::ofstream(file) << "{" << top
                      << R"("format": "oflab-study", "version": 1, "name": "x", "title": "X",
    "method": "quest+", "trials": 40, "error_range_px": [0.1, 10], "seed": 1, "conditions": [)"
                      << (conditions.empty() ? kCondition : conditions) << "]}";
  std::string error;
  try {
    read_study_file(file.string());
  } catch (const StudyError& e) {
    error = e.what();
  }
  fs::remove_all(dir);
  return error;
}

TEST(StudyFile, TheShippedStudiesReadWithTheirConditions) {
  const std::vector<std::string> names = shipped_study_names();
  ASSERT_GE(names.size(), 2u);
  for (const std::string& name : names) {
    const Study s = find_or_read_study(name);
    EXPECT_EQ(s.name, name);
    EXPECT_FALSE(s.conditions.empty()) << name;
  }
  const Study full = find_or_read_study("reuse-threshold");
  EXPECT_EQ(full.trials, 40);
  EXPECT_EQ(full.conditions.size(), 5u);
  EXPECT_STREQ(study_policy_name(full.conditions[2].policy), "perspective");
  EXPECT_STREQ(study_policy_name(full.conditions[4].policy), "affine");
  EXPECT_STREQ(study_texture_name(full.conditions[3].texture), "grating");
  EXPECT_LT(find_or_read_study("class").trials, full.trials);
}

TEST(StudyFile, AGoodFileReads) { EXPECT_EQ(study_error(""), ""); }

TEST(StudyFile, BadFilesAreRefusedNamingTheFieldAndTheLimit) {
  EXPECT_EQ(study_error(R"("extra": 1, )"),
            "x.json: field 'extra': unknown field (known: format, version, name, title, "
            "description, method, trials, error_range_px, seed, assumed_slope, assumed_lapse, "
            "conditions)");
  EXPECT_EQ(study_error(R"("assumed_lapse": 0.5, )"),
            "x.json: field 'assumed_lapse': 0.5 is outside 0..0.2");
  EXPECT_EQ(study_error("", R"({"name": "a", "policy": "affine", "speed_deg_s": 900,
      "texture": "butterfly", "viewing_distance_cm": 60})"),
            "x.json: condition 1: field 'speed_deg_s': 900 is outside 1..360 deg/s");
  EXPECT_EQ(study_error("", R"({"name": "a", "policy": "warp", "speed_deg_s": 9,
      "texture": "butterfly", "viewing_distance_cm": 60})"),
            "x.json: condition 1: field 'policy': 'warp' is not one of affine, perspective");
  EXPECT_EQ(study_error("", std::string(kCondition) + ", " + kCondition),
            "x.json: condition 2: field 'name': is also an earlier condition's");
  EXPECT_EQ(study_error("", R"({"name": "a", "policy": "affine", "speed_deg_s": 9,
      "texture": "butterfly"})"),
            "x.json: condition 1: field 'viewing_distance_cm': is missing");
}

TEST(StudyFile, MoreThanSixteenConditionsAreRefused) {
  std::string many;
  for (int i = 0; i < 17; ++i)
    many +=
        std::string(i ? ", " : "") + R"({"name": "c)" + std::to_string(i) +
        R"(", "policy": "affine", "speed_deg_s": 9, "texture": "grating", "viewing_distance_cm": 60})";
  EXPECT_EQ(study_error("", many), "x.json: field 'conditions': 17 is outside 1..16 conditions");
}

TEST(StudyFile, MethodRangeTrialsAndNestingAreChecked) {
  const fs::path dir = fs::temp_directory_path() / ("oflab-study-b-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const auto error_of = [&](const std::string& text) {
    std::ofstream(dir / "y.json") << text;
    try {
      read_study_file((dir / "y.json").string());
    } catch (const StudyError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string head = R"({"format": "oflab-study", "version": 1, "name": "y", "title": "Y", )";
  const std::string tail = std::string(R"("seed": 1, "conditions": [)") + kCondition + "]}";
  EXPECT_EQ(
      error_of(head + R"("method": "quest", "trials": 40, "error_range_px": [0.1, 10], )" + tail),
      "y.json: field 'method': 'quest' is not one of staircase, quest+");
  EXPECT_EQ(error_of(head + R"("method": "quest+", "trials": 40.5, "error_range_px": [0.1, 10], )" +
                     tail),
            "y.json: field 'trials': 40.5 is not a whole number (5..400 trials)");
  EXPECT_EQ(
      error_of(head + R"("method": "quest+", "trials": 40, "error_range_px": [1, 1.5], )" + tail),
      "y.json: field 'error_range_px': the largest error must be at least twice the smallest");
  EXPECT_EQ(error_of(std::string(100, '[') + std::string(100, ']')),
            "y.json: lists and objects nested more than 64 deep, the limit for data files");
  EXPECT_EQ(error_of("{\"format\": \"oflab-lesson\"}"),
            "y.json: field 'format': must be \"oflab-study\"");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace oflab
