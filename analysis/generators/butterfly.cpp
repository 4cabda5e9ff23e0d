#include "generators/butterfly.h"

#include <algorithm>
#include <cmath>

namespace oflab {
namespace {

struct Rgba {
  double r, g, b, a;
};

// Signed "inside" of an ellipse centred at (cx, cy) with radii (rx, ry), rotated by angle:
// < 1 inside.
double ellipse(double x, double y, double cx, double cy, double rx, double ry, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  const double u = ((x - cx) * c + (y - cy) * s) / rx;
  const double v = (-(x - cx) * s + (y - cy) * c) / ry;
  return u * u + v * v;
}

// Colour of the butterfly at normalised point (x, y): x in [-1, 1] (0 = body axis),
// y in [-1, 1] downwards. Mirror symmetric in x.
Rgba butterfly_colour(double x, double y) {
  const double ax = std::abs(x);
  // Body: a thin dark ellipse with a round head and two antennae.
  if (ellipse(ax, y, 0.0, 0.05, 0.045, 0.62, 0.0) < 1.0 ||
      ellipse(ax, y, 0.0, -0.62, 0.07, 0.07, 0.0) < 1.0) {
    return {0.12, 0.09, 0.08, 1.0};
  }
  const double antenna = std::abs(ax - (0.05 + 0.35 * (-0.66 - y)));
  if (y < -0.66 && y > -0.98 && antenna < 0.018) return {0.12, 0.09, 0.08, 1.0};
  if (y < -0.66 && ellipse(ax, y, 0.17, -0.97, 0.04, 0.04, 0.0) < 1.0)
    return {0.12, 0.09, 0.08, 1.0};
  // Wings: upper (fore) and lower (hind) wing as rotated ellipses.
  const double fore = ellipse(ax, y, 0.50, -0.28, 0.50, 0.36, -0.45);
  const double hind = ellipse(ax, y, 0.38, 0.42, 0.33, 0.40, 0.55);
  const double wing = std::min(fore, hind);
  if (wing >= 1.0) return {0.0, 0.0, 0.0, 0.0};
  // Dark border with white spots, orange inside with dark veins, blue eye spots.
  if (wing > 0.62) {
    const double spot = std::fmod(std::atan2(y + 0.05, ax) * 7.0 + 20.0, 1.0);
    const bool white = wing > 0.70 && wing < 0.88 && std::abs(spot - 0.5) < 0.18;
    return white ? Rgba{0.97, 0.96, 0.90, 1.0} : Rgba{0.10, 0.08, 0.07, 1.0};
  }
  if (ellipse(ax, y, 0.62, 0.48, 0.10, 0.10, 0.0) < 1.0) return {0.15, 0.35, 0.85, 1.0};
  if (ellipse(ax, y, 0.70, -0.42, 0.09, 0.09, 0.0) < 1.0) return {0.98, 0.90, 0.30, 1.0};
  const double vein = std::abs(std::sin(std::atan2(y - 0.05, ax - 0.02) * 6.0));
  if (vein < 0.10 && ax > 0.08) return {0.20, 0.12, 0.06, 1.0};
  const double shade = 0.75 + 0.25 * (1.0 - wing);
  return {0.98 * shade, 0.52 * shade, 0.10 * shade, 1.0};
}

}  // namespace

Image make_butterfly(int width, int height) {
  Image image(width, height);
  constexpr int kSub = 4;
  for (int py = 0; py < height; ++py) {
    for (int px = 0; px < width; ++px) {
      Rgba sum{0, 0, 0, 0};
      for (int sy = 0; sy < kSub; ++sy) {
        for (int sx = 0; sx < kSub; ++sx) {
          const double x = ((px + (sx + 0.5) / kSub) / width) * 2.0 - 1.0;
          const double y = ((py + (sy + 0.5) / kSub) / height) * 2.0 - 1.0;
          const Rgba c = butterfly_colour(x * 1.04, y * 1.04);
          sum.r += c.r * c.a;  // premultiplied accumulation
          sum.g += c.g * c.a;
          sum.b += c.b * c.a;
          sum.a += c.a;
        }
      }
      const double n = kSub * kSub;
      auto byte = [](double v) {
        return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
      };
      Pixel p;
      p.a = byte(sum.a / n);
      p.r = std::min(p.a, byte(sum.r / n));
      p.g = std::min(p.a, byte(sum.g / n));
      p.b = std::min(p.a, byte(sum.b / n));
      image.at(px, py) = p;
    }
  }
  return image;
}

}  // namespace oflab
