#include "display/world_geometry.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "scene/scene_animator.h"
#include "scene_shifting/scene_shifting_renderer.h"

namespace oflab {

std::array<Vec3, 4> image_plane_corners(const Camera& camera, double depth) {
  const double k = depth / camera.focal_px;  // world units per pixel on the image plane
  const double left = -camera.cx * k, right = (camera.width - camera.cx) * k;
  const double top = -camera.cy * k, bottom = (camera.height - camera.cy) * k;
  return {Vec3(left, top, depth), Vec3(right, top, depth), Vec3(right, bottom, depth),
          Vec3(left, bottom, depth)};
}

Vec3 ray_at_depth(const Vec3& point, double depth) { return point * (depth / point.z); }

double plane_image_depth(const std::vector<Vec3>& centres) {
  if (centres.empty()) return 1.0;
  std::vector<double> depths;
  for (const Vec3& c : centres) depths.push_back(c.z);
  std::sort(depths.begin(), depths.end());
  const double median = depths[depths.size() / 2];
  if (!(median > 0.0)) return 1.0;
  return std::max(0.5 * depths.front(), 0.25 * median);
}

double scene_image_depth(const std::vector<Vec3>& points) {
  if (points.empty()) return 1.0;
  Vec3 lo = points.front(), hi = points.front();
  for (const Vec3& p : points) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const double diagonal = glm::length(hi - lo);
  return diagonal > 0.0 ? 0.1 * diagonal : 1.0;
}

double arrow_length(double magnitude, double largest, double full_length) {
  if (!(magnitude > 0.0)) return 0.0;
  const double ratio = largest > 0.0 ? std::min(1.0, magnitude / largest) : 1.0;
  return full_length * (0.35 + 0.65 * ratio);
}

std::array<double, 16> arrow_matrix(const Vec3& origin, const Vec3& direction, double length) {
  const double norm = glm::length(direction);
  Vec3 x(0.0), y(0.0), z(0.0);
  if (norm > 0.0 && length > 0.0) {
    const Vec3 d = direction / norm;
    // Any unit vector not parallel to d completes the frame; the arrow is round.
    const Vec3 helper = std::abs(d.x) < 0.9 ? Vec3(1.0, 0.0, 0.0) : Vec3(0.0, 1.0, 0.0);
    const Vec3 e1 = glm::normalize(glm::cross(d, helper));
    x = d * length;
    y = e1 * length;
    z = glm::cross(d, e1) * length;
  }
  return {x.x, y.x, z.x, origin.x,  //
          x.y, y.y, z.y, origin.y,  //
          x.z, y.z, z.z, origin.z,  //
          0.0, 0.0, 0.0, 1.0};
}

std::array<double, 16> viewer_to_world_matrix(const ViewerPose& pose) {
  const Mat3 qt = glm::transpose(pose.rotation);
  const Vec3 t = -(qt * pose.translation);
  std::array<double, 16> m{};
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) m[size_t(4 * r + c)] = entry(qt, r, c);
    m[size_t(4 * r + 3)] = t[r];
  }
  m[15] = 1.0;
  return m;
}

Vec3 viewer_to_world(const ViewerPose& pose, const Vec3& viewer_point) {
  return glm::transpose(pose.rotation) * (viewer_point - pose.translation);
}

std::array<double, 16> arrow_matrix(const WorldArrow& arrow) {
  return arrow_matrix(arrow.origin, arrow.direction, arrow.length);
}

MotionArrows motion_arrows(const Vec3& at, const Vec3& omega_at, const Vec3& eye,
                           const Vec3& velocity, const Vec3& omega, double largest_velocity,
                           double largest_omega, double full_length) {
  const double v = glm::length(velocity), w = glm::length(omega);
  MotionArrows out;
  out.velocity = {at, velocity,
                  v >= kLeastShownRate ? arrow_length(v, largest_velocity, full_length) : 0.0};
  out.omega = {omega_at, omega,
               w >= kLeastShownRate ? arrow_length(w, largest_omega, full_length) : 0.0};
  if (out.omega.length > 0.0) {
    const double reach = std::max(1.1 * glm::length(at - eye), out.omega.length);
    out.omega_axis = {eye, eye + reach * (omega / w)};
  }
  return out;
}

PlaneWorldLoop plane_world_loop(const MotionScript& script, const Camera& camera,
                                const PlanePose& fallback, double seconds_per_frame) {
  PlaneWorldLoop loop;
  loop.camera = camera;
  const double dt = seconds_per_frame;
  for (const ScriptFrame& f : script.frames) {
    loop.path.push_back(f.pose.point);
    for (const Vec3& c : plane_corners(f.pose)) loop.loop_corners.push_back(c);
    loop.largest_velocity =
        std::max(loop.largest_velocity, glm::length(eye_velocity(f.motion, f.pose)) / dt);
    loop.largest_omega = std::max(loop.largest_omega, glm::length(f.motion.omega) / dt);
  }
  loop.first_pose = script.frames.empty() ? fallback : script.frames.front().pose;
  loop.depth = plane_image_depth(loop.path);
  loop.full_arrow = 0.6 * std::hypot(loop.first_pose.size.x, loop.first_pose.size.y);
  for (const Vec3& p : loop.path) loop.world_centre += p / double(loop.path.size());
  return loop;
}

PlaneWorldFrame plane_world_frame(const PlaneWorldLoop& loop, const PlanePose& pose,
                                  const RigidMotion& motion, int frame) {
  PlaneWorldFrame out;
  out.image_corners = image_plane_corners(loop.camera, loop.depth);
  out.plane_corners = plane_corners(pose);
  for (const Vec3& c : out.plane_corners) {
    if (c.z > 0.0) out.ray_images.push_back(ray_at_depth(c, loop.depth));
  }
  const PlaneAxes axes = plane_axes(pose);
  const double side = 0.3 * std::hypot(pose.size.x, pose.size.y);
  out.normal = {pose.point, axes.normal, side};
  out.up = {pose.point, axes.up, side};
  out.velocity = eye_velocity(motion, pose);
  out.omega = motion.omega;
  // Omega turns about the eye (the theory's convention): its arrow starts there.
  out.motion = motion_arrows(pose.point, Vec3(0.0), Vec3(0.0), out.velocity, out.omega,
                             loop.largest_velocity, loop.largest_omega, loop.full_arrow);
  out.path_index = loop.path.empty() ? 0 : std::clamp(frame, 0, int(loop.path.size()) - 1);
  return out;
}

std::string plane_world_caption(const PlaneWorldLoop& loop) {
  char text[400];
  std::snprintf(text, sizeof text,
                "The eye looks along +Z; the image plane is drawn at "
                "depth %.2f (f = %.0f px scaled to the scene).\n"
                "Omega turns about the eye, the viewer's origin (the theory's convention); "
                "V is the velocity of the body point at the eye.\n"
                "Path of the plane's centre: past thick, future thin. Rays: eye to the plane's "
                "corners through their images.",
                loop.depth, loop.camera.focal_px);
  return text;
}

std::string velocity_label(const MotionArrows& arrows) {
  if (!(arrows.velocity.length > 0.0)) return "";
  char text[96];
  std::snprintf(text, sizeof text, "V %.2f units/s", glm::length(arrows.velocity.direction));
  return text;
}

std::string omega_label(const MotionArrows& arrows) {
  if (!(arrows.omega.length > 0.0)) return "";
  char text[96];
  std::snprintf(text, sizeof text, "Omega %.2f rad/s about the eye",
                glm::length(arrows.omega.direction));
  return text;
}

namespace {

// The viewer script a scene source plays, or nullptr for other animators.
const ViewerScript* viewer_script_of(const Animator& animator) {
  if (const auto* scene = dynamic_cast<const SceneScriptAnimator*>(&animator)) {
    return &scene->script();
  }
  if (const auto* shifting = dynamic_cast<const SceneShiftingAnimator*>(&animator)) {
    return &shifting->script();
  }
  return nullptr;
}

}  // namespace

Rgb8 scene_polygon_colour(PolygonStatus status, Level level) {
  switch (status) {
    case PolygonStatus::kAnimated:
      return level_colour(level);
    case PolygonStatus::kClipped:
      return level_colour(Level::kRerender);
    case PolygonStatus::kBackFacing:
    case PolygonStatus::kOutsideFrustum:
      return {215, 215, 215};
    case PolygonStatus::kHidden:
      return {70, 70, 70};
    case PolygonStatus::kStarved:
      return {0, 0, 0};
  }
  return kUnreportedPolygon;
}

SceneWorldLoop scene_world_loop(const Animator& animator, double seconds_per_frame) {
  SceneWorldLoop loop;
  loop.camera = animator.camera();
  std::vector<Vec3> points;
  for (const ScenePolygon& polygon : animator.scene().polygons) {
    loop.outlines.push_back(polygon_vertices(polygon));
    points.insert(points.end(), loop.outlines.back().begin(), loop.outlines.back().end());
  }
  loop.first_view = animator.view();
  if (const ViewerScript* script = viewer_script_of(animator)) {
    for (const ViewerFrame& f : script->frames) {
      loop.path.push_back(viewer_to_world(f.pose, Vec3(0.0)));
      loop.largest_velocity =
          std::max(loop.largest_velocity, glm::length(f.motion.velocity) / seconds_per_frame);
      loop.largest_omega =
          std::max(loop.largest_omega, glm::length(f.motion.omega) / seconds_per_frame);
    }
    if (!script->frames.empty()) loop.first_view = script->frames.front().pose;
  }
  loop.depth = scene_image_depth(points);
  loop.full_arrow = 2.0 * loop.depth;
  for (const Vec3& p : points) loop.world_centre += p / double(points.size());
  return loop;
}

SceneWorldFrame scene_world_frame(const SceneWorldLoop& loop, const Animator& animator,
                                  double seconds_per_frame) {
  SceneWorldFrame out;
  out.view = animator.view();
  out.viewer_matrix = viewer_to_world_matrix(out.view);
  out.eye = viewer_to_world(out.view, Vec3(0.0));
  const std::array<Vec3, 4> corners = image_plane_corners(loop.camera, loop.depth);
  for (size_t k = 0; k < 4; ++k) out.image_corners[k] = viewer_to_world(out.view, corners[k]);
  out.colours.assign(loop.outlines.size(), kUnreportedPolygon);
  if (const auto* scene = dynamic_cast<const SceneScriptAnimator*>(&animator)) {
    const std::vector<PolygonStatus>& statuses = scene->renderer().statuses();
    const std::vector<Level>& levels = scene->renderer().levels();
    for (size_t k = 0; k < out.colours.size() && k < statuses.size() && k < levels.size(); ++k) {
      out.colours[k] = scene_polygon_colour(statuses[k], levels[k]);
    }
  }
  const int frame = animator.frame();
  const ViewerScript* script = viewer_script_of(animator);
  if (script && frame >= 0 && frame < int(script->frames.size())) {
    const RigidMotion& motion = script->frames[size_t(frame)].motion;
    const Mat3 to_world = glm::transpose(out.view.rotation);
    const Vec3 at = viewer_to_world(out.view, Vec3(0.0, 0.0, 1.5 * loop.depth));
    out.walking = true;
    out.motion = motion_arrows(at, at, out.eye, to_world * motion.velocity / seconds_per_frame,
                               to_world * motion.omega / seconds_per_frame, loop.largest_velocity,
                               loop.largest_omega, loop.full_arrow);
  }
  out.path_index = loop.path.empty() ? 0 : std::clamp(frame, 0, int(loop.path.size()) - 1);
  return out;
}

std::string scene_world_caption(bool frame_on_image_plane) {
  return std::string(frame_on_image_plane
                         ? "The viewer walks through the scene; its image plane shows the "
                           "engine's frame.\n"
                         : "The viewer walks through the scene; the comparison view shows the "
                           "engine's frame.\n") +
         "Polygons in their level's colour (none grey, translate sky blue, affine green, "
         "perspective "
         "orange, re-render vermillion); culled pale, hidden dark.\n"
         "V and Omega: the scene's motion seen by the viewer (Omega about the eye). Viewer's "
         "path: past thick, future thin.";
}

}  // namespace oflab
