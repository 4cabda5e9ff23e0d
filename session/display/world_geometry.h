// The geometry of the world view, plain C++ over core: where the image plane, the frustum,
// the rays, the arrows and the path go in 3D. No Qt, no VTK: the desktop's VTK view
// (gui/views/world_view.h) and the page's vtk.js view (web/world_view.js, through
// web/world_json.h) draw the same numbers from here.
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
#include <string>
#include <vector>

#include "display/palette.h"
#include "engine/animator.h"
#include "engine/script.h"
#include "flow/camera.h"
#include "flow/geometry.h"
#include "flow/motion.h"
#include "flow/plane.h"
#include "scene/polygon_layer.h"
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

// An arrow of the world view: from `origin` along `direction` (any length), drawn `length`
// world units long (0: not drawn).
struct WorldArrow {
  Vec3 origin{0.0};
  Vec3 direction{0.0};
  double length = 0.0;
};
// arrow_matrix of the arrow.
std::array<double, 16> arrow_matrix(const WorldArrow& arrow);

// The motion arrows: V at `at`, Omega at `omega_at` (per second, world frame), each
// arrow_length of its magnitude over the loop's largest and `full_length`; a vector shorter
// than kLeastShownRate (which a label prints as 0.00) is not drawn (length 0). Omega's axis:
// from `eye` along Omega, 1.1 times the eye's distance to `at` (at least the arrow's length),
// empty when Omega is not drawn.
constexpr double kLeastShownRate = 0.005;
struct MotionArrows {
  WorldArrow velocity, omega;
  std::vector<Vec3> omega_axis;
};
MotionArrows motion_arrows(const Vec3& at, const Vec3& omega_at, const Vec3& eye,
                           const Vec3& velocity, const Vec3& omega, double largest_velocity,
                           double largest_omega, double full_length);

// What a plane's world shows over its whole loop (the viewer frame: the eye at the origin):
// built once per source. Speeds per second; lengths in world units.
struct PlaneWorldLoop {
  Camera camera;
  std::vector<Vec3> path;          // the plane's centre at every frame
  std::vector<Vec3> loop_corners;  // the plane's four corners at every frame
  double largest_velocity = 0.0;   // of the body point at the eye, eq. 21
  double largest_omega = 0.0;
  double depth = 1.0;       // the image plane's (plane_image_depth of the path)
  double full_arrow = 1.0;  // the longest motion arrow: 0.6 diagonals of the first pose
  Vec3 world_centre{0.0};   // the mean of the path
  PlanePose first_pose;
};
// The loop of `script` (per-frame motions, `seconds_per_frame` > 0 apart) seen by `camera`;
// `fallback` is the first pose when the script has no frames.
PlaneWorldLoop plane_world_loop(const MotionScript& script, const Camera& camera,
                                const PlanePose& fallback, double seconds_per_frame);

// One frame of a plane's world: the plane at `pose` moving by `motion` (per second) at
// frame `frame` of `loop`.
struct PlaneWorldFrame {
  std::array<Vec3, 4> image_corners;  // the image plane at loop.depth (image_plane_corners)
  std::array<Vec3, 4> plane_corners;  // flow/plane.h plane_corners
  std::vector<Vec3> ray_images;       // the corners in front of the eye on the image plane
  WorldArrow normal, up;              // N and U at the centre, 0.3 diagonals long
  Vec3 velocity{0.0};                 // eye_velocity, per second
  Vec3 omega{0.0};                    // per second
  MotionArrows motion;                // V at the centre, Omega at the eye
  int path_index = 0;                 // the frame clamped to the path: past ..k, future k..
};
PlaneWorldFrame plane_world_frame(const PlaneWorldLoop& loop, const PlanePose& pose,
                                  const RigidMotion& motion, int frame);

// The caption under a plane's world: where the image plane is drawn (its depth and the
// camera's f), Omega's and V's conventions, what the path and the rays are.
std::string plane_world_caption(const PlaneWorldLoop& loop);
// The labels of the motion arrows: "V 0.12 units/s", "Omega 0.30 rad/s about the eye", or ""
// for an arrow not drawn.
std::string velocity_label(const MotionArrows& arrows);
std::string omega_label(const MotionArrows& arrows);

// A scene's world (an animator of a scene source: a scene walked by a viewer script, or
// scene shifting), in the scene file's world frame: the scene's polygons, the viewer's
// path, the eye's frustum and image plane moved by the viewer's pose each frame.

// How a polygon of a scene is drawn: its level's colour (palette.h level_colour) when it was
// drawn this frame (clipped polygons are re-rendered: the re-render colour), pale grey (215)
// when culled (back-facing or outside the frustum), dark grey (70) when hidden by polygons in
// front, black when starved.
Rgb8 scene_polygon_colour(PolygonStatus status, Level level);
// The colour of a polygon whose status the animator does not report (scene shifting's).
constexpr Rgb8 kUnreportedPolygon{150, 150, 150};

// What a scene's world shows over its whole walk: built once per source. Speeds per second,
// lengths in world units.
struct SceneWorldLoop {
  Camera camera;
  std::vector<std::vector<Vec3>> outlines;  // each polygon's vertices (core polygon_vertices)
  std::vector<Vec3> path;                   // the eye at every frame of the walk
  double largest_velocity = 0.0;            // of the scene's motion seen by the viewer
  double largest_omega = 0.0;
  double depth = 1.0;       // the image plane's: scene_image_depth of the polygons' vertices
  double full_arrow = 2.0;  // the longest motion arrow: twice the depth
  Vec3 world_centre{0.0};   // the mean of the polygons' vertices
  ViewerPose first_view;    // the walk's first pose (the animator's view without a walk)
};
// The loop of `animator`'s scene and walk (its viewer script when it plays one, frames
// `seconds_per_frame` > 0 apart).
SceneWorldLoop scene_world_loop(const Animator& animator, double seconds_per_frame);

// One frame of a scene's world: the viewer at the animator's view now.
struct SceneWorldFrame {
  ViewerPose view;
  std::array<double, 16> viewer_matrix{};  // viewer_to_world_matrix(view)
  Vec3 eye{0.0};                           // the eye in the world
  std::array<Vec3, 4> image_corners;       // the image plane at loop.depth, world frame
  std::vector<Rgb8> colours;               // per polygon: scene_polygon_colour
  // V and Omega of the frame's scene motion (per second, world frame), both starting 1.5
  // depths ahead of the eye (the eye is crowded with the frustum's labels), when `walking`
  // (the animator plays a viewer script and the frame is one of its frames).
  bool walking = false;
  MotionArrows motion;
  int path_index = 0;  // the frame clamped to the path: past ..k, future k..
};
SceneWorldFrame scene_world_frame(const SceneWorldLoop& loop, const Animator& animator,
                                  double seconds_per_frame);

// The caption under a scene's world: the image plane (showing the engine's frame when
// `frame_on_image_plane`, as the desktop draws it; else a grey rectangle, as the page's), the
// polygons' colours, the arrows and the path.
std::string scene_world_caption(bool frame_on_image_plane);

}  // namespace oflab
