#include "app/session_file.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace oflab {
namespace {

using nlohmann::json;

json vec(const Vec3& v) { return json::array({v.x, v.y, v.z}); }
json vec(const Vec2& v) { return json::array({v.x, v.y}); }

// Field access that names the field in every error.
class Reader {
 public:
  explicit Reader(std::string origin) : origin_(std::move(origin)) {}
  [[noreturn]] void fail(const std::string& field, const std::string& why) const {
    throw SessionError(origin_ + ": field '" + field + "': " + why);
  }
  const json& at(const json& j, const std::string& field) const {
    if (!j.is_object() || !j.contains(field)) fail(field, "missing");
    return j.at(field);
  }
  double number(const json& j, const std::string& field) const {
    const json& v = at(j, field);
    if (!v.is_number() || !std::isfinite(v.get<double>())) fail(field, "must be a finite number");
    return v.get<double>();
  }
  std::string text(const json& j, const std::string& field) const {
    const json& v = at(j, field);
    if (!v.is_string()) fail(field, "must be a string");
    return v.get<std::string>();
  }
  std::vector<double> numbers(const json& j, const std::string& field, size_t n) const {
    const json& v = at(j, field);
    if (!v.is_array() || v.size() != n) fail(field, "must be an array of " + std::to_string(n));
    std::vector<double> out;
    for (const json& e : v) {
      if (!e.is_number() || !std::isfinite(e.get<double>())) fail(field, "must hold finite numbers");
      out.push_back(e.get<double>());
    }
    return out;
  }
  Vec3 vec3(const json& j, const std::string& field) const {
    const auto v = numbers(j, field, 3);
    return Vec3(v[0], v[1], v[2]);
  }

 private:
  std::string origin_;
};

PlaneScene read_plane(const Reader& r, const json& j) {
  PlaneScene s;
  const json& camera = r.at(j, "camera");
  s.camera = make_camera(r.number(camera, "focal_px"), int(r.number(camera, "width")),
                         int(r.number(camera, "height")));
  const json& pose = r.at(j, "pose");
  s.pose.point = r.vec3(pose, "point");
  s.pose.normal = r.vec3(pose, "normal");
  s.pose.up = r.vec3(pose, "up");
  const auto size = r.numbers(pose, "size", 2);
  s.pose.size = Vec2(size[0], size[1]);
  const json& motion = r.at(j, "motion");
  s.motion.velocity = r.vec3(motion, "velocity");
  s.motion.omega = r.vec3(motion, "omega");
  if (!parse_motion_model(r.text(motion, "model").c_str(), &s.motion.model)) {
    r.fail("model", "unknown motion model");
  }
  const std::string problem = plane_scene_problem(s);
  if (!problem.empty()) r.fail("plane", problem);
  return s;
}

EngineSettings read_settings(const Reader& r, const json& j) {
  EngineSettings s;
  s.policy = find_reuse_policy(r.text(j, "mode"));
  if (!s.policy) r.fail("mode", "unknown reuse policy (one of " + reuse_policy_names() + ")");
  const auto t = r.numbers(j, "thresholds", kTermCount);
  for (int k = 0; k < kTermCount; ++k) {
    if (t[size_t(k)] < 0) r.fail("thresholds", "must not be negative");
    s.thresholds[size_t(k)] = t[size_t(k)];
  }
  if (!parse_delta_policy(r.text(j, "delta"), &s.delta)) r.fail("delta", "unknown Delta policy");
  if (!parse_sampling(r.text(j, "sampling"), &s.sampling)) {
    r.fail("sampling", "one of " + sampling_name_list());
  }
  return s;
}

}  // namespace

std::string session_to_json(const Session& s) {
  json j;
  j["format"] = "oflab-session";
  j["version"] = 1;
  j["plane"] = {{"camera", {{"focal_px", s.plane.camera.focal_px},
                            {"width", s.plane.camera.width},
                            {"height", s.plane.camera.height}}},
                {"pose", {{"point", vec(s.plane.pose.point)}, {"normal", vec(s.plane.pose.normal)},
                          {"up", vec(s.plane.pose.up)}, {"size", vec(s.plane.pose.size)}}},
                {"motion", {{"velocity", vec(s.plane.motion.velocity)},
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
      {"display", s.display}};
  j["frame"] = s.frame;
  j["view"] = s.view;
  return j.dump(2) + "\n";
}

Session parse_session(const std::string& text, const std::string& origin) {
  const json j = json::parse(text, nullptr, false);
  if (j.is_discarded()) throw SessionError(origin + ": not valid JSON");
  const Reader r(origin);
  if (r.text(j, "format") != "oflab-session") r.fail("format", "must be \"oflab-session\"");
  if (r.number(j, "version") != 1) r.fail("version", "only version 1 is known");
  Session s;
  s.plane = read_plane(r, r.at(j, "plane"));
  s.script = r.text(j, "script");
  s.texture = r.text(j, "texture");
  const json& animation = r.at(j, "animation");
  const json& source = r.at(animation, "source");
  s.source_kind = r.text(source, "kind");
  if (s.source_kind != "plane" && s.source_kind != "script" && s.source_kind != "scene") {
    r.fail("kind", "must be plane, script or scene");
  }
  s.source_name = r.text(source, "name");
  s.viewer_script = r.text(source, "viewer");
  s.settings = read_settings(r, animation);
  s.display = r.text(animation, "display");
  const double frame = r.number(j, "frame");
  if (frame < 0 || frame != std::floor(frame) || frame > 1e6) r.fail("frame", "must be a whole number >= 0");
  s.frame = int(frame);
  s.view = r.text(j, "view");
  return s;
}

Session read_session_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw SessionError(path + ": cannot be read");
  std::stringstream text;
  text << in.rdbuf();
  return parse_session(text.str(), std::filesystem::path(path).filename().string());
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
