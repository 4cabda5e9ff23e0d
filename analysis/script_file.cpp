#include "analysis/script_file.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

namespace oflab {
namespace {

using nlohmann::json;

// Error context: "file: frame 3: field 'normal'".
struct Where {
  std::string origin;
  std::string part;  // "", "frame 3", "segment 1"

  [[noreturn]] void fail(const std::string& field, const std::string& message) const {
    std::string text = origin + ": ";
    if (!part.empty()) text += part + ": ";
    if (!field.empty()) text += "field '" + field + "': ";
    throw ScriptError(text + message);
  }
};

double number(const json& j, const Where& w, const std::string& field) {
  if (!j.is_number()) w.fail(field, "must be a number");
  const double v = j.get<double>();
  if (!std::isfinite(v)) w.fail(field, "must be finite");
  return v;
}

const json& member(const json& obj, const Where& w, const std::string& field) {
  if (!obj.contains(field)) w.fail(field, "is missing");
  return obj.at(field);
}

Vec3 vec3(const json& obj, const Where& w, const std::string& field) {
  const json& j = member(obj, w, field);
  if (!j.is_array() || j.size() != 3) w.fail(field, "must be a list of 3 numbers");
  return Vec3(number(j[0], w, field), number(j[1], w, field), number(j[2], w, field));
}

Vec2 vec2(const json& obj, const Where& w, const std::string& field) {
  const json& j = member(obj, w, field);
  if (!j.is_array() || j.size() != 2) w.fail(field, "must be a list of 2 numbers");
  return Vec2(number(j[0], w, field), number(j[1], w, field));
}

int positive_integer(const json& obj, const Where& w, const std::string& field) {
  const double v = number(member(obj, w, field), w, field);
  if (v != std::floor(v) || v < 1 || v > 1e6) w.fail(field, "must be a whole number from 1 to 1000000");
  return static_cast<int>(v);
}

void check_pose(const PlanePose& p, const Where& w) {
  if (glm::length(p.normal) < 1e-12) w.fail("normal", "must not be zero");
  if (glm::length(glm::cross(p.normal, p.up)) < 1e-9 * glm::length(p.normal) * glm::length(p.up)) {
    w.fail("up", "must be non-zero and not parallel to the normal");
  }
  if (!(p.point.z > 0.0)) w.fail("point", "plane centre is behind the camera (Z must be positive)");
}

Camera read_camera(const json& root, const Where& w) {
  const json& c = member(root, w, "camera");
  if (!c.is_object()) w.fail("camera", "must be an object");
  const double f = number(member(c, w, "focal_px"), w, "camera.focal_px");
  const Vec2 size = vec2(c, w, "image");
  if (f <= 0) w.fail("camera.focal_px", "must be positive");
  if (size.x < 1 || size.y < 1 || size.x > 8192 || size.y > 8192 || size.x != std::floor(size.x) ||
      size.y != std::floor(size.y)) {
    w.fail("camera.image", "must be two whole numbers from 1 to 8192");
  }
  return make_camera(f, static_cast<int>(size.x), static_cast<int>(size.y));
}

PlanePose read_pose(const json& obj, const Where& w, const PlanePose& base) {
  PlanePose p = base;
  p.point = vec3(obj, w, "point");
  p.normal = vec3(obj, w, "normal");
  p.up = vec3(obj, w, "up");
  check_pose(p, w);
  return p;
}

RigidMotion read_motion(const json& obj, const Where& w, MotionModel model) {
  RigidMotion m;
  m.velocity = vec3(obj, w, "velocity");
  m.omega = vec3(obj, w, "omega");
  m.model = model;
  return m;
}

}  // namespace

MotionScript parse_script(const std::string& text, const std::string& origin) {
  const Where top{origin, ""};
  json root;
  try {
    root = json::parse(text);
  } catch (const json::parse_error& e) {
    top.fail("", std::string("not valid JSON (") + e.what() + ")");
  }
  if (!root.is_object()) top.fail("", "must be a JSON object");
  MotionScript s;
  s.name = root.value("name", std::string());
  s.description = root.value("description", std::string());
  s.camera = read_camera(root, top);
  const json& plane = member(root, top, "plane");
  if (!plane.is_object()) top.fail("plane", "must be an object");
  PlanePose base;
  base.size = vec2(plane, top, "size");
  if (!(base.size.x > 0 && base.size.y > 0)) top.fail("size", "must be two positive numbers");
  MotionModel model = MotionModel::Screw;
  const std::string model_name = root.value("motion_model", std::string("screw"));
  if (!parse_motion_model(model_name.c_str(), &model)) {
    top.fail("motion_model", "must be one of screw, rt, centre");
  }
  const bool has_segments = root.contains("segments"), has_frames = root.contains("frames");
  if (has_segments == has_frames) top.fail("", "needs exactly one of 'segments' or 'frames'");
  if (has_segments) {
    const PlanePose initial = read_pose(plane, top, base);
    const json& segs = root.at("segments");
    if (!segs.is_array() || segs.empty()) top.fail("segments", "must be a non-empty list");
    std::vector<ScriptSegment> segments;
    for (size_t i = 0; i < segs.size(); ++i) {
      const Where w{origin, "segment " + std::to_string(i)};
      if (!segs[i].is_object()) w.fail("", "must be an object");
      ScriptSegment seg;
      seg.frames = positive_integer(segs[i], w, "frames");
      const RigidMotion m = read_motion(segs[i], w, model);
      seg.velocity = m.velocity;
      seg.omega = m.omega;
      segments.push_back(seg);
    }
    s.frames = expand_segments(initial, model, segments);
  } else {
    const json& frames = root.at("frames");
    if (!frames.is_array() || frames.empty()) top.fail("frames", "must be a non-empty list");
    for (size_t i = 0; i < frames.size(); ++i) {
      const Where w{origin, "frame " + std::to_string(i)};
      if (!frames[i].is_object()) w.fail("", "must be an object");
      ScriptFrame f;
      f.pose = read_pose(frames[i], w, base);
      f.motion = read_motion(frames[i], w, model);
      s.frames.push_back(f);
    }
  }
  if (s.frames.size() > 1000000) top.fail("", "more than 1000000 frames");
  return s;
}

MotionScript read_script_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ScriptError(path + ": cannot open the file");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_script(text.str(), path);
}

}  // namespace oflab
