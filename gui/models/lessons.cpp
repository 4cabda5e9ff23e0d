#include "models/lessons.h"

#include <algorithm>
#include <filesystem>

#include "formats/datasets.h"
#include "formats/json_fields.h"
#include "models/window_state_file.h"

namespace oflab {
namespace {

using namespace json_fields;
using Where = Place<SessionError>;

}  // namespace

Lesson read_lesson_file(const std::string& path) {
  const std::string origin = std::filesystem::path(path).filename().string();
  const Where top{origin, ""};
  const json root = parse_object(read_file_text<SessionError>(path), top);
  for (auto it = root.begin(); it != root.end(); ++it) {
    static const char* known[] = {"format", "version",   "name", "order",
                                  "title",  "narrative", "state"};
    if (std::find_if(std::begin(known), std::end(known),
                     [&](const char* k) { return it.key() == k; }) == std::end(known)) {
      top.fail(it.key(),
               "unknown field (known: format, version, name, order, title, "
               "narrative, state)");
    }
  }
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

const Lesson* find_lesson(const std::string& name) {
  for (const Lesson& lesson : lessons()) {
    if (lesson.name == name) return &lesson;
  }
  return nullptr;
}

std::string lesson_names() {
  std::string names;
  for (const Lesson& lesson : lessons()) names += (names.empty() ? "" : ", ") + lesson.name;
  return names;
}

}  // namespace oflab
