// The page's world view in numbers (web/world_view.js draws them with vtk.js): the teaching
// layer's plane world (session/display/world_geometry.h), the one the desktop's world view
// draws, as JSON. Plain C++ (no emscripten), so tests/web checks it natively.
//
// Frames and units: the viewer frame of core/flow/camera.h (the eye at the origin, looking
// along +Z, X right, Y down), world units; speeds per second; matrices row-major 4x4 mapping
// the unit arrow from (0,0,0) to (1,0,0) onto the arrow (world_geometry.h arrow_matrix).
#pragma once

#include <string>

#include "display/label_layout.h"
#include "display/world_geometry.h"
#include "engine/animator.h"
#include "player/plane_panel.h"

namespace oflab {

// The loop of the panel's plane (plane_world_loop of its script, PlanePanel::kSecondsPerFrame
// apart): {"kind": "plane", "camera": {width, height, focal_px, cx, cy}, "depth", "full_arrow",
// "largest_velocity", "largest_omega", "image_corners": 4 points, "path": a point per frame,
// "world_centre", "bounds": [xmin, xmax, ymin, ymax, zmin, zmax] of the eye, the image plane
// and the plane's corners over the loop, "caption", "texture": `texture_source` (the file the
// plane's texture came from, "" for the default), "colours": {velocity, omega, normal, up,
// rays, path_past, plane}: [r, g, b] of session/display/palette.h}.
PlaneWorldLoop panel_world_loop(const PlanePanel& panel);
std::string world_loop_json(const PlaneWorldLoop& loop, const std::string& texture_source);

// The frame shown: {"frame", "plane_corners", "ray_images", "omega_axis", "velocity",
// "omega" (per second), "path_index", "arrows": {velocity, omega, normal, up: {"origin",
// "direction", "length", "matrix"}}, "labels": [{"key", "text", "at"}] for the eye, the
// image plane, V, Omega, N and U (at the arrows' tips; "" text for an arrow not drawn)}.
std::string world_frame_json(const PlaneWorldLoop& loop, const PlanePanel& panel);

// A scene's walk (session/display/world_geometry.h scene_world_loop), in the scene's world
// frame: {"kind": "scene", "camera", "depth", "full_arrow", "largest_velocity",
// "largest_omega", "image_corners" (viewer frame: the frame's viewer_matrix places them),
// "path" (the eye per frame), "world_centre", "first_view" (viewer_to_world_matrix of the
// walk's first pose, row-major), "bounds" of the polygons, the path and the first eye,
// "outlines": per polygon its vertices, "caption", "colours" (as the plane's)}.
std::string scene_world_loop_json(const SceneWorldLoop& loop);
// The animator's frame: {"frame", "viewer_matrix" (row-major, viewer to world), "eye",
// "polygon_colours": per polygon [r, g, b] (scene_polygon_colour), "omega_axis",
// "path_index", "arrows": {velocity, omega, normal, up (N and U: length 0, not drawn)},
// "labels": eye, image plane, V, Omega}.
std::string scene_world_frame_json(const SceneWorldLoop& loop, const Animator& animator,
                                   double seconds_per_frame);

// The world view's labels placed by the teaching layer's rule (session/display/label_layout.h
// place_labels), the desktop's: `request` is {"sizes": [[w, h], ...], "anchors": [[x, y], ...]
// (as many), "area": [x, y, w, h], "taken": [[x, y, w, h], ...], "gap", "avoid": [[[x, y],
// ...], ...]} in the picture's pixels (top-left origin, y down); the answer is the boxes,
// [[x, y, w, h], ...], one per label in order. Throws std::invalid_argument naming the field
// when a field is missing or not of its form.
std::string placed_labels_json(const std::string& request);

}  // namespace oflab
