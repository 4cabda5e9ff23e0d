// Convex textured polygons of a static scene (see core/scene/scene.h).
#include "scene/scene.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "image/polygon.h"

namespace oflab {
namespace {

bool finite(const Vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Newell's normal of a polygon: twice its vector area, robust for any vertex order.
Vec3 newell_normal(const std::vector<Vec3>& v) {
  Vec3 n(0.0);
  for (std::size_t k = 0; k < v.size(); ++k) {
    const Vec3& a = v[k];
    const Vec3& b = v[next_vertex(k, v.size())];
    n += Vec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
  }
  return n;
}

}  // namespace

std::vector<Vec2> polygon_outline(const ScenePolygon& polygon) {
  if (!polygon.outline.empty()) return polygon.outline;
  return {Vec2(0.0, 0.0), Vec2(1.0, 0.0), Vec2(1.0, 1.0), Vec2(0.0, 1.0)};
}

Vec3 polygon_right(const ScenePolygon& polygon) { return glm::cross(polygon.up, polygon.front); }

Vec3 polygon_point(const ScenePolygon& polygon, const Vec2& uv) {
  return polygon.centre + (uv.x - 0.5) * polygon.size.x * polygon_right(polygon) +
         (0.5 - uv.y) * polygon.size.y * polygon.up;
}

std::vector<Vec3> polygon_vertices(const ScenePolygon& polygon) {
  std::vector<Vec3> out;
  for (const Vec2& uv : polygon_outline(polygon)) out.push_back(polygon_point(polygon, uv));
  return out;
}

PlanePose polygon_pose(const ScenePolygon& polygon, const ViewerPose& view,
                       glm::ivec2 texture_size) {
  PlanePose pose;
  pose.point = to_view(view, polygon.centre);
  pose.normal = -direction_to_view(view, polygon.front);
  pose.up = direction_to_view(view, polygon.up);
  pose.size = polygon.size;
  pose.texture_size = texture_size;
  return pose;
}

Scene plane_as_scene(const PlanePose& pose, const Image& texture) {
  const PlaneAxes axes = plane_axes(pose);
  ScenePolygon polygon;
  polygon.name = "plane";
  polygon.centre = pose.point;
  polygon.front = -axes.normal;  // the pose's normal N is -F (see the header)
  polygon.up = axes.up;
  polygon.size = pose.size;
  polygon.two_sided = true;  // a textured sheet: its back is seen too, as the engine draws it
  Scene scene;
  scene.name = "plane";
  scene.textures.push_back(texture);
  scene.texture_names.push_back("texture");
  scene.polygons.push_back(polygon);
  return scene;
}

ViewerPose viewer_for_pose(const PlanePose& first, const PlanePose& now) {
  const PlaneAxes a = plane_axes(first);
  const PlaneAxes b = plane_axes(now);
  const Mat3 from(a.right, a.up, a.normal);  // columns
  const Mat3 to(b.right, b.up, b.normal);
  ViewerPose view;
  view.rotation = to * glm::transpose(from);
  view.translation = now.point - view.rotation * first.point;
  return view;
}

ScenePolygon polygon_from_vertices(const std::string& name, const std::vector<Vec3>& vertices,
                                   const Vec3& up_hint, int texture) {
  if (vertices.size() < 3) throw std::invalid_argument("needs at least 3 vertices");
  for (const Vec3& v : vertices) {
    if (!finite(v)) throw std::invalid_argument("vertex coordinates must be finite");
  }
  if (!finite(up_hint)) throw std::invalid_argument("up must be finite");
  const Vec3 area_normal = newell_normal(vertices);
  double extent = 0.0;
  for (const Vec3& v : vertices) extent = std::max(extent, glm::length(v - vertices[0]));
  if (glm::length(area_normal) <= 1e-12 * std::max(1.0, extent * extent)) {
    throw std::invalid_argument("the vertices enclose no area");
  }
  ScenePolygon p;
  p.name = name;
  p.texture = texture;
  p.front = glm::normalize(area_normal);
  Vec3 centroid(0.0);
  for (const Vec3& v : vertices) centroid += v;
  centroid /= static_cast<double>(vertices.size());
  for (std::size_t k = 0; k < vertices.size(); ++k) {
    const double off = std::abs(glm::dot(vertices[k] - centroid, p.front));
    if (off > 1e-4 * extent) {
      throw std::invalid_argument("not planar: vertex " + std::to_string(k) + " is " +
                                  std::to_string(off) + " units off the polygon's plane");
    }
  }
  Vec3 up = up_hint;
  if (glm::length(up) < 1e-12) {
    up = std::abs(p.front.y) > 0.99 ? Vec3(0.0, 0.0, -1.0) : Vec3(0.0, 1.0, 0.0);
  }
  up -= glm::dot(up, p.front) * p.front;
  if (glm::length(up) < 1e-9) throw std::invalid_argument("up must not be parallel to the normal");
  p.up = glm::normalize(up);
  const Vec3 right = polygon_right(p);
  // Plane coordinates (along R, along U) of every vertex, then the bounding rectangle.
  std::vector<Vec2> plane;
  for (const Vec3& v : vertices) {
    plane.emplace_back(glm::dot(v - centroid, right), glm::dot(v - centroid, p.up));
  }
  Vec2 lo = plane[0], hi = plane[0];
  for (const Vec2& q : plane) {
    lo = glm::min(lo, q);
    hi = glm::max(hi, q);
  }
  p.size = hi - lo;
  if (!(p.size.x > 0.0 && p.size.y > 0.0))
    throw std::invalid_argument("the vertices enclose no area");
  const Vec2 mid = 0.5 * (lo + hi);
  p.centre = centroid + mid.x * right + mid.y * p.up;
  for (const Vec2& q : plane) {
    p.outline.emplace_back((q.x - lo.x) / p.size.x, (hi.y - q.y) / p.size.y);
  }
  try {
    (void)ConvexPolygon::from_vertices(p.outline);
  } catch (const std::invalid_argument&) {
    throw std::invalid_argument("not convex: the vertices turn both ways");
  }
  return p;
}

PolygonProblem scene_polygon_problem(const Scene& scene, const ScenePolygon& p) {
  if (!finite(p.centre)) return {"centre", "must be three finite numbers"};
  if (!finite(p.front) || std::abs(glm::length(p.front) - 1.0) > 1e-6) {
    return {"normal", "must be a finite unit vector"};
  }
  if (!finite(p.up) || std::abs(glm::length(p.up) - 1.0) > 1e-6 ||
      std::abs(glm::dot(p.up, p.front)) > 1e-6) {
    return {"up", "must be a finite unit vector orthogonal to the normal"};
  }
  if (!(p.size.x > 0.0 && p.size.y > 0.0 && std::isfinite(p.size.x) && std::isfinite(p.size.y))) {
    return {"size", "must be two positive finite numbers"};
  }
  if (p.texture < 0 || p.texture >= static_cast<int>(scene.textures.size())) {
    return {"texture", "names no texture of the scene"};
  }
  if (scene.textures[p.texture].empty()) return {"texture", "the texture image is empty"};
  if (!p.outline.empty()) {
    for (const Vec2& uv : p.outline) {
      if (!(uv.x >= 0.0 && uv.x <= 1.0 && uv.y >= 0.0 && uv.y <= 1.0)) {
        return {"outline", "coordinates must lie in [0, 1]"};
      }
    }
    try {
      if (ConvexPolygon::from_vertices(p.outline).empty()) {
        return {"outline", "encloses no area"};
      }
    } catch (const std::invalid_argument&) {
      return {"outline", "is not convex"};
    }
  }
  return {};
}

bool polygon_is_opaque(const ScenePolygon& polygon, const Image& texture) {
  if (texture.empty()) return false;
  Vec2 lo(1.0), hi(0.0);
  for (const Vec2& uv : polygon_outline(polygon)) {
    lo = glm::min(lo, uv);
    hi = glm::max(hi, uv);
  }
  const int x0 = std::max(0, static_cast<int>(std::floor(lo.x * texture.width())) - 1);
  const int y0 = std::max(0, static_cast<int>(std::floor(lo.y * texture.height())) - 1);
  const int x1 = std::min(texture.width(), static_cast<int>(std::ceil(hi.x * texture.width())) + 1);
  const int y1 =
      std::min(texture.height(), static_cast<int>(std::ceil(hi.y * texture.height())) + 1);
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      if (texture.at(x, y).a != 255) return false;
    }
  }
  return true;
}

}  // namespace oflab
