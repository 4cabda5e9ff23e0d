// Push-pull inpainting (core/image/push_pull.h).
#include "image/push_pull.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace oflab {
namespace {

// One level of the pyramid: premultiplied RGBA as reals and a weight per pixel.
struct Level {
  int width = 0;
  int height = 0;
  std::vector<std::array<float, 4>> colour;
  std::vector<float> weight;
};

// Level l + 1 from level l: weighted means of 2 x 2 blocks, weight min(1, sum).
Level pull(const Level& fine) {
  Level coarse;
  coarse.width = (fine.width + 1) / 2;
  coarse.height = (fine.height + 1) / 2;
  const std::size_t n = static_cast<std::size_t>(coarse.width) * coarse.height;
  coarse.colour.assign(n, {0.0f, 0.0f, 0.0f, 0.0f});
  coarse.weight.assign(n, 0.0f);
  for (int y = 0; y < fine.height; ++y) {
    for (int x = 0; x < fine.width; ++x) {
      const std::size_t f = static_cast<std::size_t>(y) * fine.width + x;
      const std::size_t c = static_cast<std::size_t>(y / 2) * coarse.width + x / 2;
      const float w = fine.weight[f];
      for (int k = 0; k < 4; ++k) coarse.colour[c][k] += w * fine.colour[f][k];
      coarse.weight[c] += w;
    }
  }
  for (std::size_t c = 0; c < n; ++c) {
    const float w = coarse.weight[c];
    if (w > 0.0f) {
      for (float& channel : coarse.colour[c]) channel /= w;
    }
    coarse.weight[c] = std::min(1.0f, w);
  }
  return coarse;
}

// Level l pushed from its pushed parent: w c + (1 - w) c_parent.
void push(Level& fine, const Level& coarse) {
  for (int y = 0; y < fine.height; ++y) {
    for (int x = 0; x < fine.width; ++x) {
      const std::size_t f = static_cast<std::size_t>(y) * fine.width + x;
      const std::size_t c = static_cast<std::size_t>(y / 2) * coarse.width + x / 2;
      const float w = fine.weight[f];
      if (w >= 1.0f) continue;
      for (int k = 0; k < 4; ++k) {
        fine.colour[f][k] = w * fine.colour[f][k] + (1.0f - w) * coarse.colour[c][k];
      }
    }
  }
}

std::uint8_t channel(float v) {
  return static_cast<std::uint8_t>(std::clamp(std::lround(v), 0L, 255L));
}

}  // namespace

std::int64_t push_pull_inpaint(Image& image, const std::vector<char>& hole) {
  if (hole.size() != image.pixel_count()) {
    throw std::invalid_argument("push_pull_inpaint: the hole mask and the image differ in size");
  }
  std::vector<Level> levels(1);
  Level& base = levels[0];
  base.width = image.width();
  base.height = image.height();
  base.colour.resize(hole.size());
  base.weight.resize(hole.size());
  bool any_valid = false;
  for (std::size_t k = 0; k < hole.size(); ++k) {
    const Pixel p = image.pixels()[k];
    base.colour[k] = {static_cast<float>(p.r), static_cast<float>(p.g), static_cast<float>(p.b),
                      static_cast<float>(p.a)};
    base.weight[k] = hole[k] ? 0.0f : 1.0f;
    any_valid = any_valid || !hole[k];
  }
  if (!any_valid || hole.empty()) return 0;
  while (levels.back().width > 1 || levels.back().height > 1) levels.push_back(pull(levels.back()));
  for (std::size_t l = levels.size() - 1; l-- > 0;) push(levels[l], levels[l + 1]);
  std::int64_t filled = 0;
  for (std::size_t k = 0; k < hole.size(); ++k) {
    if (!hole[k]) continue;
    const std::array<float, 4>& c = levels[0].colour[k];
    Pixel p{channel(c[0]), channel(c[1]), channel(c[2]), channel(c[3])};
    p.r = std::min(p.r, p.a), p.g = std::min(p.g, p.a), p.b = std::min(p.b, p.a);
    image.pixels()[k] = p;
    ++filled;
  }
  return filled;
}

}  // namespace oflab
