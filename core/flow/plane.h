// Pose of a textured plane in the viewer frame (dissertation sections 4.6 and 5.4.4).
//
// The plane passes through `point` P with normal N; its texture's up direction is U and its
// right direction is R = N x U (reference convention; with Y down the texture appears
// unmirrored when N points away from the viewer). The plane equation is N.X = d with
// d = N.P, written n.X = 1 with the plane vector n = N / d (never divides by N3, so planes
// seen edge-on through the optical axis, N3 = 0, work too).
//
// Texture coordinates: texel (u, v) has its origin at the top-left texel corner, u right,
// v down, in texels; texel centres are at half-integers. Texture point (u, v) sits at
//   P + s R + r U,  s = (u - tw/2) * sw / tw,  r = (th/2 - v) * sh / th
// (sw, sh = plane size in world units, tw, th = texture size in texels).
#pragma once

#include <array>
#include <string>

#include "flow/geometry.h"

namespace oflab {

struct PlanePose {
  Vec3 point{0.0, 0.0, 1.0};          // P, world units, viewer frame (centre of the texture)
  Vec3 normal{0.0, 0.0, 1.0};         // N, any non-zero length
  Vec3 up{0.0, -1.0, 0.0};            // U, texture up; need not be unit or exactly in the plane
  Vec2 size{1.0, 1.0};                // plane extent along R and U, world units
  glm::ivec2 texture_size{256, 256};  // texels (width, height)
};

// What is wrong with a pose, naming the field ("point", "normal", "up", "size",
// "texture_size"); field is empty when the pose is usable. Checks: finite values, non-zero
// normal, plane not through the eye (|N.P| > 1e-12 |N||P|), centre in front of the camera
// (P.z > 0), up not parallel to the normal, positive size.
struct PoseProblem {
  std::string field;
  std::string message;
};
PoseProblem plane_pose_problem(const PlanePose& pose);

// The plane vector n = N / (N.P): plane points X satisfy n.X = 1 and 1/Z = n.(x/f, y/f, 1)
// at centred pixel (x, y). Precondition: N.P != 0.
Vec3 plane_vector(const PlanePose& pose);

// Orthonormal in-plane axes: unit right R = N x U and unit up U' (U made orthogonal to N).
struct PlaneAxes {
  Vec3 right;
  Vec3 up;
  Vec3 normal;  // unit N
};
PlaneAxes plane_axes(const PlanePose& pose);

// The four corners of the plane rectangle in the viewer frame, in texture order
// top-left, top-right, bottom-right, bottom-left (texel corners (0,0), (tw,0), (tw,th), (0,th)).
std::array<Vec3, 4> plane_corners(const PlanePose& pose);

// Maps texel coordinates (homogeneous (u, v, 1)) to plane coordinates (s, r, 1) in world units.
Mat3 texel_to_plane(const PlanePose& pose);

// The plane point seen along the ray through centred pixel (x, y). Precondition: the ray
// meets the plane in front of the eye (n.(x/f, y/f, 1) > 0).
Vec3 plane_point_at_pixel(const PlanePose& pose, double focal_px, const Vec2& centred);

}  // namespace oflab
