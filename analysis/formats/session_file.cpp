#include "formats/session_file.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "engine/budget.h"
#include "engine/reuse_policy.h"
#include "formats/json_fields.h"

namespace oflab {
namespace {

using namespace json_fields;
using Where = Place<SessionError>;

json vec(const Vec3& v) { return json::array({v.x, v.y, v.z}); }
json vec(const Vec2& v) { return json::array({v.x, v.y}); }

// obj[field] as a finite number (json_fields::number of the member).
double number_field(const json& obj, const Where& w, const std::string& field) {
  return number(member(obj, w, field), w, field);
}

// obj[field] as an image side: a whole number of pixels from 1 to 8192, as in motion scripts.
int image_side(const json& obj, const Where& w, const std::string& field) {
  const double v = number_field(obj, w, field);
  if (v < 1 || v > 8192 || v != std::floor(v))
    w.fail(field, "must be a whole number from 1 to 8192");
  return static_cast<int>(v);
}

PlaneScene read_plane(const json& plane, const std::string& origin) {
  const Where in_plane{origin, "plane"};
  PlaneScene s;
  const json& camera = object(plane, in_plane, "camera");
  const Where in_camera{origin, "plane.camera"};
  s.camera =
      make_camera(number_field(camera, in_camera, "focal_px"),
                  image_side(camera, in_camera, "width"), image_side(camera, in_camera, "height"));
  const json& pose = object(plane, in_plane, "pose");
  const Where in_pose{origin, "plane.pose"};
  s.pose.point = vec3(pose, in_pose, "point");
  s.pose.normal = vec3(pose, in_pose, "normal");
  s.pose.up = vec3(pose, in_pose, "up");
  s.pose.size = vec2(pose, in_pose, "size");
  const json& motion = object(plane, in_plane, "motion");
  const Where in_motion{origin, "plane.motion"};
  s.motion.velocity = vec3(motion, in_motion, "velocity");
  s.motion.omega = vec3(motion, in_motion, "omega");
  if (!parse_motion_model(text(motion, in_motion, "model").c_str(), &s.motion.model)) {
    in_motion.fail("model", "unknown motion model");
  }
  const std::string problem = plane_scene_problem(s);
  if (!problem.empty()) in_plane.fail("", problem);
  return s;
}

// The layer content ("content", "content_quality"; sessions without them keep the texture).
void read_content(const json& j, const Where& w, LayerContent* content) {
  if (j.contains("content")) {
    if (!parse_content(text(j, w, "content"), &content->kind)) {
      w.fail("content", "one of " + content_name_list());
    }
  }
  if (j.contains("content_quality")) {
    const double q = number_field(j, w, "content_quality");
    if (q < 1 || q > kMaxContentQuality || q != std::floor(q)) {
      w.fail("content_quality",
             "must be a whole number in 1.." + std::to_string(kMaxContentQuality));
    }
    content->quality = static_cast<int>(q);
  }
}

// The budget policy's frame budget ("budget_pixels" or "budget_ms", at most one; sessions
// without either have none, so the policy takes its default).
void read_budget(const json& j, const Where& w, FrameBudget* budget) {
  const bool pixels = j.contains("budget_pixels"), ms = j.contains("budget_ms");
  if (pixels && ms) w.fail("budget_ms", "give budget_pixels or budget_ms, not both");
  if (!pixels && !ms) return;
  const char* field = pixels ? "budget_pixels" : "budget_ms";
  *budget = {pixels ? FrameBudget::Unit::kPixels : FrameBudget::Unit::kMilliseconds,
             number_field(j, w, field)};
  const std::string problem = frame_budget_problem(*budget);
  if (!problem.empty()) w.fail(field, problem);
}

EngineSettings read_settings(const json& j, const Where& w) {
  EngineSettings s;
  s.policy = find_reuse_policy(text(j, w, "mode"));
  if (!s.policy) w.fail("mode", "unknown reuse policy (one of " + reuse_policy_names() + ")");
  const json& t = member(j, w, "thresholds");
  if (!t.is_array() || t.size() != size_t(kTermCount)) {
    w.fail("thresholds", "must be a list of " + std::to_string(kTermCount) + " numbers");
  }
  for (int k = 0; k < kTermCount; ++k) {
    s.thresholds[size_t(k)] = number(t[size_t(k)], w, "thresholds");
    if (s.thresholds[size_t(k)] < 0) w.fail("thresholds", "must not be negative");
  }
  if (!parse_delta_policy(text(j, w, "delta"), &s.delta)) w.fail("delta", "unknown Delta policy");
  if (!parse_sampling(text(j, w, "sampling"), &s.sampling)) {
    w.fail("sampling", "one of " + sampling_name_list());
  }
  read_content(j, w, &s.content);
  read_budget(j, w, &s.budget);
  return s;
}

bool boolean(const json& obj, const Where& w, const std::string& field) {
  const json& value = member(obj, w, field);
  if (!value.is_boolean()) w.fail(field, "must be true or false");
  return value.get<bool>();
}

// The "window" object: the flow view's options, the basis, presentation, lesson, rate.
void read_window(const json& j, const Where& w, Session* s) {
  s->flow_part = text(j, w, "flow_part");
  const json& draw = member(j, w, "flow_draw");
  if (!draw.is_array() || draw.size() != s->flow_draw.size()) {
    w.fail("flow_draw", "must be a list of " + std::to_string(s->flow_draw.size()) + " booleans");
  }
  for (size_t k = 0; k < s->flow_draw.size(); ++k) {
    if (!draw[k].is_boolean()) w.fail("flow_draw", "must be a list of booleans");
    s->flow_draw[k] = draw[k].get<bool>();
  }
  s->basis = text(j, w, "basis");
  s->basis_playing = boolean(j, w, "basis_playing");
  s->presentation = boolean(j, w, "presentation");
  s->lesson = text(j, w, "lesson");
  const double rate = number_field(j, w, "play_rate");
  if (rate < 1 || rate > 1000 || rate != std::floor(rate)) {
    w.fail("play_rate", "must be a whole number of frames per second in 1..1000");
  }
  s->play_rate = int(rate);
}

}  // namespace

std::string session_to_json(const Session& s) {
  json j;
  j["format"] = "oflab-session";
  j["version"] = 1;
  j["plane"] = {{"camera",
                 {{"focal_px", s.plane.camera.focal_px},
                  {"width", s.plane.camera.width},
                  {"height", s.plane.camera.height}}},
                {"pose",
                 {{"point", vec(s.plane.pose.point)},
                  {"normal", vec(s.plane.pose.normal)},
                  {"up", vec(s.plane.pose.up)},
                  {"size", vec(s.plane.pose.size)}}},
                {"motion",
                 {{"velocity", vec(s.plane.motion.velocity)},
                  {"omega", vec(s.plane.motion.omega)},
                  {"model", motion_model_name(s.plane.motion.model)}}}};
  j["script"] = s.script;
  j["texture"] = s.texture;
  j["animation"] = {
      {"source", {{"kind", s.source_kind}, {"name", s.source_name}, {"viewer", s.viewer_script}}},
      {"mode", s.settings.policy->name},
      {"thresholds", json::array({s.settings.thresholds[0], s.settings.thresholds[1],
                                  s.settings.thresholds[2], s.settings.thresholds[3]})},
      {"delta", delta_policy_name(s.settings.delta)},
      {"sampling", sampling_name(s.settings.sampling)},
      {"content", content_name(s.settings.content.kind)},
      {"content_quality", s.settings.content.quality},
      {"display", s.display},
      {"exact_renderer", s.exact_renderer}};
  if (s.settings.budget.unit == FrameBudget::Unit::kPixels) {
    j["animation"]["budget_pixels"] = s.settings.budget.amount;
  } else if (s.settings.budget.unit == FrameBudget::Unit::kMilliseconds) {
    j["animation"]["budget_ms"] = s.settings.budget.amount;
  }
  j["frame"] = s.frame;
  j["view"] = s.view;
  json draw = json::array();
  for (bool on : s.flow_draw) draw.push_back(on);
  j["window"] = {{"flow_part", s.flow_part},
                 {"flow_draw", draw},
                 {"basis", s.basis},
                 {"basis_playing", s.basis_playing},
                 {"presentation", s.presentation},
                 {"lesson", s.lesson},
                 {"play_rate", s.play_rate}};
  return j.dump(2) + "\n";
}

Session parse_session(const std::string& json_text, const std::string& origin) {
  const Where top{origin, ""};
  const json root = parse_object(json_text, top);
  if (text(root, top, "format") != "oflab-session") top.fail("format", "must be \"oflab-session\"");
  if (number_field(root, top, "version") != 1) top.fail("version", "only version 1 is known");
  Session s;
  s.plane = read_plane(object(root, top, "plane"), origin);
  s.script = text(root, top, "script");
  s.texture = text(root, top, "texture");
  const json& animation = object(root, top, "animation");
  const Where in_animation{origin, "animation"};
  const json& source = object(animation, in_animation, "source");
  const Where in_source{origin, "animation.source"};
  s.source_kind = text(source, in_source, "kind");  // a source kind's name, checked when applied
  s.source_name = text(source, in_source, "name");
  s.viewer_script = text(source, in_source, "viewer");
  s.settings = read_settings(animation, in_animation);
  s.display = text(animation, in_animation, "display");
  if (animation.contains("exact_renderer")) {  // a renderer's name, checked when applied
    s.exact_renderer = text(animation, in_animation, "exact_renderer");
  }
  const double frame = number_field(root, top, "frame");
  if (frame < 0 || frame != std::floor(frame)) top.fail("frame", "must be a whole number >= 0");
  s.frame = int(frame);
  s.view = text(root, top, "view");
  if (root.contains("window"))
    read_window(object(root, top, "window"), Where{origin, "window"}, &s);
  return s;
}

Session read_session_file(const std::string& path) {
  return parse_session(read_file_text<SessionError>(path),
                       std::filesystem::path(path).filename().string());
}

void write_session_file(const std::string& path, const Session& session, bool overwrite) {
  if (!overwrite && std::filesystem::exists(path)) {
    throw SessionError(path + ": exists; not overwritten");
  }
  std::ofstream out(path);
  out << session_to_json(session);
  if (!out) throw SessionError(path + ": cannot be written");
}

}  // namespace oflab
