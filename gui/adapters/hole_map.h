// The hole map of per-pixel depth reprojection (core/scene/depth_reprojection.h): the pixels
// of a reprojected frame that no warped pixel reached although the exact frame shows a
// surface there (a disocclusion, or a part of the view outside the rendered frame), marked
// on the comparison's difference heat map in one colour that the viridis ramp never takes,
// so a hole is never mistaken for an error and never filled silently.
// Images are camera-sized; pixel (x, y) of a core Image is pixel (x, y) of the QImage.
#pragma once

#include <QColor>
#include <QImage>
#include <cstdint>
#include <vector>

#include "engine/animator.h"
#include "image/image.h"

namespace oflab {

// The colour hole pixels are marked in: magenta, which neither the viridis ramp nor a level's
// colour (session/display/palette.h) takes.
QColor hole_colour();

// Per pixel (row-major, camera-sized) 1 where `animator`'s frame shown now is a hole: the
// depth-reprojection policy's frame left the pixel unreached (no source pixel) and `exact`,
// the exact frame of the same view, covers it (alpha > 0); 0 elsewhere. Empty when the frame
// shown now is no reprojection (another policy or source, or a frame rendered afresh on the
// cadence), so it has no holes. Precondition: exact is the animator's camera size or empty.
std::vector<char> reprojection_holes(const Animator& animator, const Image& exact);

// Paints every hole pixel of `holes` (reprojection_holes) in hole_colour() on `map` (a heat
// map of the same size) and returns how many it marked; 0 for an empty mask.
std::int64_t mark_holes(QImage& map, const std::vector<char>& holes);

}  // namespace oflab
