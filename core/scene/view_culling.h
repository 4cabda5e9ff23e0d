// Backface and view-frustum culling of scene polygons, and the clipping of polygons that
// cross the near plane or the image border (dissertation section 5.6.2: "backface and
// viewing frustum culling"). Everything here is in the viewer frame of core/flow/camera.h
// (eye at the origin, X right, Y down, Z forward; pixels top-left).
#pragma once

#include <array>
#include <vector>

#include "flow/camera.h"
#include "flow/geometry.h"
#include "flow/plane.h"
#include "image/polygon.h"

namespace oflab {

// A convex polygon in the viewer frame with the normalised texture coordinates of its
// vertices (see core/scene/scene.h), so clipping keeps the texture mapping.
struct ViewPolygon {
  std::vector<Vec3> points;
  std::vector<Vec2> uv;
  bool empty() const { return points.size() < 3; }
};

// The view frustum as five half-spaces dot(plane.xyz, p) + plane.w >= 0: the near plane
// Z >= near and the four planes through the eye and the image border, moved out by
// margin_px pixels so that border pixels are never lost to rounding. No far plane.
struct ViewFrustum {
  std::array<glm::dvec4, 5> planes;
};
// Preconditions: valid camera, near > 0, margin_px >= 0.
ViewFrustum view_frustum(const Camera& camera, double near, double margin_px);

// True when the polygon's plane (unit front normal `front`, any point `point`, viewer
// frame) is seen from behind or within `edge_on_cosine` of edge-on: the cosine between the
// front normal and the direction from the plane to the eye is below edge_on_cosine.
bool is_back_facing(const Vec3& front, const Vec3& point, double edge_on_cosine = 1e-3);

// Sutherland-Hodgman against each half-space; the texture coordinates are interpolated
// along the cut edges (exact: the texture mapping is affine on the plane). Empty when no
// part of the polygon is inside.
ViewPolygon clip_to_half_space(const ViewPolygon& polygon, const glm::dvec4& plane);
ViewPolygon clip_to_frustum(const ViewPolygon& polygon, const ViewFrustum& frustum);
// The same in place, without allocating when the polygon lies wholly inside or outside.
void clip_to_frustum_in_place(ViewPolygon& polygon, const ViewFrustum& frustum);

// The texel polygon of normalised texture coordinates `uv` on a texture of `size` texels.
ConvexPolygon texel_polygon(const std::vector<Vec2>& uv, glm::ivec2 size);

// The projection of a polygon lying at Z > 0 in top-left pixel coordinates.
// Precondition: every point has Z > 0 (true after clip_to_frustum).
ConvexPolygon project_to_pixels(const Camera& camera, const ViewPolygon& polygon);

// The part of a textured plane's rectangle (plane_corners of core/flow/plane.h) that is
// seen inside the image: the rectangle clipped to Z >= near and to the image border, then
// projected to top-left pixels. Empty when no part of the plane in front of the near plane
// projects into the image with positive area: wholly beside or behind the camera, edge-on,
// or a pose whose corners are not finite. Preconditions: valid camera, near > 0 (world
// units along the optical axis).
ConvexPolygon plane_image_polygon(const Camera& camera, const PlanePose& pose, double near);

// True when plane_image_polygon is not empty: the plane is visible in the image.
bool plane_meets_image(const Camera& camera, const PlanePose& pose, double near);

}  // namespace oflab
