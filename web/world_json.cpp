#include "world_json.h"

#include <algorithm>
#include <limits>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "display/palette.h"

namespace oflab {
namespace {

using json = nlohmann::json;

json vec_json(const Vec3& p) { return json::array({p.x, p.y, p.z}); }

template <typename Points>
json points_json(const Points& points) {
  json out = json::array();
  for (const Vec3& p : points) out.push_back(vec_json(p));
  return out;
}

json rgb_json(const Rgb8& c) { return json::array({int(c.r), int(c.g), int(c.b)}); }

json arrow_json(const WorldArrow& a) {
  return {{"origin", vec_json(a.origin)},
          {"direction", vec_json(a.direction)},
          {"length", a.length},
          {"matrix", arrow_matrix(a)}};
}

Vec3 tip(const WorldArrow& a) {
  return a.length > 0.0 ? a.origin + glm::normalize(a.direction) * a.length : a.origin;
}

json label_json(const std::string& key, const std::string& text, const Vec3& at) {
  return {{"key", key}, {"text", text}, {"at", vec_json(at)}};
}

json camera_json(const Camera& c) {
  return {{"width", c.width},
          {"height", c.height},
          {"focal_px", c.focal_px},
          {"cx", c.cx},
          {"cy", c.cy}};
}

json colours_json() {
  namespace oi = okabe_ito;
  return {{"velocity", rgb_json(oi::kVermillion)}, {"omega", rgb_json(oi::kReddishPurple)},
          {"normal", rgb_json(oi::kBlue)},         {"up", rgb_json(oi::kBluishGreen)},
          {"rays", rgb_json(oi::kYellow)},         {"path_past", rgb_json(oi::kOrange)},
          {"plane", rgb_json(Rgb8{225, 225, 225})}};
}

}  // namespace

PlaneWorldLoop panel_world_loop(const PlanePanel& panel) {
  return plane_world_loop(panel.as_script(), panel.scene().camera, panel.current_pose(),
                          PlanePanel::kSecondsPerFrame);
}

std::string world_loop_json(const PlaneWorldLoop& loop, const std::string& texture_source) {
  const Camera& c = loop.camera;
  const std::array<Vec3, 4> image = image_plane_corners(c, loop.depth);
  Vec3 lo(0.0), hi(0.0);  // the eye
  for (const auto* points : {&loop.loop_corners, &loop.path}) {
    for (const Vec3& p : *points) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  }
  for (const Vec3& p : image) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  json out;
  out["kind"] = "plane";
  out["camera"] = camera_json(c);
  out["depth"] = loop.depth;
  out["full_arrow"] = loop.full_arrow;
  out["largest_velocity"] = loop.largest_velocity;
  out["largest_omega"] = loop.largest_omega;
  out["image_corners"] = points_json(image);
  out["path"] = points_json(loop.path);
  out["world_centre"] = vec_json(loop.world_centre);
  out["bounds"] = {lo.x, hi.x, lo.y, hi.y, lo.z, hi.z};
  out["caption"] = plane_world_caption(loop);
  out["texture"] = texture_source;
  out["colours"] = colours_json();
  return out.dump();
}

std::string world_frame_json(const PlaneWorldLoop& loop, const PlanePanel& panel) {
  const PlaneWorldFrame f =
      plane_world_frame(loop, panel.current_pose(), panel.current_motion(), panel.frame());
  json out;
  out["frame"] = panel.frame();
  out["plane_corners"] = points_json(f.plane_corners);
  out["ray_images"] = points_json(f.ray_images);
  out["omega_axis"] = points_json(f.motion.omega_axis);
  out["velocity"] = vec_json(f.velocity);
  out["omega"] = vec_json(f.omega);
  out["path_index"] = f.path_index;
  out["arrows"] = {{"velocity", arrow_json(f.motion.velocity)},
                   {"omega", arrow_json(f.motion.omega)},
                   {"normal", arrow_json(f.normal)},
                   {"up", arrow_json(f.up)}};
  out["labels"] = {label_json("eye", "eye", Vec3(0.0)),
                   label_json("image_plane", "image plane", f.image_corners[0]),
                   label_json("velocity", velocity_label(f.motion), tip(f.motion.velocity)),
                   label_json("omega", omega_label(f.motion), tip(f.motion.omega)),
                   label_json("normal", "N", tip(f.normal)),
                   label_json("up", "U", tip(f.up))};
  return out.dump();
}

std::string scene_world_loop_json(const SceneWorldLoop& loop) {
  Vec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  auto grow = [&](const Vec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  };
  json outlines = json::array();
  for (const std::vector<Vec3>& outline : loop.outlines) {
    outlines.push_back(points_json(outline));
    for (const Vec3& p : outline) grow(p);
  }
  for (const Vec3& p : loop.path) grow(p);
  grow(viewer_to_world(loop.first_view, Vec3(0.0)));
  json out;
  out["kind"] = "scene";
  out["camera"] = camera_json(loop.camera);
  out["depth"] = loop.depth;
  out["full_arrow"] = loop.full_arrow;
  out["largest_velocity"] = loop.largest_velocity;
  out["largest_omega"] = loop.largest_omega;
  out["image_corners"] = points_json(image_plane_corners(loop.camera, loop.depth));
  out["path"] = points_json(loop.path);
  out["world_centre"] = vec_json(loop.world_centre);
  out["first_view"] = viewer_to_world_matrix(loop.first_view);
  out["bounds"] = {lo.x, hi.x, lo.y, hi.y, lo.z, hi.z};
  out["outlines"] = outlines;
  out["caption"] = scene_world_caption(false);  // the image plane is drawn grey
  out["colours"] = colours_json();
  return out.dump();
}

std::string scene_world_frame_json(const SceneWorldLoop& loop, const Animator& animator,
                                   double seconds_per_frame) {
  const SceneWorldFrame f = scene_world_frame(loop, animator, seconds_per_frame);
  json colours = json::array();
  for (const Rgb8& c : f.colours) colours.push_back(rgb_json(c));
  const WorldArrow none;  // the plane's N and U: not drawn in a scene
  json out;
  out["frame"] = animator.frame();
  out["viewer_matrix"] = f.viewer_matrix;
  out["eye"] = vec_json(f.eye);
  out["polygon_colours"] = colours;
  out["omega_axis"] = points_json(f.motion.omega_axis);
  out["path_index"] = f.path_index;
  out["arrows"] = {{"velocity", arrow_json(f.motion.velocity)},
                   {"omega", arrow_json(f.motion.omega)},
                   {"normal", arrow_json(none)},
                   {"up", arrow_json(none)}};
  out["labels"] = {label_json("eye", "eye", f.eye),
                   label_json("image_plane", "image plane", f.image_corners[0]),
                   label_json("velocity", velocity_label(f.motion), tip(f.motion.velocity)),
                   label_json("omega", omega_label(f.motion), tip(f.motion.omega))};
  return out.dump();
}

namespace {

Vec2 pair_of(const json& j, const char* field) {
  if (!j.is_array() || j.size() != 2 || !j[0].is_number() || !j[1].is_number())
    throw std::invalid_argument(std::string("placeLabels: ") + field + " must hold [x, y] pairs");
  return Vec2(j[0].get<double>(), j[1].get<double>());
}

LabelBox box_of(const json& j, const char* field) {
  if (!j.is_array() || j.size() != 4 ||
      !std::all_of(j.begin(), j.end(), [](const json& v) { return v.is_number(); }))
    throw std::invalid_argument(std::string("placeLabels: ") + field + " must be [x, y, w, h]");
  return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>(), j[3].get<double>()};
}

const json& array_field(const json& j, const char* field) {
  if (!j.contains(field) || !j[field].is_array())
    throw std::invalid_argument(std::string("placeLabels: ") + field + " must be an array");
  return j[field];
}

}  // namespace

std::string placed_labels_json(const std::string& request) {
  const json j = json::parse(request, nullptr, false);
  if (!j.is_object()) throw std::invalid_argument("placeLabels: the request is not a JSON object");
  std::vector<Vec2> sizes, anchors;
  for (const json& s : array_field(j, "sizes")) sizes.push_back(pair_of(s, "sizes"));
  for (const json& a : array_field(j, "anchors")) anchors.push_back(pair_of(a, "anchors"));
  if (sizes.size() != anchors.size())
    throw std::invalid_argument("placeLabels: sizes and anchors differ in length");
  if (!j.contains("area")) throw std::invalid_argument("placeLabels: area is missing");
  std::vector<LabelBox> taken;
  if (j.contains("taken"))
    for (const json& t : array_field(j, "taken")) taken.push_back(box_of(t, "taken"));
  std::vector<std::vector<Vec2>> avoid;
  if (j.contains("avoid")) {
    for (const json& outline : array_field(j, "avoid")) {
      if (!outline.is_array()) throw std::invalid_argument("placeLabels: avoid must hold outlines");
      avoid.emplace_back();
      for (const json& p : outline) avoid.back().push_back(pair_of(p, "avoid"));
    }
  }
  const double gap = j.contains("gap") && j["gap"].is_number() ? j["gap"].get<double>() : 6.0;
  json out = json::array();
  for (const LabelBox& b :
       place_labels(sizes, anchors, box_of(j["area"], "area"), std::move(taken), gap, avoid))
    out.push_back({b.x, b.y, b.width, b.height});
  return out.dump();
}

}  // namespace oflab
