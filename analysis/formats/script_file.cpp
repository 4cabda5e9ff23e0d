#include "formats/script_file.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "formats/json_fields.h"

namespace oflab {
namespace {

using namespace json_fields;
using Where = json_fields::Place<ScriptError>;

void check_pose(const PlanePose& p, const Where& w) {
  if (glm::length(p.normal) < 1e-12) w.fail("normal", "must not be zero");
  if (glm::length(glm::cross(p.normal, p.up)) < 1e-9 * glm::length(p.normal) * glm::length(p.up)) {
    w.fail("up", "must be non-zero and not parallel to the normal");
  }
  if (!(p.point.z > 0.0)) w.fail("point", "plane centre is behind the camera (Z must be positive)");
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
  m.velocity = limited_vec3(obj, w, "velocity", limits::kVelocity);
  m.omega = limited_vec3(obj, w, "omega", limits::kAngularVelocity);
  m.model = model;
  return m;
}

}  // namespace

MotionScript parse_script(const std::string& text, const std::string& origin) {
  const Where top{origin, ""};
  const json root = parse_object(text, top);
  MotionScript s;
  s.name = optional_text(root, top, "name", "");
  s.description = optional_text(root, top, "description", "");
  s.camera = read_camera(root, top);
  const json& plane = member(root, top, "plane");
  if (!plane.is_object()) top.fail("plane", "must be an object");
  PlanePose base;
  base.size = limited_vec2(plane, top, "size", limits::kPlaneSize);
  MotionModel model = MotionModel::kScrew;
  const std::string model_name = optional_text(root, top, "motion_model", "screw");
  if (!parse_motion_model(model_name.c_str(), &model)) {
    top.fail("motion_model", "must be one of " + motion_model_name_list());
  }
  const bool has_segments = root.contains("segments"), has_frames = root.contains("frames");
  if (has_segments == has_frames) top.fail("", "needs exactly one of 'segments' or 'frames'");
  if (has_segments) {
    const PlanePose initial = read_pose(plane, top, base);
    const json& segs = root.at("segments");
    if (!segs.is_array() || segs.empty()) top.fail("segments", "must be a non-empty list");
    std::vector<ScriptSegment> segments;
    long total = 0;  // checked against the cap before anything is expanded
    for (size_t i = 0; i < segs.size(); ++i) {
      const Where w{origin, "segment " + std::to_string(i + 1)};  // from 1, as steps and claims
      if (!segs[i].is_object()) w.fail("", "must be an object");
      ScriptSegment seg;
      seg.frames = limited_integer(segs[i], w, "frames", limits::kPlayedFrames);
      add_script_frames(&total, seg.frames, w);
      const RigidMotion m = read_motion(segs[i], w, model);
      seg.velocity = m.velocity;
      seg.omega = m.omega;
      segments.push_back(seg);
    }
    s.frames = expand_segments(initial, model, segments);
  } else {
    const json& frames = root.at("frames");
    if (!frames.is_array() || frames.empty()) top.fail("frames", "must be a non-empty list");
    if (frames.size() > size_t(kMaxScriptFrames)) {
      top.fail("frames", "more than " + std::to_string(kMaxScriptFrames) + " frames");
    }
    for (size_t i = 0; i < frames.size(); ++i) {
      const Where w{origin, "frame " + std::to_string(i)};
      if (!frames[i].is_object()) w.fail("", "must be an object");
      ScriptFrame f;
      f.pose = read_pose(frames[i], w, base);
      f.motion = read_motion(frames[i], w, model);
      s.frames.push_back(f);
    }
  }
  return s;
}

MotionScript read_script_file(const std::string& path) {
  return parse_script(read_file_text<ScriptError>(path), path);
}

}  // namespace oflab
