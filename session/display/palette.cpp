#include "display/palette.h"

#include <algorithm>
#include <cmath>

namespace oflab {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::uint8_t to_byte(double v) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
}

// HSV to RGB with h in [0, 1), s and v in [0, 1].
Rgb8 hsv(double h, double s, double v) {
  const double h6 = (h - std::floor(h)) * 6.0;
  const int sector = static_cast<int>(h6) % 6;
  const double f = h6 - std::floor(h6);
  const double p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
  const double rgb[6][3] = {{v, t, p}, {q, v, p}, {p, v, t}, {p, q, v}, {t, p, v}, {v, p, q}};
  return {to_byte(rgb[sector][0]), to_byte(rgb[sector][1]), to_byte(rgb[sector][2])};
}

}  // namespace

Rgb8 level_colour(Level level) {
  switch (level) {
    case Level::kNone:
      return {90, 90, 90};
    case Level::kTranslate:
      return okabe_ito::kSkyBlue;
    case Level::kAffine:
      return okabe_ito::kBluishGreen;
    case Level::kPerspective:
      return okabe_ito::kOrange;
    case Level::kRerender:
      return okabe_ito::kVermillion;
  }
  return okabe_ito::kBlack;
}

Rgb8 policy_colour(int index) {
  // Hues 251, 340, 100 and 294 degrees: at least 40 degrees from every level's hue (sky
  // blue 202, bluish green 164, orange 41, vermillion 26) and from each other.
  static constexpr std::array<Rgb8, 4> kPolicies{
      {{100, 70, 235}, {235, 70, 125}, {95, 205, 40}, {205, 60, 220}}};
  return kPolicies[size_t(((index % 4) + 4) % 4)];
}

Rgb8 order_colour(int order) {
  switch (order) {
    case 0:
      return level_colour(Level::kTranslate);
    case 1:
      return level_colour(Level::kAffine);
    default:
      return level_colour(Level::kPerspective);
  }
}

Rgb8 flow_wheel_colour(const Vec2& flow, double max_magnitude) {
  const double magnitude = glm::length(flow);
  const double s = max_magnitude > 0.0 ? std::min(1.0, magnitude / max_magnitude) : 0.0;
  const double angle = std::atan2(flow.y, flow.x);  // image coordinates, Y down
  return hsv(angle / (2.0 * kPi) + (angle < 0.0 ? 1.0 : 0.0), s, 1.0);
}

Rgb8 magnitude_colour(double t) {
  // Five stops of viridis, linearly interpolated.
  static constexpr double kStops[5][3] = {{0.267, 0.005, 0.329},
                                          {0.230, 0.322, 0.546},
                                          {0.128, 0.567, 0.551},
                                          {0.369, 0.789, 0.383},
                                          {0.993, 0.906, 0.144}};
  const double x = std::clamp(std::isfinite(t) ? t : 0.0, 0.0, 1.0) * 4.0;
  const int i = std::min(3, static_cast<int>(x));
  const double f = x - i;
  return {to_byte(kStops[i][0] + f * (kStops[i + 1][0] - kStops[i][0])),
          to_byte(kStops[i][1] + f * (kStops[i + 1][1] - kStops[i][1])),
          to_byte(kStops[i][2] + f * (kStops[i + 1][2] - kStops[i][2]))};
}

}  // namespace oflab
