// Per-pixel maps of a frame against its exact frame, camera-sized and row-major like core's
// images: the difference (what the --vtk-series difference images and the Python module's
// run.differences show) and the holes of per-pixel depth reprojection
// (core/scene/depth_reprojection.h; the Python module's run.holes).
#pragma once

#include <cstdint>
#include <vector>

#include "engine/animator.h"
#include "image/image.h"

namespace oflab {

// Per pixel, the largest of the four premultiplied channels' absolute differences between
// `shown` and `exact`, in 8-bit levels (0: the same pixel). Throws std::invalid_argument for
// images of different sizes.
std::vector<std::uint8_t> channel_difference_map(const Image& shown, const Image& exact);

// Per pixel, 1 where `animator`'s frame shown now is a hole of depth reprojection: no warped
// pixel reached it (the scene engine's last reprojection left it without a source pixel) and
// `exact`, the exact frame of the same view, covers it (alpha > 0); 0 elsewhere. Empty when
// the frame shown now is no reprojection (another policy or source, or a frame rendered
// afresh on the cadence). Precondition: exact is the animator's camera size or empty.
std::vector<std::uint8_t> reprojection_hole_map(const Animator& animator, const Image& exact);

// What reprojection_hole_map reads: the scene engine's source pixel of every pixel of the
// frame shown now (row-major, -1 where no warped pixel reached it), or nullptr when that
// frame is no reprojection or `exact` is empty or of another size (then the map is empty).
// Valid until the animator advances. A hole is a pixel with source -1 that `exact` covers
// (alpha > 0).
const std::vector<int>* reprojection_sources(const Animator& animator, const Image& exact);

}  // namespace oflab
