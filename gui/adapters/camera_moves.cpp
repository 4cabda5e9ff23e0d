#include "adapters/camera_moves.h"

#include <vtkCamera.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include <cmath>

namespace oflab {
namespace {

constexpr double kMotionFactor = 10.0;  // vtkInteractorStyle's default

// The picture's size in pixels, at least 1 x 1.
void picture_size(vtkRenderer* renderer, double* w, double* h) {
  const int* size = renderer->GetRenderWindow()->GetSize();
  *w = std::max(1, size[0]);
  *h = std::max(1, size[1]);
}

void dolly(vtkRenderer* renderer, double factor) {
  vtkCamera* camera = renderer->GetActiveCamera();
  if (camera->GetParallelProjection()) {
    camera->SetParallelScale(camera->GetParallelScale() / factor);
  } else {
    camera->Dolly(factor);
  }
  renderer->ResetCameraClippingRange();
}

}  // namespace

void orbit_camera(vtkRenderer* renderer, const QPointF& drag_px) {
  double w, h;
  picture_size(renderer, &w, &h);
  vtkCamera* camera = renderer->GetActiveCamera();
  // VTK counts y upwards, Qt downwards: a drag down raises the camera over the focal point.
  camera->Azimuth(-20.0 / w * drag_px.x() * kMotionFactor);
  camera->Elevation(20.0 / h * drag_px.y() * kMotionFactor);
  camera->OrthogonalizeViewUp();
  renderer->ResetCameraClippingRange();
}

void pan_camera(vtkRenderer* renderer, const QPointF& drag_px) {
  vtkCamera* camera = renderer->GetActiveCamera();
  double focal[3], position[3];
  camera->GetFocalPoint(focal);
  camera->GetPosition(position);
  // The focal point's depth in display coordinates: the drag moves points at that depth.
  renderer->SetWorldPoint(focal[0], focal[1], focal[2], 1.0);
  renderer->WorldToDisplay();
  const double* display = renderer->GetDisplayPoint();
  const double x = display[0], y = display[1], depth = display[2];
  const auto to_world = [renderer, depth](double dx, double dy, double* out) {
    renderer->SetDisplayPoint(dx, dy, depth);
    renderer->DisplayToWorld();
    const double* p = renderer->GetWorldPoint();
    for (int k = 0; k < 3; ++k) out[k] = p[3] != 0.0 ? p[k] / p[3] : p[k];
  };
  double from[3], to[3];
  to_world(x, y, from);
  to_world(x + drag_px.x(), y - drag_px.y(), to);
  for (int k = 0; k < 3; ++k) {
    const double motion = from[k] - to[k];
    focal[k] += motion;
    position[k] += motion;
  }
  camera->SetFocalPoint(focal);
  camera->SetPosition(position);
  renderer->ResetCameraClippingRange();
}

void dolly_camera(vtkRenderer* renderer, double notches) {
  dolly(renderer, std::pow(1.1, 0.2 * kMotionFactor * notches));
}

void drag_zoom_camera(vtkRenderer* renderer, const QPointF& drag_px) {
  double w, h;
  picture_size(renderer, &w, &h);
  dolly(renderer, std::pow(1.1, -kMotionFactor * drag_px.y() / (0.5 * h)));
}

}  // namespace oflab
