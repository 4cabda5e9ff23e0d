// The basis explorer's three pictures (session/basis/basis_explorer.h), painted with Qt: the
// combined deformation on the texture and on a grid, the two solutions' planes with their
// motions, and the two solutions played forward. Each returns a new image of the asked size
// (at least 1 x 1 pixels) in the theme's colours, its text at least the theme's label size.
#pragma once

#include <QImage>
#include <QRectF>
#include <QSize>
#include <QTransform>

class QPainter;

#include "adapters/view_theme.h"
#include "basis/basis_explorer.h"

namespace oflab {

// Where paint_explorer_deformation draws on a picture of `size` pixels: a caption band of
// `caption` pixels on top, the picture under it (6 px from the sides and the bottom), and the
// camera image (centred pixels) mapped by `to_screen` (a uniform `scale`, canvas pixels per
// camera pixel) onto `frame`, canvas pixels. The framing zooms so that the texture rectangle
// before and after `deformation`, grown by 3 % on every side and within the camera image,
// fills the picture and sits at its centre; the image's frame may then reach past the
// picture. A rectangle carried behind the eye frames the whole image. scale is 0 when the
// picture is empty.
struct DeformationFraming {
  double caption = 0.0;
  QRectF picture, frame;
  QTransform to_screen;
  double scale = 0.0;
};
DeformationFraming explorer_deformation_framing(const Mat3& deformation, const Camera& camera,
                                                const QSize& size, const ViewTheme& theme);

// The share (0..1) of that picture the texture rectangle carried by `deformation` covers
// (inside the image's frame): the explorer's panel_fill. 0 when the rectangle goes behind the
// eye or the picture is empty.
double explorer_deformation_fill(const Mat3& deformation, const Camera& camera, const QSize& size,
                                 const ViewTheme& theme);

// The camera image (its frame), the texture rectangle (the middle half of the image in each
// direction, centred pixels) carried by `deformation` (centred pixels to centred pixels,
// explorer_deformation), a grid of 8 x 8 cells on it deformed the same way, the undeformed
// rectangle's outline, and a caption naming the time, framed by explorer_deformation_framing.
QImage paint_explorer_deformation(const QImage& texture, const Mat3& deformation,
                                  const Camera& camera, const QSize& size, const ViewTheme& theme);

// Each solution of `result` in its own half, seen from above and behind the eye at one
// shared scale: the eye, its line of sight, the plane (a unit square at distance d = 1 across
// its normal N), the arrows of N, V/d (from the plane's centre) and Omega (at the eye, about
// which it turns), with a title and a legend. One solution fills the picture; a plane that
// is unobservable (pure rotation) is drawn as a note.
QImage paint_explorer_solutions(const ExplorerResult& result, const QSize& size,
                                const ViewTheme& theme);

// The two futures at frame `frame` (0 .. result.futures.frames_played): above, side by side,
// the camera's image under solution A and under solution B (`texture` on the quad its
// rectangle's corners reach in `camera`'s frame, the other solution's quad dashed); below
// left, the track of the corner that parts most under each solution, magnified so both fit;
// below right, the largest corner distance per frame with the 1 px line and the first frame
// beyond it marked. A note when the futures were not played (result.futures_note).
QImage paint_explorer_futures(const ExplorerResult& result, int frame, const QImage& texture,
                              const Camera& camera, const QSize& size, const ViewTheme& theme);

// The same two pictures drawn by `painter` on a device of `size` over what is there (the
// functions above fill a new image with the background first; a text recorder,
// gui/adapters/painted_text.h, measures their texts this way).
void draw_explorer_solutions(QPainter& painter, const ExplorerResult& result, const QSize& size,
                             const ViewTheme& theme);
void draw_explorer_futures(QPainter& painter, const ExplorerResult& result, int frame,
                           const QImage& texture, const Camera& camera, const QSize& size,
                           const ViewTheme& theme);

}  // namespace oflab
