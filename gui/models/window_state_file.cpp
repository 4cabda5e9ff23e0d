#include "models/window_state_file.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <vector>

#include "engine/reuse_policy.h"
#include "formats/atomic_file.h"
#include "formats/json_fields.h"

namespace oflab {
namespace {

using namespace json_fields;
using Where = Place<SessionError>;

json vec(const Vec3& v) { return json::array({v.x, v.y, v.z}); }
json vec(const Vec2& v) { return json::array({v.x, v.y}); }

double number_field(const json& obj, const Where& w, const std::string& field) {
  return number(member(obj, w, field), w, field);
}

bool boolean(const json& obj, const Where& w, const std::string& field) {
  const json& value = member(obj, w, field);
  if (!value.is_boolean()) w.fail(field, "must be true or false");
  return value.get<bool>();
}

// obj[field] as a whole number (its range is checked by window_state_problem).
int whole(const json& obj, const Where& w, const std::string& field) {
  const double v = number_field(obj, w, field);
  if (v != std::floor(v)) w.fail(field, "must be a whole number");
  return int(v);
}

// Reads obj[field] into *out with `read` when the field is present.
template <class T, class Read>
void optional(const json& obj, const char* field, T* out, Read read) {
  if (obj.contains(field)) *out = read(field);
}

PlaneScene read_plane(const json& plane, const std::string& origin) {
  const Where in_plane{origin, "plane"};
  only_fields(plane, in_plane, {"camera", "pose", "motion"});
  PlaneScene s;
  const json& camera = object(plane, in_plane, "camera");
  const Where in_camera{origin, "plane.camera"};
  only_fields(camera, in_camera, {"focal_px", "width", "height"});
  s.camera = make_camera(number_field(camera, in_camera, "focal_px"),
                         whole(camera, in_camera, "width"), whole(camera, in_camera, "height"));
  const json& pose = object(plane, in_plane, "pose");
  const Where in_pose{origin, "plane.pose"};
  only_fields(pose, in_pose, {"point", "normal", "up", "size", "texture_size"});
  s.pose.point = vec3(pose, in_pose, "point");
  s.pose.normal = vec3(pose, in_pose, "normal");
  s.pose.up = vec3(pose, in_pose, "up");
  s.pose.size = vec2(pose, in_pose, "size");
  if (pose.contains("texture_size")) {
    const Vec2 t = vec2(pose, in_pose, "texture_size");
    if (t.x < 1 || t.y < 1 || t.x > 16384 || t.y > 16384 || t.x != std::floor(t.x) ||
        t.y != std::floor(t.y)) {
      in_pose.fail("texture_size", "must be two whole numbers from 1 to 16384");
    }
    s.pose.texture_size = {int(t.x), int(t.y)};
  }
  const json& motion = object(plane, in_plane, "motion");
  const Where in_motion{origin, "plane.motion"};
  only_fields(motion, in_motion, {"velocity", "omega", "model"});
  s.motion.velocity = vec3(motion, in_motion, "velocity");
  s.motion.omega = vec3(motion, in_motion, "omega");
  if (!parse_motion_model(text(motion, in_motion, "model").c_str(), &s.motion.model)) {
    in_motion.fail("model", "one of " + motion_model_name_list());
  }
  return s;
}

json plane_object(const PlaneScene& p) {
  return {
      {"camera",
       {{"focal_px", p.camera.focal_px}, {"width", p.camera.width}, {"height", p.camera.height}}},
      {"pose",
       {{"point", vec(p.pose.point)},
        {"normal", vec(p.pose.normal)},
        {"up", vec(p.pose.up)},
        {"size", vec(p.pose.size)},
        {"texture_size", json::array({p.pose.texture_size.x, p.pose.texture_size.y})}}},
      {"motion",
       {{"velocity", vec(p.motion.velocity)},
        {"omega", vec(p.motion.omega)},
        {"model", motion_model_name(p.motion.model)}}}};
}

void read_thresholds(const json& j, const Where& w, EngineSettings* s) {
  const json& t = member(j, w, "thresholds");
  if (!t.is_array() || t.size() != size_t(kTermCount)) {
    w.fail("thresholds", "must be a list of " + std::to_string(kTermCount) + " numbers");
  }
  for (int k = 0; k < kTermCount; ++k)
    s->thresholds[size_t(k)] = number(t[size_t(k)], w, "thresholds");
}

// The engine settings of an "animation" object (both versions), over `s`.
void read_settings(const json& j, const Where& w, EngineSettings* s) {
  if (j.contains("mode")) {
    s->policy = find_reuse_policy(text(j, w, "mode"));
    if (!s->policy) w.fail("mode", "unknown reuse policy (one of " + reuse_policy_names() + ")");
  }
  if (j.contains("thresholds")) read_thresholds(j, w, s);
  if (j.contains("delta") && !parse_delta_policy(text(j, w, "delta"), &s->delta)) {
    w.fail("delta", "one of " + delta_policy_name_list());
  }
  if (j.contains("sampling") && !parse_sampling(text(j, w, "sampling"), &s->sampling)) {
    w.fail("sampling", "one of " + sampling_name_list());
  }
  if (j.contains("content") && !parse_content(text(j, w, "content"), &s->content.kind)) {
    w.fail("content", "one of " + content_name_list());
  }
  optional(j, "content_quality", &s->content.quality,
           [&](const char* f) { return whole(j, w, f); });
  optional(j, "cadence", &s->cadence, [&](const char* f) { return whole(j, w, f); });
}

// The stabilization plane: {"automatic": true} or {"automatic": false, "point": [x, y, z],
// "normal": [x, y, z]} (point and normal optional, over `plane`).
StabilizationPlane read_stabilization(const json& j, const std::string& origin,
                                      StabilizationPlane plane) {
  const Where w{origin, "animation.stabilization"};
  only_fields(j, w, {"automatic", "point", "normal"});
  optional(j, "automatic", &plane.automatic, [&](const char* f) { return boolean(j, w, f); });
  optional(j, "point", &plane.point, [&](const char* f) { return vec3(j, w, f); });
  optional(j, "normal", &plane.normal, [&](const char* f) { return vec3(j, w, f); });
  return plane;
}

// Version 1's budget: "budget_pixels" or "budget_ms", at most one.
void read_budget_v1(const json& j, const Where& w, FrameBudget* budget) {
  const bool pixels = j.contains("budget_pixels"), ms = j.contains("budget_ms");
  if (pixels && ms) w.fail("budget_ms", "give budget_pixels or budget_ms, not both");
  if (!pixels && !ms) return;
  const char* field = pixels ? "budget_pixels" : "budget_ms";
  *budget = {pixels ? FrameBudget::Unit::kPixels : FrameBudget::Unit::kMilliseconds,
             number_field(j, w, field)};
}

const char* budget_unit_name(FrameBudget::Unit unit) {
  switch (unit) {
    case FrameBudget::Unit::kPixels:
      return "pixels";
    case FrameBudget::Unit::kMilliseconds:
      return "ms";
    default:
      return "none";
  }
}

// Version 2's budget: {"unit": "none" | "pixels" | "ms", "amount": number}.
FrameBudget read_budget(const json& j, const std::string& origin) {
  const Where w{origin, "animation.budget"};
  only_fields(j, w, {"unit", "amount"});
  const std::string unit = text(j, w, "unit");
  FrameBudget budget;
  if (unit == "pixels") {
    budget.unit = FrameBudget::Unit::kPixels;
  } else if (unit == "ms") {
    budget.unit = FrameBudget::Unit::kMilliseconds;
  } else if (unit != "none") {
    w.fail("unit", "one of none, pixels, ms");
  }
  if (budget.unit != FrameBudget::Unit::kNone) budget.amount = number_field(j, w, "amount");
  return budget;
}

SourceChoice read_source(const json& j, const std::string& origin, SourceChoice source) {
  const Where w{origin, "animation.source"};
  only_fields(j, w, {"kind", "name", "viewer"});
  // The kind's name is checked when applied (the source-kind table is the window's).
  optional(j, "kind", &source.kind, [&](const char* f) { return text(j, w, f); });
  optional(j, "name", &source.name, [&](const char* f) { return text(j, w, f); });
  optional(j, "viewer", &source.viewer, [&](const char* f) { return text(j, w, f); });
  return source;
}

std::vector<std::string> read_compared(const json& j, const Where& w) {
  const json& list = member(j, w, "compared");
  if (!list.is_array()) w.fail("compared", "must be a list of policy names");
  std::vector<std::string> names;
  for (const json& name : list) {
    if (!name.is_string()) w.fail("compared", "must be a list of policy names");
    names.push_back(name.get<std::string>());
  }
  return names;
}

void read_animation(const json& j, const std::string& origin, WindowState* s) {
  const Where w{origin, "animation"};
  only_fields(
      j, w,
      {"source", "mode", "thresholds", "delta", "sampling", "content", "content_quality", "budget",
       "cadence", "stabilization", "display", "compared", "exact_renderer", "zoom"});
  if (j.contains("source")) s->source = read_source(object(j, w, "source"), origin, s->source);
  read_settings(j, w, &s->settings);
  if (j.contains("budget")) s->settings.budget = read_budget(object(j, w, "budget"), origin);
  if (j.contains("stabilization")) {
    s->settings.stabilization =
        read_stabilization(object(j, w, "stabilization"), origin, s->settings.stabilization);
  }
  if (j.contains("display") && !parse_panel_display(text(j, w, "display"), &s->display)) {
    w.fail("display", "one of " + panel_display_names());
  }
  if (j.contains("compared")) s->compared = read_compared(j, w);
  optional(j, "exact_renderer", &s->exact_renderer, [&](const char* f) { return text(j, w, f); });
  optional(j, "zoom", &s->zoom, [&](const char* f) { return number_field(j, w, f); });
}

FlowDisplay read_flow(const json& j, const std::string& origin, FlowDisplay d) {
  const Where w{origin, "flow"};
  std::vector<std::string> known = {"part", "spacing_px"};
  for (const FlowDrawOption& option : flow_draw_options()) known.push_back(option.key);
  only_fields(j, w, known);
  if (j.contains("part") && !parse_flow_part(text(j, w, "part"), &d.part)) {
    w.fail("part", "unknown flow part");
  }
  for (const FlowDrawOption& option : flow_draw_options()) {
    if (j.contains(option.key)) d.*option.member = boolean(j, w, option.key);
  }
  optional(j, "spacing_px", &d.spacing_px, [&](const char* f) { return number_field(j, w, f); });
  return d;
}

json flow_object(const FlowDisplay& d) {
  json j = {{"part", flow_part_key(d.part)}, {"spacing_px", d.spacing_px}};
  for (const FlowDrawOption& option : flow_draw_options()) j[option.key] = d.*option.member;
  return j;
}

// The explorer's values present in `j`, by key, over `terms`; their limits are checked with
// the rest (window_state_problem).
void read_explorer_terms(const json& j, const std::string& origin, ExplorerTerms* terms) {
  const Where w{origin, "basis.terms"};
  std::vector<std::string> keys;
  for (const ExplorerTerm& term : explorer_terms()) keys.push_back(term.key);
  only_fields(j, w, keys);
  for (int k = 0; k < kExplorerTermCount; ++k) {
    const char* key = explorer_terms()[size_t(k)].key;
    optional(j, key, &(*terms)[size_t(k)], [&](const char* f) { return number_field(j, w, f); });
  }
}

json explorer_terms_object(const ExplorerTerms& terms) {
  json j = json::object();
  for (int k = 0; k < kExplorerTermCount; ++k)
    j[explorer_terms()[size_t(k)].key] = terms[size_t(k)];
  return j;
}

void read_basis(const json& j, const std::string& origin, WindowState* s) {
  const Where w{origin, "basis"};
  only_fields(j, w, {"kind", "playing", "explorer", "terms"});
  if (j.contains("kind") && !parse_basis_kind(text(j, w, "kind"), &s->basis)) {
    w.fail("kind", "one of taylor, waxman-ullman, planar");
  }
  optional(j, "playing", &s->basis_playing, [&](const char* f) { return boolean(j, w, f); });
  optional(j, "explorer", &s->basis_explorer, [&](const char* f) { return boolean(j, w, f); });
  if (j.contains("terms")) read_explorer_terms(object(j, w, "terms"), origin, &s->explorer_terms);
}

// The limits of every number (one rule per value: window_state_problem), as a file error.
void check_limits(const WindowState& s, const std::string& origin) {
  const std::string problem = window_state_problem(s);
  if (problem.empty()) return;
  const size_t colon = problem.find(": ");
  const std::string field = problem.substr(0, colon);
  const size_t dot = field.rfind('.');
  const Where w{origin, dot == std::string::npos ? "" : field.substr(0, dot)};
  w.fail(dot == std::string::npos ? field : field.substr(dot + 1), problem.substr(colon + 2));
}

// Version 1: every part present, the flow options as six booleans in a fixed order.
WindowState read_version_1(const json& root, const std::string& origin) {
  const Where top{origin, ""};
  WindowState s;
  s.plane = read_plane(object(root, top, "plane"), origin);
  s.script = text(root, top, "script");
  s.texture = text(root, top, "texture");
  const json& animation = object(root, top, "animation");
  const Where in_animation{origin, "animation"};
  const json& source = object(animation, in_animation, "source");
  const Where in_source{origin, "animation.source"};
  s.source = {text(source, in_source, "kind"), text(source, in_source, "name"),
              text(source, in_source, "viewer")};
  text(animation, in_animation, "mode");  // required in version 1
  member(animation, in_animation, "thresholds");
  read_settings(animation, in_animation, &s.settings);
  read_budget_v1(animation, in_animation, &s.settings.budget);
  if (!parse_panel_display(text(animation, in_animation, "display"), &s.display)) {
    in_animation.fail("display", "one of " + panel_display_names());
  }
  s.exact_renderer = optional_text(animation, in_animation, "exact_renderer", s.exact_renderer);
  s.frame = whole(root, top, "frame");
  s.view = text(root, top, "view");
  if (!root.contains("window")) return s;
  const json& window = object(root, top, "window");
  const Where w{origin, "window"};
  if (!parse_flow_part(text(window, w, "flow_part"), &s.flow.part)) {
    w.fail("flow_part", "unknown flow part");
  }
  const json& draw = member(window, w, "flow_draw");
  if (!draw.is_array() || draw.size() != 6) w.fail("flow_draw", "must be a list of 6 booleans");
  bool* flags[6] = {&s.flow.arrows,  &s.flow.streamlines,   &s.flow.colour_wheel,
                    &s.flow.texture, &s.flow.zoom_to_plane, &s.flow.common_scale};
  for (size_t k = 0; k < 6; ++k) {
    if (!draw[k].is_boolean()) w.fail("flow_draw", "must be a list of booleans");
    *flags[k] = draw[k].get<bool>();
  }
  if (!parse_basis_kind(text(window, w, "basis"), &s.basis)) {
    w.fail("basis", "one of taylor, waxman-ullman, planar");
  }
  s.basis_playing = boolean(window, w, "basis_playing");
  s.presentation = boolean(window, w, "presentation");
  s.lesson = text(window, w, "lesson");
  s.play_rate = whole(window, w, "play_rate");
  return s;
}

}  // namespace

json window_state_object(const WindowState& s) {
  const EngineSettings& e = s.settings;
  return {
      {"view", s.view},
      {"frame", s.frame},
      {"playing", s.playing},
      {"play_rate", s.play_rate},
      {"presentation", s.presentation},
      {"scene_panel", s.scene_panel},
      {"cause_and_effect", s.cause_and_effect},
      {"lesson", s.lesson},
      {"lesson_step", s.lesson_step},
      {"flow", flow_object(s.flow)},
      {"basis",
       {{"kind", basis_key(s.basis)},
        {"playing", s.basis_playing},
        {"explorer", s.basis_explorer},
        {"terms", explorer_terms_object(s.explorer_terms)}}},
      {"plane", plane_object(s.plane)},
      {"script", s.script},
      {"texture", s.texture},
      {"animation",
       {{"source", {{"kind", s.source.kind}, {"name", s.source.name}, {"viewer", s.source.viewer}}},
        {"mode", e.policy->name},
        {"thresholds",
         json::array({e.thresholds[0], e.thresholds[1], e.thresholds[2], e.thresholds[3]})},
        {"delta", delta_policy_name(e.delta)},
        {"sampling", sampling_name(e.sampling)},
        {"content", content_name(e.content.kind)},
        {"content_quality", e.content.quality},
        {"budget", {{"unit", budget_unit_name(e.budget.unit)}, {"amount", e.budget.amount}}},
        {"cadence", e.cadence},
        {"stabilization",
         {{"automatic", e.stabilization.automatic},
          {"point", vec(e.stabilization.point)},
          {"normal", vec(e.stabilization.normal)}}},
        {"display", panel_display_name(s.display)},
        {"compared", s.compared},
        {"exact_renderer", s.exact_renderer},
        {"zoom", s.zoom}}}};
}

std::string window_state_to_json(const WindowState& state) {
  json j = {{"format", "oflab-session"}, {"version", kSessionFormatVersion}};
  j.update(window_state_object(state));
  return j.dump(2) + "\n";
}

WindowState read_window_state_object(const json& j, const std::string& origin,
                                     const std::string& part, WindowState s) {
  const Where w{origin, part};
  only_fields(
      j, w,
      {"view", "frame", "playing", "play_rate", "presentation", "scene_panel", "cause_and_effect",
       "lesson", "lesson_step", "flow", "basis", "plane", "script", "texture", "animation"});
  const auto name = [&](const char* f) { return text(j, w, f); };
  const auto flag = [&](const char* f) { return boolean(j, w, f); };
  optional(j, "view", &s.view, name);
  optional(j, "frame", &s.frame, [&](const char* f) { return whole(j, w, f); });
  optional(j, "playing", &s.playing, flag);
  optional(j, "play_rate", &s.play_rate, [&](const char* f) { return whole(j, w, f); });
  optional(j, "presentation", &s.presentation, flag);
  optional(j, "scene_panel", &s.scene_panel, flag);
  optional(j, "cause_and_effect", &s.cause_and_effect, flag);
  optional(j, "lesson", &s.lesson, name);
  optional(j, "lesson_step", &s.lesson_step, [&](const char* f) { return whole(j, w, f); });
  if (j.contains("flow")) s.flow = read_flow(object(j, w, "flow"), origin, s.flow);
  if (j.contains("basis")) read_basis(object(j, w, "basis"), origin, &s);
  if (j.contains("plane")) s.plane = read_plane(object(j, w, "plane"), origin);
  optional(j, "script", &s.script, name);
  optional(j, "texture", &s.texture, name);
  if (j.contains("animation")) read_animation(object(j, w, "animation"), origin, &s);
  check_limits(s, origin);
  return s;
}

WindowState parse_session(const std::string& json_text, const std::string& origin) {
  const Where top{origin, ""};
  json root = parse_object(json_text, top);
  if (text(root, top, "format") != "oflab-session") top.fail("format", "must be \"oflab-session\"");
  const double version = number_field(root, top, "version");
  if (version == 1) {
    const WindowState s = read_version_1(root, origin);
    check_limits(s, origin);
    return s;
  }
  if (version != kSessionFormatVersion) top.fail("version", "must be 1 or 2");
  root.erase("format");
  root.erase("version");
  return read_window_state_object(root, origin, "", WindowState());
}

WindowState read_session_file(const std::string& path) {
  return parse_session(read_file_text<SessionError>(path),
                       std::filesystem::path(path).filename().string());
}

void write_session_file(const std::string& path, const WindowState& state, bool overwrite) {
  try {
    write_file_atomically(path, window_state_to_json(state),
                          overwrite ? Overwrite::kReplace : Overwrite::kRefuse);
  } catch (const FileWriteError& e) {
    throw SessionError(e.what());
  }
}

}  // namespace oflab
