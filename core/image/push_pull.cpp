// Push-pull inpainting (core/image/push_pull.h).
#include "image/push_pull.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "image/thread_pool.h"

namespace oflab {
namespace {

// One level of the pyramid: premultiplied RGBA as reals and a weight per pixel.
struct Level {
  int width = 0;
  int height = 0;
  std::vector<std::array<float, 4>> colour;
  std::vector<float> weight;
  void resize(int w, int h) {
    width = w, height = h;
    colour.resize(static_cast<std::size_t>(w) * h);
    weight.resize(static_cast<std::size_t>(w) * h);
  }
};

// Rows per band of a pass over a level `width` pixels wide.
int min_band_rows(int width) { return std::max(4, 16384 / std::max(width, 1)); }

// Level l + 1 (`coarse`, sized) from level l, rows [begin, end) of it: weighted means of 2 x 2
// blocks, weight min(1, sum). Each block is summed from 0 in row-major order of its children,
// as accumulating the children row by row over the fine level sums it. fine(f, w, c) gives
// child f's weight and colour (level l is `width` x `height`).
template <class Fine>
void pull_rows(int width, int height, const Fine& fine, Level& coarse, int begin, int end) {
  for (int y = begin; y < end; ++y) {
    for (int x = 0; x < coarse.width; ++x) {
      std::array<float, 4> sum = {0.0f, 0.0f, 0.0f, 0.0f};
      float weight = 0.0f;
      for (int fy = 2 * y; fy < std::min(2 * y + 2, height); ++fy) {
        for (int fx = 2 * x; fx < std::min(2 * x + 2, width); ++fx) {
          float w = 0.0f;
          std::array<float, 4> c;
          fine(static_cast<std::size_t>(fy) * width + fx, w, c);
          for (int k = 0; k < 4; ++k) sum[k] += w * c[k];
          weight += w;
        }
      }
      if (weight > 0.0f) {
        for (float& channel : sum) channel /= weight;
      }
      const std::size_t c = static_cast<std::size_t>(y) * coarse.width + x;
      coarse.colour[c] = sum;
      coarse.weight[c] = std::min(1.0f, weight);
    }
  }
}

// Rows [begin, end) of level l pushed from its pushed parent: w c + (1 - w) c_parent.
void push_rows(Level& fine, const Level& coarse, int begin, int end) {
  for (int y = begin; y < end; ++y) {
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

// Rows [begin, end) of the image's holes given their pushed colour, their parent's in level 1
// (`parent`); returns the pixels filled.
std::int64_t fill_hole_rows(const Level& parent, const std::vector<char>& hole, int begin, int end,
                            Image& image) {
  const int width = image.width();
  std::int64_t filled = 0;
  for (int y = begin; y < end; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::size_t k = static_cast<std::size_t>(y) * width + x;
      if (!hole[k]) continue;
      const std::array<float, 4>& c =
          parent.colour[static_cast<std::size_t>(y / 2) * parent.width + x / 2];
      Pixel p{channel(c[0]), channel(c[1]), channel(c[2]), channel(c[3])};
      p.r = std::min(p.r, p.a), p.g = std::min(p.g, p.a), p.b = std::min(p.b, p.a);
      image.pixels()[k] = p;
      ++filled;
    }
  }
  return filled;
}

}  // namespace

std::int64_t push_pull_inpaint(Image& image, const std::vector<char>& hole) {
  if (hole.size() != image.pixel_count()) {
    throw std::invalid_argument("push_pull_inpaint: the hole mask and the image differ in size");
  }
  if (hole.empty() || std::find(hole.begin(), hole.end(), 0) == hole.end()) return 0;
  const int width = image.width(), height = image.height();
  std::size_t top = 0;  // the coarsest level, 1 x 1
  for (int w = width, h = height; w > 1 || h > 1; w = (w + 1) / 2, h = (h + 1) / 2) ++top;
  if (top == 0) return 0;  // one pixel, and it is valid
  // Levels 1 .. top, kept by each thread that inpaints: fresh levels cost a page fault per
  // page every frame. (The bands reach them through `levels`: on a worker thread the name
  // `pyramid` is that thread's own.) Level 0, the image with weight 0 in a hole and 1
  // elsewhere, is read in place: a valid pixel keeps its colour, and a hole's pushed colour,
  // 0 c + (1 - 0) c_parent, is its parent's to the bit, so it is never made.
  thread_local std::vector<Level> pyramid;
  std::vector<Level>& levels = pyramid;
  if (levels.size() < top + 1) levels.resize(top + 1);
  levels[1].resize((width + 1) / 2, (height + 1) / 2);
  const auto image_pixel = [&](std::size_t f, float& w, std::array<float, 4>& c) {
    const Pixel p = image.pixels()[f];
    w = hole[f] ? 0.0f : 1.0f;
    c = {static_cast<float>(p.r), static_cast<float>(p.g), static_cast<float>(p.b),
         static_cast<float>(p.a)};
  };
  for_each_band(levels[1].height, min_band_rows(levels[1].width), [&](int, int begin, int end) {
    pull_rows(width, height, image_pixel, levels[1], begin, end);
  });
  for (std::size_t l = 1; l < top; ++l) {
    const Level& fine = levels[l];
    Level& coarse = levels[l + 1];
    coarse.resize((fine.width + 1) / 2, (fine.height + 1) / 2);
    const auto level_pixel = [&](std::size_t f, float& w, std::array<float, 4>& c) {
      w = fine.weight[f], c = fine.colour[f];
    };
    for_each_band(coarse.height, min_band_rows(coarse.width), [&](int, int begin, int end) {
      pull_rows(fine.width, fine.height, level_pixel, coarse, begin, end);
    });
  }
  for (std::size_t l = top; l-- > 1;) {
    for_each_band(levels[l].height, min_band_rows(levels[l].width), [&](int, int begin, int end) {
      push_rows(levels[l], levels[l + 1], begin, end);
    });
  }
  const Level& parent = levels[1];
  const int bands = band_count(height, min_band_rows(width));
  std::vector<std::int64_t> filled(static_cast<std::size_t>(bands), 0);
  for_each_band(height, min_band_rows(width), [&](int band, int begin, int end) {
    filled[band] = fill_hole_rows(parent, hole, begin, end, image);
  });
  std::int64_t total = 0;
  for (const std::int64_t f : filled) total += f;
  return total;
}

}  // namespace oflab
