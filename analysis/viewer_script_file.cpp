#include "analysis/viewer_script_file.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "analysis/datasets.h"

namespace oflab {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

constexpr int kMaxFrames = 1000000;

struct Where {
  std::string origin;
  std::string part;

  [[noreturn]] void fail(const std::string& field, const std::string& message) const {
    std::string text = origin + ": ";
    if (!part.empty()) text += part + ": ";
    if (!field.empty()) text += "field '" + field + "': ";
    throw ViewerScriptError(text + message);
  }
};

const json& member(const json& obj, const Where& w, const std::string& field) {
  if (!obj.contains(field)) w.fail(field, "is missing");
  return obj.at(field);
}

double number(const json& j, const Where& w, const std::string& field) {
  if (!j.is_number()) w.fail(field, "must be a number");
  const double v = j.get<double>();
  if (!std::isfinite(v) || std::abs(v) > 1e6) w.fail(field, "must be a finite number up to 1e6");
  return v;
}

Vec3 vec3(const json& obj, const Where& w, const std::string& field) {
  const json& j = member(obj, w, field);
  if (!j.is_array() || j.size() != 3) w.fail(field, "must be a list of 3 numbers");
  return Vec3(number(j[0], w, field), number(j[1], w, field), number(j[2], w, field));
}

Camera read_camera(const json& root, const Where& w) {
  const json& c = member(root, w, "camera");
  if (!c.is_object()) w.fail("camera", "must be an object");
  const double f = number(member(c, w, "focal_px"), w, "camera.focal_px");
  const json& image = member(c, w, "image");
  if (!image.is_array() || image.size() != 2) w.fail("camera.image", "must be [width, height]");
  const double width = number(image[0], w, "camera.image"),
               height = number(image[1], w, "camera.image");
  if (!(f > 0.0)) w.fail("camera.focal_px", "must be positive");
  if (width < 1 || height < 1 || width > 8192 || height > 8192 || width != std::floor(width) ||
      height != std::floor(height)) {
    w.fail("camera.image", "must be two whole numbers from 1 to 8192");
  }
  return make_camera(f, static_cast<int>(width), static_cast<int>(height));
}

}  // namespace

ViewerScript parse_viewer_script(const std::string& text, const std::string& origin) {
  const Where top{origin, ""};
  json root;
  try {
    root = json::parse(text);
  } catch (const json::parse_error& e) {
    top.fail("", std::string("not valid JSON (") + e.what() + ")");
  }
  if (!root.is_object()) top.fail("", "must be a JSON object");
  if (root.contains("format") && root.at("format") != "oflab-viewer-script") {
    top.fail("format", "must be \"oflab-viewer-script\"");
  }
  ViewerScript script;
  for (const char* field : {"name", "description"}) {
    if (root.contains(field) && !root.at(field).is_string()) top.fail(field, "must be a string");
  }
  script.name = root.value("name", fs::path(origin).stem().string());
  script.description = root.value("description", std::string());
  script.camera = read_camera(root, top);
  const json& viewer = member(root, top, "viewer");
  if (!viewer.is_object()) top.fail("viewer", "must be an object");
  const Where vw{origin, "viewer"};
  const Vec3 position = vec3(viewer, vw, "position");
  const Vec3 target = vec3(viewer, vw, "look_at");
  const Vec3 up = vec3(viewer, vw, "up");
  const std::string problem = look_at_problem(position, target, up);
  if (!problem.empty()) vw.fail("look_at", problem);
  const json& segs = member(root, top, "segments");
  if (!segs.is_array() || segs.empty()) top.fail("segments", "must be a non-empty list");
  std::vector<ViewerSegment> segments;
  long total = 0;
  for (std::size_t i = 0; i < segs.size(); ++i) {
    const Where w{origin, "segment " + std::to_string(i)};
    if (!segs[i].is_object()) w.fail("", "must be an object");
    ViewerSegment s;
    const double frames = number(member(segs[i], w, "frames"), w, "frames");
    if (frames != std::floor(frames) || frames < 1 || frames > kMaxFrames) {
      w.fail("frames", "must be a whole number from 1 to 1000000");
    }
    s.frames = static_cast<int>(frames);
    s.camera_velocity = vec3(segs[i], w, "velocity");
    s.camera_omega = vec3(segs[i], w, "omega");
    total += s.frames;
    if (total > kMaxFrames) w.fail("frames", "the script has more than 1000000 frames");
    segments.push_back(s);
  }
  script.frames = expand_viewer_segments(look_at(position, target, up), segments);
  return script;
}

ViewerScript read_viewer_script_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ViewerScriptError(path + ": cannot open the file");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_viewer_script(text.str(), path);
}

std::vector<std::string> shipped_viewer_script_names() { return shipped_names("viewer-scripts"); }

std::string resolve_viewer_script_path(const std::string& name_or_file) {
  return resolve_shipped_path(name_or_file, "viewer-scripts", "viewer script");
}

}  // namespace oflab
