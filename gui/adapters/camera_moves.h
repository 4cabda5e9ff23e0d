// Moving a VTK camera with the mouse without a VTK interactor: the rules of VTK's trackball
// camera style (vtkInteractorStyleTrackballCamera, motion factor 10) applied to drags and
// wheel turns that a plain Qt widget reports, so a view rendered offscreen
// (gui/adapters/offscreen_vtk.h) is turned like VTK's own widget was.
//
// Units: drags in device pixels of the rendered picture, Qt's convention (x right, y down);
// `renderer` is the renderer whose active camera moves, in a render window of the picture's
// size. Every move resets the camera's clipping range to what the renderer shows.
#pragma once

#include <QPointF>

class vtkRenderer;

namespace oflab {

// Turns the camera about its focal point: a drag across the whole picture's width turns it
// by 200 degrees about the view-up (azimuth), one across its height by 200 degrees about
// the horizontal (elevation); the view-up is kept orthogonal.
void orbit_camera(vtkRenderer* renderer, const QPointF& drag_px);

// Slides the camera and its focal point together so that the point under the mouse at the
// focal depth follows the mouse by `drag_px`.
void pan_camera(vtkRenderer* renderer, const QPointF& drag_px);

// Moves the camera towards its focal point by the factor 1.1^(2 notches) (a wheel notch
// away from the user zooms in; negative notches zoom out).
void dolly_camera(vtkRenderer* renderer, double notches);

// The right button's zoom: dragging up by half the picture's height zooms in by 1.1^10,
// down zooms out.
void drag_zoom_camera(vtkRenderer* renderer, const QPointF& drag_px);

}  // namespace oflab
