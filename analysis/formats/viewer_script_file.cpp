#include "formats/viewer_script_file.h"

#include <filesystem>
#include <nlohmann/json.hpp>

#include "formats/datasets.h"
#include "formats/json_fields.h"

namespace oflab {
namespace {

namespace fs = std::filesystem;
using namespace json_fields;
using Where = json_fields::Place<ViewerScriptError>;

}  // namespace

ViewerScript parse_viewer_script(const std::string& text, const std::string& origin) {
  const Where top{origin, ""};
  const json root = parse_object(text, top);
  if (root.contains("format") && root.at("format") != "oflab-viewer-script") {
    top.fail("format", "must be \"oflab-viewer-script\"");
  }
  ViewerScript script;
  script.name = optional_text(root, top, "name", fs::path(origin).stem().string());
  script.description = optional_text(root, top, "description", "");
  script.camera = read_camera(root, top);
  const json& viewer = member(root, top, "viewer");
  if (!viewer.is_object()) top.fail("viewer", "must be an object");
  const Where vw{origin, "viewer"};
  const Vec3 position = vec3(viewer, vw, "position");
  const Vec3 target = vec3(viewer, vw, "look_at");
  const Vec3 up = vec3(viewer, vw, "up");
  const std::string problem = look_at_problem(position, target, up);
  // A problem of `up` (zero, or parallel to the view direction) names up, not look_at.
  if (!problem.empty()) vw.fail(problem.rfind("up ", 0) == 0 ? "up" : "look_at", problem);
  const json& segs = member(root, top, "segments");
  if (!segs.is_array() || segs.empty()) top.fail("segments", "must be a non-empty list");
  std::vector<ViewerSegment> segments;
  long total = 0;
  for (std::size_t i = 0; i < segs.size(); ++i) {
    const Where w{origin, "segment " + std::to_string(i + 1)};  // from 1, as steps and claims
    if (!segs[i].is_object()) w.fail("", "must be an object");
    ViewerSegment s;
    s.frames = limited_integer(segs[i], w, "frames", limits::kPlayedFrames);
    s.camera_velocity = limited_vec3(segs[i], w, "velocity", limits::kVelocity);
    s.camera_omega = limited_vec3(segs[i], w, "omega", limits::kAngularVelocity);
    add_script_frames(&total, s.frames, w);
    segments.push_back(s);
  }
  script.frames = expand_viewer_segments(look_at(position, target, up), segments);
  return script;
}

ViewerScript read_viewer_script_file(const std::string& path) {
  return parse_viewer_script(read_file_text<ViewerScriptError>(path), path);
}

std::vector<std::string> shipped_viewer_script_names() { return shipped_names("viewer-scripts"); }

std::string resolve_viewer_script_path(const std::string& name_or_file) {
  return resolve_shipped_path(name_or_file, "viewer-scripts", "viewer script");
}

}  // namespace oflab
