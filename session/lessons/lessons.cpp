#include "lessons/lessons.h"

#include <algorithm>
#include <deque>
#include <filesystem>
#include <system_error>

#include "flow/limits.h"
#include "formats/datasets.h"
#include "formats/json_fields.h"
#include "lessons/claim_kinds.h"
#include "state/window_state_file.h"

namespace oflab {
namespace {

using namespace json_fields;
using Where = Place<SessionError>;

// obj[field] as a whole number in first..last.
int whole_in(const json& obj, const Where& w, const std::string& field, int first, int last) {
  const double v = number(member(obj, w, field), w, field);
  if (v != std::floor(v) || v < first || v > last) {
    w.fail(field,
           "must be a whole number from " + std::to_string(first) + " to " + std::to_string(last));
  }
  return int(v);
}

LessonClaim read_claim(const json& j, const Where& w) {
  if (!j.is_object()) w.fail("claims", "each claim must be an object");
  only_fields(j, w, {"says", "claim", "of", "over", "level", "at_least", "at_most"});
  LessonClaim c;
  c.says = text(j, w, "says");
  c.claim = text(j, w, "claim");
  c.of = optional_text(j, w, "of", "");
  c.over = optional_text(j, w, "over", "");
  c.level = optional_text(j, w, "level", "");
  if (j.contains("at_least")) c.at_least = number(j.at("at_least"), w, "at_least");
  if (j.contains("at_most")) c.at_most = number(j.at("at_most"), w, "at_most");
  if (!j.contains("at_least") && !j.contains("at_most")) {
    w.fail("at_least", "a claim needs at_least, at_most or both");
  }
  // The kind and its fields, through the registry (lessons/claim_kinds.h).
  const std::string problem = claim_problem(c);
  if (!problem.empty()) {
    const size_t colon = problem.find(": ");
    w.fail(problem.substr(0, colon), problem.substr(colon + 2));
  }
  return c;
}

std::vector<LessonClaim> read_claims(const json& obj, const Where& w) {
  std::vector<LessonClaim> claims;
  if (!obj.contains("claims")) return claims;
  const json& list = obj.at("claims");
  if (!list.is_array()) w.fail("claims", "must be a list of claims");
  for (size_t i = 0; i < list.size(); ++i) {
    claims.push_back(read_claim(list[i], Where{w.origin, w.part + (w.part.empty() ? "" : ", ") +
                                                             "claim " + std::to_string(i + 1)}));
  }
  return claims;
}

// Adds `frames` frames played at `field` to the lesson's `played` so far; fails at `w` when
// they pass limits::kLessonFrames.
void count_played(int frames, int& played, const Where& w, const std::string& field) {
  played += frames;
  const Limit& limit = limits::kLessonFrames;
  if (!limit.allows(played)) {
    w.fail(field, "the lesson plays " + std::to_string(played) + " frames up to here, more than " +
                      std::to_string(int(limit.maximum)) + " (the " + limit.what + " limit)");
  }
}

// The steps, each state read over the one before it (the lesson's own first); `played` the
// frames played before them, counted on against limits::kLessonFrames. At most
// limits::kLessonSteps steps: the reader stops at the first one over, before reading it.
std::vector<LessonStep> read_steps(const json& root, const std::string& origin,
                                   const WindowState& lesson_state, int played) {
  std::vector<LessonStep> steps;
  if (!root.contains("steps")) return steps;
  const Where top{origin, ""};
  const json& list = root.at("steps");
  if (!list.is_array()) top.fail("steps", "must be a list of steps");
  WindowState state = lesson_state;
  for (size_t i = 0; i < list.size(); ++i) {
    const Where w{origin, "step " + std::to_string(i + 1)};
    if (!limits::kLessonSteps.allows(double(i + 1))) {
      w.fail("", "the lesson has " + std::to_string(list.size()) + " steps, more than " +
                     std::to_string(int(limits::kLessonSteps.maximum)) + " (the " +
                     limits::kLessonSteps.what + " limit)");
    }
    const json& j = list[i];
    if (!j.is_object()) top.fail("steps", "each step must be an object");
    only_fields(j, w, {"say", "do", "claims"});
    LessonStep step;
    step.say = text(j, w, "say");
    if (j.contains("do")) {
      const json& act = object(j, w, "do");
      only_fields(act, w, {"frame", "play", "state"});
      if (act.contains("frame")) {
        step.frame = whole_in(act, w, "frame", 0, 1000000);
        count_played(step.frame, played, w, "frame");
      }
      if (act.contains("play")) {
        step.play = whole_in(act, w, "play", 0, 100000);
        count_played(step.play, played, w, "play");
      }
      if (act.contains("state")) {
        state =
            read_window_state_object(object(act, w, "state"), origin, w.part + ": state", state);
        step.has_state = true;
        step.state = state;
      }
    }
    step.claims = read_claims(j, w);
    steps.push_back(step);
  }
  return steps;
}

}  // namespace

Lesson read_lesson_file(const std::string& path) {
  const std::string origin = std::filesystem::path(path).filename().string();
  const Where top{origin, ""};
  const json root = parse_object(read_file_text<SessionError>(path), top);
  only_fields(root, top,
              {"format", "version", "name", "order", "title", "narrative", "state", "play",
               "claims", "steps"});
  if (text(root, top, "format") != "oflab-lesson") top.fail("format", "must be \"oflab-lesson\"");
  if (number(member(root, top, "version"), top, "version") != 1) {
    top.fail("version", "only version 1 is known");
  }
  Lesson lesson;
  lesson.name = text(root, top, "name");
  if (lesson.name != std::filesystem::path(path).stem().string()) {
    top.fail("name", "must be the file's name without .json");
  }
  lesson.title = text(root, top, "title");
  lesson.narrative = text(root, top, "narrative");
  const double order = number(member(root, top, "order"), top, "order");
  if (order != std::floor(order) || order < 1 || order > 1000) {
    top.fail("order", "must be a whole number from 1 to 1000");
  }
  lesson.order = int(order);
  lesson.state =
      read_window_state_object(object(root, top, "state"), origin, "state", WindowState());
  if (!lesson.state.lesson.empty()) top.fail("state", "must not name a lesson itself");
  lesson.state.lesson = lesson.name;
  int played = 0;
  if (root.contains("play")) {
    lesson.play = whole_in(root, top, "play", 0, 100000);
    count_played(lesson.play, played, top, "play");
  }
  lesson.claims = read_claims(root, Where{origin, "narrative"});
  lesson.steps = read_steps(root, origin, lesson.state, played);
  for (LessonStep& step : lesson.steps) step.state.lesson = lesson.name;
  // The files a lesson names are found beside it first (a teacher's folder of lesson,
  // textures and scripts).
  lesson.state = with_files_beside(lesson.state, path);
  for (LessonStep& step : lesson.steps) step.state = with_files_beside(step.state, path);
  return lesson;
}

const std::vector<Lesson>& lessons() {
  static const std::vector<Lesson> all = [] {
    std::vector<Lesson> list;
    for (const std::string& name : shipped_names("lessons")) {
      list.push_back(read_lesson_file(datasets_dir() + "/lessons/" + name + ".json"));
    }
    std::sort(list.begin(), list.end(),
              [](const Lesson& a, const Lesson& b) { return a.order < b.order; });
    for (size_t i = 1; i < list.size(); ++i) {
      if (list[i].order == list[i - 1].order) {
        throw SessionError(list[i].name + ".json: field 'order': " + std::to_string(list[i].order) +
                           " is also " + list[i - 1].name + "'s");
      }
    }
    return list;
  }();
  return all;
}

namespace {

// Lessons added from the user's files (a deque: references stay valid as it grows).
std::deque<Lesson>& added_lessons() {
  static std::deque<Lesson> added;
  return added;
}

}  // namespace

const Lesson* find_lesson(const std::string& name) {
  for (const Lesson& lesson : lessons()) {
    if (lesson.name == name) return &lesson;
  }
  for (const Lesson& lesson : added_lessons()) {
    if (lesson.name == name) return &lesson;
  }
  return nullptr;
}

const Lesson& add_lesson(const Lesson& lesson) {
  for (const Lesson& shipped : lessons()) {
    if (shipped.name == lesson.name) {
      throw SessionError(lesson.name + ".json: field 'name': '" + lesson.name +
                         "' is a shipped lesson's name");
    }
  }
  for (Lesson& added : added_lessons()) {
    if (added.name == lesson.name) return added = lesson;
  }
  return added_lessons().emplace_back(lesson);
}

namespace {

// True when `name_or_file` is meant as a file: it names something on disk (a file, a
// directory, a device, a dangling or looping link), cannot even be looked up (a name too
// long, a loop of links on the way), or is written as a path (a '/' or a ".json" ending).
// A plain word that names nothing is an unknown lesson's name.
bool meant_as_file(const std::string& name_or_file) {
  if (name_or_file.find('/') != std::string::npos) return true;
  const std::string json = ".json";
  if (name_or_file.size() > json.size() &&
      name_or_file.compare(name_or_file.size() - json.size(), json.size(), json) == 0) {
    return true;
  }
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::symlink_status(name_or_file, error);
  // A name that is simply not there reports ENOENT beside not_found; any other error (a loop,
  // a name too long) means the file system was asked about a path.
  return status.type() != std::filesystem::file_type::not_found ||
         (error && error != std::errc::no_such_file_or_directory);
}

}  // namespace

const Lesson& find_or_read_lesson(const std::string& name_or_file) {
  if (const Lesson* lesson = find_lesson(name_or_file)) return *lesson;
  if (!meant_as_file(name_or_file)) {
    throw SessionError("unknown lesson '" + name_or_file + "' (known: " + lesson_names() +
                       ", or a lesson file)");
  }
  try {  // the reader names the path and why it cannot be read (a loop, a name too long, ...)
    return add_lesson(read_lesson_file(name_or_file));
  } catch (const std::filesystem::filesystem_error& e) {
    throw SessionError(name_or_file + ": cannot read the file (" + e.code().message() + ")");
  }
}

std::string lesson_names() {
  std::string names;
  for (const Lesson& lesson : lessons()) names += (names.empty() ? "" : ", ") + lesson.name;
  return names;
}

}  // namespace oflab
