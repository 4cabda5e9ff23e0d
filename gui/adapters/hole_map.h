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

#include "image/image.h"

namespace oflab {

// The colour hole pixels are marked in: magenta, which neither the viridis ramp nor a level's
// colour (session/display/palette.h) takes.
QColor hole_colour();

// Paints every hole pixel of `holes` (analysis/runs/frame_maps.h reprojection_hole_map: 1 for
// a hole, row-major) in hole_colour() on `map` (a heat map of the same size) and returns how
// many it marked; 0 for an empty mask.
std::int64_t mark_holes(QImage& map, const std::vector<std::uint8_t>& holes);

// The same without the mask: marks the pixels whose reprojection source is -1 (`sources`,
// analysis/runs/frame_maps.h reprojection_sources, row-major) and that `exact` covers
// (alpha > 0), in bands of rows on core's worker threads, and returns how many: the pixels and
// the count of mark_holes(map, reprojection_hole_map(...)). 0, marking nothing, when `map`,
// `sources` and `exact` differ in size.
std::int64_t mark_reprojection_holes(QImage& map, const std::vector<int>& sources,
                                     const Image& exact);

}  // namespace oflab
