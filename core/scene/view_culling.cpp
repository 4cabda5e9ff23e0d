// Backface and frustum culling, and frustum clipping with texture coordinates.
#include "scene/view_culling.h"

#include <cmath>

namespace oflab {

ViewFrustum view_frustum(const Camera& camera, double near, double margin_px) {
  // u = cx + f X / Z >= -m  <=>  f X + (cx + m) Z >= 0 for Z > 0; the other sides alike.
  const double f = camera.focal_px, m = margin_px;
  ViewFrustum frustum;
  frustum.planes = {glm::dvec4(0.0, 0.0, 1.0, -near), glm::dvec4(f, 0.0, camera.cx + m, 0.0),
                    glm::dvec4(-f, 0.0, camera.width + m - camera.cx, 0.0),
                    glm::dvec4(0.0, f, camera.cy + m, 0.0),
                    glm::dvec4(0.0, -f, camera.height + m - camera.cy, 0.0)};
  return frustum;
}

bool is_back_facing(const Vec3& front, const Vec3& point, double edge_on_cosine) {
  // The eye is at the origin, so the direction from the plane to the eye is -point.
  const double length = glm::length(point);
  if (length <= 0.0) return true;  // the eye lies in the plane
  return glm::dot(front, -point) < edge_on_cosine * length * glm::length(front);
}

ViewPolygon clip_to_half_space(const ViewPolygon& polygon, const glm::dvec4& plane) {
  ViewPolygon out;
  const std::size_t n = polygon.points.size();
  if (n < 3) return out;
  const Vec3 normal(plane);
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t j = (k + 1) % n;
    const double dk = glm::dot(normal, polygon.points[k]) + plane.w;
    const double dj = glm::dot(normal, polygon.points[j]) + plane.w;
    if (dk >= 0.0) {
      out.points.push_back(polygon.points[k]);
      out.uv.push_back(polygon.uv[k]);
    }
    if ((dk > 0.0 && dj < 0.0) || (dk < 0.0 && dj > 0.0)) {
      const double t = dk / (dk - dj);
      out.points.push_back(polygon.points[k] + t * (polygon.points[j] - polygon.points[k]));
      out.uv.push_back(polygon.uv[k] + t * (polygon.uv[j] - polygon.uv[k]));
    }
  }
  if (out.points.size() < 3) return ViewPolygon{};
  return out;
}

void clip_to_frustum_in_place(ViewPolygon& polygon, const ViewFrustum& frustum) {
  // Most polygons lie wholly inside or wholly outside: decide those without clipping.
  bool inside_all = true;
  for (const glm::dvec4& plane : frustum.planes) {
    const Vec3 normal(plane);
    int inside = 0;
    for (const Vec3& p : polygon.points) inside += glm::dot(normal, p) + plane.w >= 0.0;
    if (inside == 0) {
      polygon.points.clear();
      polygon.uv.clear();
      return;
    }
    inside_all = inside_all && inside == static_cast<int>(polygon.points.size());
  }
  if (inside_all) return;
  for (const glm::dvec4& plane : frustum.planes) {
    polygon = clip_to_half_space(polygon, plane);
    if (polygon.empty()) return;
  }
}

ViewPolygon clip_to_frustum(const ViewPolygon& polygon, const ViewFrustum& frustum) {
  ViewPolygon clipped = polygon;
  clip_to_frustum_in_place(clipped, frustum);
  if (clipped.empty()) return ViewPolygon{};
  return clipped;
}

ConvexPolygon texel_polygon(const std::vector<Vec2>& uv, glm::ivec2 size) {
  std::vector<Vec2> texels;
  for (const Vec2& p : uv) texels.emplace_back(p.x * size.x, p.y * size.y);
  return make_polygon_unchecked(std::move(texels));
}

ConvexPolygon project_to_pixels(const Camera& camera, const ViewPolygon& polygon) {
  std::vector<Vec2> pixels;
  pixels.reserve(polygon.points.size());
  for (const Vec3& p : polygon.points) {
    pixels.push_back(centred_to_pixel(camera, project_centred(camera, p)));
  }
  return make_polygon_unchecked(std::move(pixels));
}

ConvexPolygon plane_image_polygon(const Camera& camera, const PlanePose& pose, double near) {
  ViewPolygon rectangle;
  for (const Vec3& corner : plane_corners(pose)) {
    if (!std::isfinite(corner.x) || !std::isfinite(corner.y) || !std::isfinite(corner.z)) {
      return ConvexPolygon{};
    }
    rectangle.points.push_back(corner);
    rectangle.uv.push_back(Vec2(0.0));  // texture coordinates are not needed here
  }
  clip_to_frustum_in_place(rectangle, view_frustum(camera, near, 0.0));
  if (rectangle.empty()) return ConvexPolygon{};
  return project_to_pixels(camera, rectangle);
}

bool plane_meets_image(const Camera& camera, const PlanePose& pose, double near) {
  return !plane_image_polygon(camera, pose, near).empty();
}

}  // namespace oflab
