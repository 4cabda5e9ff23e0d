// pixman (the rasteriser behind cairo and the X server) on the same cases: a second peer
// for the timings in manual/warping.md. Only built when pkg-config finds pixman-1 (Debian's
// libpixman-1-dev); pixman is never a dependency of oflab itself.
#pragma once

#include <vector>

#include "warp_cases.h"

namespace oflab::bench {

// Registers "pixman/<nearest|bilinear>/<size>/<matrix>" cases: pixman_image_composite32
// with the OVER operator over the whole output frame (transparent before the first call;
// the timed calls composite over the previous result, as OVER reads the frame anyway), one
// thread (pixman has no threads of its own).
// pixman's transform maps output to source pixel coordinates with pixel centres at +0.5,
// oflab's convention, so it is the inverse of T(-origin) * M. Outside the source pixman
// samples transparent (REPEAT_NONE). The Mpx/s counter counts the polygon pixels, as for
// oflab and OpenCV; the "agree" counter is agreement() of warp_cases.h.
void register_pixman_cases(const std::vector<WarpCase>& cases, bool bilinear_too, int repetitions);

}  // namespace oflab::bench
