// Threshold studies as files: datasets/studies/NAME.json (manual/study.md). A study lists the
// conditions of a two-alternative forced-choice experiment on the error a reuse policy may
// show, how many trials each gets, the adaptive method that picks the error levels
// (study/adaptive_methods.h), the error range and the seed. Plain C++.
//
//   {"format": "oflab-study", "version": 1, "name": "reuse-threshold",
//    "title": "How much error can a viewer see?", "description": "...",
//    "method": "quest+", "trials": 40, "error_range_px": [0.1, 10], "seed": 43,
//    "assumed_slope": 3.5, "assumed_lapse": 0.02,
//    "conditions": [{"name": "affine-slow", "policy": "affine", "speed_deg_s": 20,
//                    "texture": "butterfly", "viewing_distance_cm": 60}, ...]}
//
// Each trial plays the condition's motion for kClipSeconds at kClipFrameRate twice: exactly,
// and reused by the condition's policy with the error the method asks for; the motion is the
// plane turning about its vertical axis at speed_deg_s degrees per second. "assumed_slope"
// and "assumed_lapse" are the psychometric function's slope and lapse rate that the threshold
// fit assumes (study/psychometric.h; optional, these defaults). Unknown fields are refused;
// every number is checked against its limit (kStudyLimits below), and a file that cannot be
// used is refused when read, naming the file, the part and the field:
//   "short.json: condition 2: field 'speed_deg_s': 900 is outside 1..360 deg/s".
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "flow/limits.h"

namespace oflab {

// Each clip of a trial: seconds and frames per second.
constexpr double kClipSeconds = 1.0;
constexpr int kClipFrameRate = 60;

// The policies and textures a condition may name.
enum class StudyPolicy { kAffine, kPerspective };
enum class StudyTexture { kButterfly, kGrating };

// The names as written in files: "affine", "perspective"; "butterfly", "grating".
const char* study_policy_name(StudyPolicy policy);
const char* study_texture_name(StudyTexture texture);

struct StudyCondition {
  std::string name;  // unique within the study
  StudyPolicy policy = StudyPolicy::kAffine;
  double speed_deg_s = 30.0;  // the plane's turn rate, degrees per second
  StudyTexture texture = StudyTexture::kButterfly;
  double viewing_distance_cm = 60.0;  // eye to screen
};

struct Study {
  std::string name;  // the file's stem
  std::string title;
  std::string description;
  std::string method = "quest+";  // one of adaptive_methods()
  int trials = 40;                // answered trials per condition (late ones not counted)
  double min_px = 0.1;            // error_range_px
  double max_px = 10.0;
  std::uint64_t seed = 1;
  double assumed_slope = 3.5;
  double assumed_lapse = 0.02;
  std::vector<StudyCondition> conditions;
};

// The limits of a study's numbers (core/flow/limits.h's Limit, for the same messages).
namespace study_limits {
inline constexpr Limit kTrials{"trials per condition", "trials", 5.0, 400.0, true};
inline constexpr Limit kConditions{"conditions", "conditions", 1.0, 16.0, true};
inline constexpr Limit kErrorPx{"error range", "px", 0.01, 100.0};
inline constexpr Limit kSeed{"seed", "", 0.0, 9007199254740992.0, true};  // 2^53
inline constexpr Limit kSpeed{"speed", "deg/s", 1.0, 360.0};
inline constexpr Limit kViewingDistance{"viewing distance", "cm", 10.0, 1000.0};
inline constexpr Limit kSlope{"assumed slope", "", 0.5, 20.0};
inline constexpr Limit kLapse{"assumed lapse", "", 0.0, 0.2};
inline constexpr Limit kPpi{"pixels per inch", "ppi", 10.0, 2000.0};  // a screen's
}  // namespace study_limits

// Thrown for a study file that cannot be used; what() names the file, the part and the field.
class StudyError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The study in the file at `path`, read through the JSON readers of analysis/formats/
// json_fields.h (their value and nesting budgets). Throws StudyError naming the file, the
// part ("condition 2") and the field with its limit.
Study read_study_file(const std::string& path);

// The names of the shipped studies (datasets/studies/), sorted.
std::vector<std::string> shipped_study_names();

// A study argument: an existing file, else a shipped study's name. Throws StudyError listing
// the shipped names when neither.
Study find_or_read_study(const std::string& name_or_file);

}  // namespace oflab
