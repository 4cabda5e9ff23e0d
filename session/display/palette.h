// Colours used by every view of every front-end, defined once. The level colours use the Okabe-Ito
// palette (Okabe and Ito, "Color Universal Design", 2008), which stays distinguishable for the
// common forms of colour blindness; the animation view will outline each polygon in the
// colour of the level chosen for it. Plain C++: colours are 8-bit sRGB.
#pragma once

#include <array>
#include <cstdint>

#include "engine/decision.h"
#include "flow/geometry.h"

namespace oflab {

struct Rgb8 {
  std::uint8_t r = 0, g = 0, b = 0;
};

// The eight Okabe-Ito colours.
namespace okabe_ito {
constexpr Rgb8 kBlack{0, 0, 0};
constexpr Rgb8 kOrange{230, 159, 0};
constexpr Rgb8 kSkyBlue{86, 180, 233};
constexpr Rgb8 kBluishGreen{0, 158, 115};
constexpr Rgb8 kYellow{240, 228, 66};
constexpr Rgb8 kBlue{0, 114, 178};
constexpr Rgb8 kVermillion{213, 94, 0};
constexpr Rgb8 kReddishPurple{204, 121, 167};
}  // namespace okabe_ito

// The colour of a level (Okabe-Ito): none grey-black, translate sky blue, affine bluish
// green, perspective orange, re-render vermillion.
Rgb8 level_colour(Level level);

// The colour of the `index`-th compared policy (0 .. 3, in the comparison's panel order;
// taken modulo 4 beyond), for its lines and legend in the analysis view, in the order
// violet-blue, rose, lime, purple. Charts show policies and levels side by side, so no
// policy colour is near a level's colour: each hue is at least 40 degrees from every
// level's hue (a policy named like a level, "rerender", is not mistaken for that level's
// frames) and from the other policies'.
Rgb8 policy_colour(int index);

// The colour of a basis order in the gallery: 0 sky blue, 1 bluish green, 2 orange
// (the colours of the levels that carry that order).
Rgb8 order_colour(int order);

// Flow colour-wheel coding: the hue gives the direction (angle of the flow in image
// coordinates, Y down: right = red, down = yellow-green, left = cyan, up = blue-violet),
// the saturation the magnitude relative to max_magnitude (white = no flow, clamped at 1).
Rgb8 flow_wheel_colour(const Vec2& flow, double max_magnitude);

// The one sequential colour ramp (viridis, five stops linearly interpolated: 0 = dark
// purple, 1 = yellow), t clamped to [0, 1] (NaN as 0): flow magnitude, and the difference
// heat maps of the desktop (gui/adapters/frame_images.h) and of the browser page
// (web/frame_pixels.h).
Rgb8 magnitude_colour(double t);

}  // namespace oflab
