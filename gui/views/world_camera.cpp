// The world view's camera (gui/views/world_scene.h): its two framings, the orbit vantage that
// frames the eye, its image plane and the plane (or the scene) from beside the eye, and the
// view through the eye. Units: world units in space, canvas pixels in the picture (VTK's
// display y runs upwards).
#include <vtkCamera.h>

#include <algorithm>
#include <cmath>

#include "display/world_geometry.h"
#include "views/world_scene.h"

namespace oflab {
namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

void WorldScene::reset_camera() {
  from_eye = false;
  show_parts();
  const Mat3 to_world = glm::transpose(first_view.rotation);
  const Vec3 forward = to_world * Vec3(0, 0, 1), view_up = to_world * Vec3(0, -1, 0),
             right = to_world * Vec3(1, 0, 0);
  if (scene_mode) {
    // A scene: from the left of the eye, a little behind and above it, the viewer's path seen
    // from its side; closer in a wide view, a narrow one (the cause-and-effect layout) keeping
    // the whole width; the viewer's path may leave the picture, the polygons and the viewer stay.
    place_orbit(-0.55 * forward - 1.0 * right + 0.45 * view_up, view_up);
    renderer->GetActiveCamera()->Zoom(1.6 *
                                      std::clamp(renderer->GetTiledAspectRatio() / 1.6, 0.6, 1.0));
  } else {
    // The plane: from behind the eye and to its left, above it, so the frustum opens towards
    // the plane across the picture. Of a few such vantages, the one whose picture of the eye,
    // its image plane and the plane now covers most of the picture between the legend and the
    // caption (the foreshortened eye-to-plane picture is wide, a view may be narrow: the
    // cause-and-effect layout's wants a higher vantage, which spreads it over the height).
    Vec3 best_side = -0.8 * forward - 0.8 * right + 0.45 * view_up;
    double best_share = -1.0;
    for (const double up : {0.45, 0.8, 1.2, 1.7}) {
      for (const double back : {0.3, 0.55, 0.8, 1.1}) {
        for (const double left : {0.4, 0.8}) {
          const Vec3 side = -back * forward - left * right + up * view_up;
          frame_plane_from(side, view_up);
          const double share = drawn_share();
          if (share > best_share + 1e-3) best_share = share, best_side = side;
        }
      }
    }
    frame_plane_from(best_side, view_up);
  }
  renderer->ResetCameraClippingRange();
  needs_render = true;
}

void WorldScene::place_orbit(const Vec3& side, const Vec3& view_up) {
  const Vec3 eye_at = viewer_to_world(first_view, Vec3(0.0));
  const Vec3 focus = 0.5 * (eye_at + world_centre);
  const double distance = std::max(1e-3, glm::length(world_centre - eye_at));
  const Vec3 from = focus + distance * side;
  vtkCamera* vtk_camera = renderer->GetActiveCamera();
  vtk_camera->SetFocalPoint(focus.x, focus.y, focus.z);
  vtk_camera->SetPosition(from.x, from.y, from.z);
  vtk_camera->SetViewUp(view_up.x, view_up.y, view_up.z);
  vtk_camera->SetViewAngle(30.0);
  renderer->ResetCamera();
}

// ResetCamera fits a bounding sphere, loosely: the plane is then centred and brought closer,
// as far as every place it takes over the loop (and the eye's frustum) stays inside 90 % of
// the picture.
void WorldScene::frame_plane_from(const Vec3& side, const Vec3& view_up) {
  place_orbit(side, view_up);
  centre_framed_points();
  renderer->GetActiveCamera()->Zoom(fit_zoom(0.9));
}

void WorldScene::centre_framed_points() {
  const std::vector<Vec3> points = framed_points();
  double left = 1e300, right = -1e300, bottom = 1e300, top = -1e300;
  for (const Vec3& p : points) {
    QPointF d;
    if (!to_display(p, &d)) continue;
    left = std::min(left, d.x()), right = std::max(right, d.x());
    bottom = std::min(bottom, d.y()), top = std::max(top, d.y());
  }
  if (left > right) return;
  vtkCamera* vtk_camera = renderer->GetActiveCamera();
  const double* focal = vtk_camera->GetFocalPoint();
  renderer->SetWorldPoint(focal[0], focal[1], focal[2], 1.0);
  renderer->WorldToDisplay();
  const double depth_z = renderer->GetDisplayPoint()[2];
  const int* size = window->GetSize();
  const QRectF picture = framed_picture();
  const auto world_at = [&](double x, double y) {
    renderer->SetDisplayPoint(x, y, depth_z);
    renderer->DisplayToWorld();
    const double* w = renderer->GetWorldPoint();
    return Vec3(w[0], w[1], w[2]) / (w[3] != 0.0 ? w[3] : 1.0);
  };
  // Pan (camera and focal point together) so that the box's centre is the picture's (VTK's
  // display y runs upwards).
  const Vec3 shift = world_at(0.5 * (left + right), 0.5 * (bottom + top)) -
                     world_at(picture.center().x(), size[1] - picture.center().y());
  const double* from = vtk_camera->GetPosition();
  vtk_camera->SetPosition(from[0] + shift.x, from[1] + shift.y, from[2] + shift.z);
  vtk_camera->SetFocalPoint(focal[0] + shift.x, focal[1] + shift.y, focal[2] + shift.z);
}

std::vector<Vec3> WorldScene::framed_points() const {
  std::vector<Vec3> points = {viewer_to_world(first_view, Vec3(0.0))};
  for (const Vec3& c : image_plane_corners(camera, depth)) {
    points.push_back(viewer_to_world(first_view, c));
  }
  // The plane's corners wherever the loop takes them; a scene's viewer path.
  if (scene_mode) {
    points.insert(points.end(), path.begin(), path.end());
  } else {
    points.insert(points.end(), loop_corners.begin(), loop_corners.end());
  }
  return points;
}

QRectF WorldScene::framed_picture() const {
  const int* size = window->GetSize();
  const QRectF free = texts.free_area();
  return free.isEmpty() || free.width() > size[0] + 0.5 || free.height() > size[1] + 0.5
             ? QRectF(0, 0, size[0], size[1])
             : free;
}

double WorldScene::fit_zoom(double fill) const {
  const std::vector<Vec3> points = framed_points();
  const int* size = window->GetSize();
  const QRectF picture = framed_picture();
  double widest = 1e-9;  // the furthest point from the picture's centre, in half sizes
  for (const Vec3& p : points) {
    QPointF d;
    if (!to_display(p, &d)) continue;
    widest =
        std::max({widest, std::abs(d.x() - picture.center().x()) / (0.5 * picture.width()),
                  std::abs(size[1] - d.y() - picture.center().y()) / (0.5 * picture.height())});
  }
  return std::clamp(fill / widest, 0.5, 3.0);
}

void WorldScene::view_from_camera() {
  const Mat3 to_world = glm::transpose(view.rotation);
  const Vec3 eye_at = viewer_to_world(view, Vec3(0.0));
  const Vec3 ahead = eye_at + to_world * Vec3(0, 0, 4.0 * depth),
             view_up = to_world * Vec3(0, -1, 0);
  // The image's half height and half width over the focal length; VTK's angle is vertical,
  // so a render narrower than the image needs a taller angle to show its whole width.
  const double aspect = std::max(1e-3, renderer->GetTiledAspectRatio());
  const double half_tan = (1.0 + 2.0 * kEyeViewMargin) * 0.5 / camera.focal_px *
                          std::max(double(camera.height), double(camera.width) / aspect);
  vtkCamera* vtk_camera = renderer->GetActiveCamera();
  vtk_camera->SetPosition(eye_at.x, eye_at.y, eye_at.z);
  vtk_camera->SetFocalPoint(ahead.x, ahead.y, ahead.z);
  vtk_camera->SetViewUp(view_up.x, view_up.y, view_up.z);
  vtk_camera->SetViewAngle(2.0 * std::atan(half_tan) * 180.0 / kPi);
  from_eye = true;
  show_parts();
  renderer->ResetCameraClippingRange();
  needs_render = true;
}

void WorldScene::leave_eye() {
  from_eye = false;
  show_parts();
  needs_render = true;
}

}  // namespace oflab
