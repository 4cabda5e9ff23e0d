// The geometry of the world view (gui/views/world_view.h), plain C++ over core: where the
// image plane, the frustum, the rays and the arrows go in 3D. No Qt, no VTK.
//
// Frames. The plane's world is the viewer frame of core/flow/camera.h: the eye at the origin,
// looking along +Z, X to the right and Y down the image, world units. A scene's world is the
// scene file's; a viewer pose (core/scene/viewer_script.h) maps it to the viewer frame by
// X_viewer = Q X_world + s.
//
// The image plane. The camera's image is drawn as a rectangle at depth `depth` (world
// units) in front of the eye: image pixel (px, py) (top-left pixels) lies at
// ((px - cx) d / f, (py - cy) d / f, d). It is the picture plane at the focal distance f,
// scaled by d / f world units per pixel so that it fits the scene, so a scene point and its
// image lie on one ray from the eye.
#pragma once

#include <array>
#include <vector>

#include "flow/camera.h"
#include "flow/geometry.h"
#include "scene/viewer_script.h"

namespace oflab {

// The image's corners on the image plane at `depth` (> 0), viewer frame, in the order of
// the pixel corners (0, 0), (W, 0), (W, H), (0, H): top-left, top-right, bottom-right,
// bottom-left.
std::array<Vec3, 4> image_plane_corners(const Camera& camera, double depth);

// Where the ray from the eye through `point` (viewer frame, point.z > 0) meets the image
// plane at `depth`: point * depth / point.z.
Vec3 ray_at_depth(const Vec3& point, double depth);

// The image plane's depth for a plane whose centre moves along `centres` (viewer frame, at
// least one): half the smallest depth, so the picture plane sits between the eye and the
// plane in every frame, but never less than a quarter of the median depth, so that a plane
// flying into the eye does not shrink the image plane to a point (the plane then passes
// through it for the frames it is that near). 1 for an empty list or a median depth <= 0.
double plane_image_depth(const std::vector<Vec3>& centres);

// The image plane's depth for a scene whose points are `points` (world units): a tenth of
// the diagonal of their bounding box (1 when it is empty or degenerate), so the frustum
// reads at the scale of the scene without hiding it.
double scene_image_depth(const std::vector<Vec3>& points);

// Length of a vector arrow drawn for `magnitude` when the largest magnitude it takes is
// `largest`, so that both arrows of the view read at any speed: 0 for a zero magnitude,
// otherwise between 0.35 and 1 times `full_length` in proportion to magnitude / largest.
// Preconditions: magnitude >= 0, full_length > 0.
double arrow_length(double magnitude, double largest, double full_length);

// The 4x4 matrix (row-major, as vtkMatrix4x4::DeepCopy reads it) that maps VTK's unit arrow
// (vtkArrowSource: from (0,0,0) to (1,0,0)) onto the arrow from `origin` along `direction`
// (any non-zero length) of length `length`, scaled uniformly (its thickness grows with it).
// A zero direction or length gives the zero-scale matrix at `origin` (nothing is drawn).
std::array<double, 16> arrow_matrix(const Vec3& origin, const Vec3& direction, double length);

// The 4x4 matrix (row-major) that maps viewer coordinates to world coordinates for the viewer
// at `pose`: X_world = Q^T (X_viewer - s). The identity for the identity pose.
std::array<double, 16> viewer_to_world_matrix(const ViewerPose& pose);

// The point `viewer_point` (viewer frame of `pose`) in world coordinates: Q^T (p - s).
Vec3 viewer_to_world(const ViewerPose& pose, const Vec3& viewer_point);

}  // namespace oflab
