#include "study/study_file.h"

#include <filesystem>
#include <set>

#include "formats/datasets.h"
#include "formats/json_fields.h"
#include "study/adaptive_methods.h"

namespace oflab {
namespace {

using namespace json_fields;
using Where = Place<StudyError>;

// Reads the name at `field` of `obj`, one of `names` (n entries).
template <class Enum>
Enum named(const json& obj, const Where& w, const std::string& field, const char* const* names,
           int n) {
  const std::string value = text(obj, w, field);
  std::string known;
  for (int i = 0; i < n; ++i) {
    if (value == names[i]) return Enum(i);
    known += (i ? ", " : "") + std::string(names[i]);
  }
  w.fail(field, "'" + value + "' is not one of " + known);
}

constexpr const char* kPolicyNames[] = {"affine", "perspective"};
constexpr const char* kTextureNames[] = {"butterfly", "grating"};

StudyCondition read_condition(const json& j, const Where& w) {
  if (!j.is_object()) w.fail("", "each condition must be an object");
  only_fields(j, w, {"name", "policy", "speed_deg_s", "texture", "viewing_distance_cm"});
  StudyCondition c;
  c.name = text(j, w, "name");
  if (c.name.empty()) w.fail("name", "must not be empty");
  c.policy = named<StudyPolicy>(j, w, "policy", kPolicyNames, 2);
  c.speed_deg_s = limited(j, w, "speed_deg_s", study_limits::kSpeed);
  c.texture = named<StudyTexture>(j, w, "texture", kTextureNames, 2);
  c.viewing_distance_cm = limited(j, w, "viewing_distance_cm", study_limits::kViewingDistance);
  return c;
}

std::vector<StudyCondition> read_conditions(const json& root, const Where& top) {
  const json& list = member(root, top, "conditions");
  if (!list.is_array()) top.fail("conditions", "must be a list of conditions");
  if (!study_limits::kConditions.allows(double(list.size()))) {
    top.fail("conditions", study_limits::kConditions.problem(double(list.size())));
  }
  std::vector<StudyCondition> conditions;
  std::set<std::string> names;
  for (size_t i = 0; i < list.size(); ++i) {
    const Where w{top.origin, "condition " + std::to_string(i + 1)};
    conditions.push_back(read_condition(list[i], w));
    if (!names.insert(conditions.back().name).second)
      w.fail("name", "is also an earlier condition's");
  }
  return conditions;
}

void read_method_and_range(const json& root, const Where& top, Study& s) {
  s.method = text(root, top, "method");
  if (!find_adaptive_method(s.method)) {
    top.fail("method", "'" + s.method + "' is not one of " + adaptive_method_names());
  }
  s.trials = limited_integer(root, top, "trials", study_limits::kTrials);
  const Vec2 range = limited_vec2(root, top, "error_range_px", study_limits::kErrorPx);
  if (!(range.x * 2.0 <= range.y)) {
    top.fail("error_range_px", "the largest error must be at least twice the smallest");
  }
  s.min_px = range.x, s.max_px = range.y;
  s.seed = std::uint64_t(limited(root, top, "seed", study_limits::kSeed));
  if (root.contains("assumed_slope")) {
    s.assumed_slope = limited(root, top, "assumed_slope", study_limits::kSlope);
  }
  if (root.contains("assumed_lapse")) {
    s.assumed_lapse = limited(root, top, "assumed_lapse", study_limits::kLapse);
  }
}

}  // namespace

const char* study_policy_name(StudyPolicy policy) { return kPolicyNames[int(policy)]; }
const char* study_texture_name(StudyTexture texture) { return kTextureNames[int(texture)]; }

Study read_study_file(const std::string& path) {
  const std::string origin = std::filesystem::path(path).filename().string();
  const Where top{origin, ""};
  const json root = parse_object(read_file_text<StudyError>(path), top);
  only_fields(root, top,
              {"format", "version", "name", "title", "description", "method", "trials",
               "error_range_px", "seed", "assumed_slope", "assumed_lapse", "conditions"});
  if (text(root, top, "format") != "oflab-study") top.fail("format", "must be \"oflab-study\"");
  if (number(member(root, top, "version"), top, "version") != 1) {
    top.fail("version", "only version 1 is known");
  }
  Study s;
  s.name = text(root, top, "name");
  if (s.name != std::filesystem::path(path).stem().string()) {
    top.fail("name", "must be the file's name without .json");
  }
  s.title = text(root, top, "title");
  s.description = optional_text(root, top, "description", "");
  read_method_and_range(root, top, s);
  s.conditions = read_conditions(root, top);
  return s;
}

std::vector<std::string> shipped_study_names() { return shipped_names("studies"); }

Study find_or_read_study(const std::string& name_or_file) {
  std::string path;
  try {
    path = resolve_shipped_path(name_or_file, "studies", "study");
  } catch (const std::runtime_error& e) {
    throw StudyError(e.what());
  }
  return read_study_file(path);
}

}  // namespace oflab
