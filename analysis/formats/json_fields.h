// Checked reading of the fields of oflab's JSON data files (motion scripts, scenes, viewer
// scripts, GUI sessions), shared by their readers. Every problem is thrown as the file kind's
// error type (the template argument) with a message naming the file, the part and the field:
//     "datasets/scripts/zoom.json: segment 1: field 'omega': must be a list of 3 numbers".
#pragma once

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "flow/camera.h"
#include "flow/geometry.h"
#include "flow/limits.h"
#include "formats/input_file.h"

namespace oflab::json_fields {

using nlohmann::json;

// Largest magnitude of any number in a data file that no Limit of core/flow/limits.h
// covers (positions, directions).
constexpr double kMaxMagnitude = 1e6;
// Most frames of a whole script (summed over its segments, or listed): the maximum of
// limits::kFrameCount.
constexpr int kMaxScriptFrames = static_cast<int>(limits::kFrameCount.maximum);

// Where a value sits: the file (or a description of the text) and the part of it ("",
// "segment 1", "polygon 3 ('a-top')").
template <class Error>
struct Place {
  std::string origin;
  std::string part;

  [[noreturn]] void fail(const std::string& field, const std::string& message) const {
    std::string text = origin + ": ";
    if (!part.empty()) text += part + ": ";
    if (!field.empty()) text += "field '" + field + "': ";
    throw Error(text + message);
  }
};

// Largest data file read (JSON or OBJ), in bytes: parsed JSON takes about ten times its size.
constexpr long long kMaxFileBytes = 64LL << 20;

// The contents of the file at `path`; Error "PATH: cannot open the file (REASON)" if it cannot
// be opened, "PATH: is a directory", "PATH: is not a regular file (...)" for a FIFO, device or
// socket (never opened, so never waited on), "PATH: larger than 64 MiB" above kMaxFileBytes
// (by its size, and by what was read: formats/input_file.h).
template <class Error>
std::string read_file_text(const std::string& path) {
  InputFile file = read_input_file(path, kMaxFileBytes);
  if (file.problem == InputProblem::kTooLarge) {
    throw Error(path + ": larger than 64 MiB, the limit for data files");
  }
  if (file.problem != InputProblem::kNone) throw Error(path + ": " + input_problem_text(file));
  return std::move(file.bytes);
}

// What the JSON library says, in a reader's words: "line 3, column 7: unexpected '}';
// expected string literal" for a syntax error (where it stopped, both from 1), "number
// overflow parsing '1e400'" for the rest; never the library's "[json.exception...]" codes.
inline std::string json_problem(const json::exception& e) {
  std::string words = e.what();
  const std::size_t code = words.find("] ");  // "[json.exception.parse_error.101] "
  if (words.rfind("[json.exception.", 0) == 0 && code != std::string::npos) {
    words.erase(0, code + 2);
  }
  const std::string at = "parse error at ";
  if (words.rfind(at, 0) == 0) words.erase(0, at.size());
  const std::size_t syntax = words.find(": syntax error while parsing ");
  const std::size_t dash = words.find(" - ", syntax == std::string::npos ? 0 : syntax);
  if (syntax != std::string::npos && dash != std::string::npos) {
    words.erase(syntax + 2, dash + 3 - (syntax + 2));
  }
  return words;
}

// Most values (numbers, strings, lists, objects, each counted once, members' keys not) in
// one JSON data file, and the deepest nesting of lists and objects. The parsed document
// takes up to about 170 bytes a value (an object member: a tree node, its key and an empty
// object), so a file within these peaks below 800 MB (770 MB measured for 4 190 000 members
// "N": {}, manual/robustness.md); without them 64 MiB of "{}," took 2.3 GB. The largest file oflab
// writes, `make-scene --cubes 20000`, has 1 700 009 values nested 4 deep; a lesson or session has a
// few hundred.
constexpr long long kMaxJsonValues = 4LL << 20;
constexpr int kMaxJsonDepth = 64;

// A counting pass over JSON text (the library's SAX interface) that builds nothing: it stops
// at the first value past kMaxJsonValues or list/object past kMaxJsonDepth, and at the first
// syntax error, keeping its words. Used by parse_object before the document is built.
class JsonBudget : public nlohmann::json_sax<json> {
 public:
  std::string problem;  // "" while within the budget and valid so far

  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool key(string_t&) override { return true; }
  bool start_object(std::size_t) override { return open(); }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override { return open(); }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) override {
    problem = "not valid JSON (" + json_problem(e) + ")";
    return false;
  }

 private:
  long long values_ = 0;
  int depth_ = 0;

  bool value() {
    if (++values_ <= kMaxJsonValues) return true;
    problem = "more than " + std::to_string(kMaxJsonValues) +
              " JSON values, the limit for data files (numbers, strings, lists and objects)";
    return false;
  }
  bool open() {
    if (++depth_ <= kMaxJsonDepth) return value();
    problem = "lists and objects nested more than " + std::to_string(kMaxJsonDepth) +
              " deep, the limit for data files";
    return false;
  }
  bool close() {
    --depth_;
    return true;
  }
};

// `text` parsed; it must be a JSON object. It is first counted (JsonBudget): over
// kMaxJsonValues values or kMaxJsonDepth levels it is refused before anything is built,
// "FILE: more than 4194304 JSON values, the limit ...". Every exception of the JSON library (a
// syntax error, a number too large for a double such as 1e400, ...) becomes an Error naming
// the file: "FILE: not valid JSON (json_problem)".
template <class Error>
json parse_object(const std::string& text, const Place<Error>& top) {
  json root;
  try {
    JsonBudget budget;
    if (!json::sax_parse(text, &budget) && !budget.problem.empty()) top.fail("", budget.problem);
    root = json::parse(text);
  } catch (const json::exception& e) {
    top.fail("", "not valid JSON (" + json_problem(e) + ")");
  }
  if (!root.is_object()) top.fail("", "must be a JSON object");
  return root;
}

// Refuses (Error naming the field and the known ones) any member of `obj` not in `known`.
template <class Error>
void only_fields(const json& obj, const Place<Error>& w, const std::vector<std::string>& known) {
  for (auto it = obj.begin(); it != obj.end(); ++it) {
    if (std::find(known.begin(), known.end(), it.key()) != known.end()) continue;
    std::string names;
    for (const std::string& k : known) names += (names.empty() ? "" : ", ") + k;
    w.fail(it.key(), "unknown field (known: " + names + ")");
  }
}

// obj[field], which must be present.
template <class Error>
const json& member(const json& obj, const Place<Error>& w, const std::string& field) {
  if (!obj.contains(field)) w.fail(field, "is missing");
  return obj.at(field);
}

// obj[field], which must be an object.
template <class Error>
const json& object(const json& obj, const Place<Error>& w, const std::string& field) {
  const json& j = member(obj, w, field);
  if (!j.is_object()) w.fail(field, "must be an object");
  return j;
}

// obj[field], which must be a string.
template <class Error>
std::string text(const json& obj, const Place<Error>& w, const std::string& field) {
  const json& j = member(obj, w, field);
  if (!j.is_string()) w.fail(field, "must be a string");
  return j.get<std::string>();
}

// obj[field] when present (it must then be a string), else `fallback`.
template <class Error>
std::string optional_text(const json& obj, const Place<Error>& w, const std::string& field,
                          const std::string& fallback) {
  return obj.contains(field) ? text(obj, w, field) : fallback;
}

// The value `j` of `field` as a finite number of magnitude at most kMaxMagnitude.
template <class Error>
double number(const json& j, const Place<Error>& w, const std::string& field) {
  if (!j.is_number()) w.fail(field, "must be a number");
  const double v = j.get<double>();
  if (!std::isfinite(v) || std::abs(v) > kMaxMagnitude) {
    w.fail(field, "must be a finite number of magnitude at most 1e6");
  }
  return v;
}

// The value `j` of `field` as a list of 3 (2) numbers.
template <class Error>
Vec3 vec3_value(const json& j, const Place<Error>& w, const std::string& field) {
  if (!j.is_array() || j.size() != 3) w.fail(field, "must be a list of 3 numbers");
  return Vec3(number(j[0], w, field), number(j[1], w, field), number(j[2], w, field));
}

template <class Error>
Vec2 vec2_value(const json& j, const Place<Error>& w, const std::string& field) {
  if (!j.is_array() || j.size() != 2) w.fail(field, "must be a list of 2 numbers");
  return Vec2(number(j[0], w, field), number(j[1], w, field));
}

// obj[field] as a list of 3 (2) numbers.
template <class Error>
Vec3 vec3(const json& obj, const Place<Error>& w, const std::string& field) {
  return vec3_value(member(obj, w, field), w, field);
}

template <class Error>
Vec2 vec2(const json& obj, const Place<Error>& w, const std::string& field) {
  return vec2_value(member(obj, w, field), w, field);
}

// The value `j` of `field` as a number `limit` allows (core/flow/limits.h, the one rule
// for each kind of value); otherwise fails with the limit's words:
// "field 'camera.focal_px': 0.5 is outside 1..100000 px".
template <class Error>
double limited_value(const json& j, const Place<Error>& w, const std::string& field,
                     const Limit& limit) {
  if (!j.is_number()) w.fail(field, "must be a number");
  const double v = j.get<double>();
  if (!limit.allows(v)) w.fail(field, limit.problem(v));
  return v;
}

// obj[field] as a number `limit` allows; for a whole-number limit whose range fits an int,
// limited_integer returns it as an int.
template <class Error>
double limited(const json& obj, const Place<Error>& w, const std::string& field,
               const Limit& limit) {
  return limited_value(member(obj, w, field), w, field, limit);
}

template <class Error>
int limited_integer(const json& obj, const Place<Error>& w, const std::string& field,
                    const Limit& limit) {
  return static_cast<int>(limited(obj, w, field, limit));
}

// The value `j` of `field` as a list of `N` numbers, each of which `limit` allows.
template <int N, class Error>
glm::vec<N, double> limited_vector(const json& j, const Place<Error>& w, const std::string& field,
                                   const Limit& limit) {
  if (!j.is_array() || j.size() != N) {
    w.fail(field, "must be a list of " + std::to_string(N) + " numbers");
  }
  glm::vec<N, double> v;
  for (int i = 0; i < N; ++i) v[i] = limited_value(j[i], w, field, limit);
  return v;
}

// obj[field] as a list of 3 (2) numbers, each of which `limit` allows.
template <class Error>
Vec3 limited_vec3(const json& obj, const Place<Error>& w, const std::string& field,
                  const Limit& limit) {
  return limited_vector<3>(member(obj, w, field), w, field, limit);
}

template <class Error>
Vec2 limited_vec2(const json& obj, const Place<Error>& w, const std::string& field,
                  const Limit& limit) {
  return limited_vector<2>(member(obj, w, field), w, field, limit);
}

// Adds a segment's `frames` to `*total`, the frames of the script so far; fails naming the
// segment's field when the script then has more than kMaxScriptFrames.
template <class Error>
void add_script_frames(long* total, int frames, const Place<Error>& w) {
  *total += frames;
  if (*total > kMaxScriptFrames) {
    w.fail("frames", "the script has more than " + std::to_string(kMaxScriptFrames) + " frames");
  }
}

// The "camera" object of `root`: {"focal_px": f, "image": [width, height]}, f within
// limits::kFocalLength and the sizes within limits::kImageSize (pixels).
template <class Error>
Camera read_camera(const json& root, const Place<Error>& w) {
  const json& c = member(root, w, "camera");
  if (!c.is_object()) w.fail("camera", "must be an object");
  const double f =
      limited_value(member(c, w, "focal_px"), w, "camera.focal_px", limits::kFocalLength);
  const Vec2 size = limited_vector<2>(member(c, w, "image"), w, "camera.image", limits::kImageSize);
  return make_camera(f, static_cast<int>(size.x), static_cast<int>(size.y));
}

}  // namespace oflab::json_fields
