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
// as accumulating the children row by row over the fine level sums it.
void pull_rows(const Level& fine, Level& coarse, int begin, int end) {
  for (int y = begin; y < end; ++y) {
    for (int x = 0; x < coarse.width; ++x) {
      std::array<float, 4> sum = {0.0f, 0.0f, 0.0f, 0.0f};
      float weight = 0.0f;
      for (int fy = 2 * y; fy < std::min(2 * y + 2, fine.height); ++fy) {
        for (int fx = 2 * x; fx < std::min(2 * x + 2, fine.width); ++fx) {
          const std::size_t f = static_cast<std::size_t>(fy) * fine.width + fx;
          const float w = fine.weight[f];
          for (int k = 0; k < 4; ++k) sum[k] += w * fine.colour[f][k];
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

}  // namespace

std::int64_t push_pull_inpaint(Image& image, const std::vector<char>& hole) {
  if (hole.size() != image.pixel_count()) {
    throw std::invalid_argument("push_pull_inpaint: the hole mask and the image differ in size");
  }
  if (hole.empty()) return 0;
  // The pyramid, kept by each thread that inpaints: fresh levels cost a page fault per page
  // every frame. (The bands reach it through `levels`: on a worker thread the name `pyramid`
  // is that thread's own.)
  thread_local std::vector<Level> pyramid(1);
  std::vector<Level>& levels = pyramid;
  const int width = image.width();
  std::size_t top = 0;  // the coarsest level, 1 x 1
  for (int w = width, h = image.height(); w > 1 || h > 1; w = (w + 1) / 2, h = (h + 1) / 2) ++top;
  if (levels.size() < top + 1) levels.resize(top + 1);
  levels[0].resize(width, image.height());
  Level& base = levels[0];
  const int bands = band_count(base.height, min_band_rows(width));
  std::vector<char> valid(static_cast<std::size_t>(bands), 0);
  for_each_band(base.height, min_band_rows(width), [&](int band, int begin, int end) {
    for (std::size_t k = static_cast<std::size_t>(begin) * width;
         k < static_cast<std::size_t>(end) * width; ++k) {
      const Pixel p = image.pixels()[k];
      base.colour[k] = {static_cast<float>(p.r), static_cast<float>(p.g), static_cast<float>(p.b),
                        static_cast<float>(p.a)};
      base.weight[k] = hole[k] ? 0.0f : 1.0f;
      valid[band] = valid[band] || !hole[k];
    }
  });
  if (std::find(valid.begin(), valid.end(), 1) == valid.end()) return 0;
  for (std::size_t l = 0; l < top; ++l) {
    const Level& fine = levels[l];
    Level& coarse = levels[l + 1];
    coarse.resize((fine.width + 1) / 2, (fine.height + 1) / 2);
    for_each_band(coarse.height, min_band_rows(coarse.width),
                  [&](int, int begin, int end) { pull_rows(fine, coarse, begin, end); });
  }
  for (std::size_t l = top; l-- > 0;) {
    for_each_band(levels[l].height, min_band_rows(levels[l].width), [&](int, int begin, int end) {
      push_rows(levels[l], levels[l + 1], begin, end);
    });
  }
  std::vector<std::int64_t> filled(static_cast<std::size_t>(bands), 0);
  for_each_band(base.height, min_band_rows(width), [&](int band, int begin, int end) {
    for (std::size_t k = static_cast<std::size_t>(begin) * width;
         k < static_cast<std::size_t>(end) * width; ++k) {
      if (!hole[k]) continue;
      const std::array<float, 4>& c = base.colour[k];
      Pixel p{channel(c[0]), channel(c[1]), channel(c[2]), channel(c[3])};
      p.r = std::min(p.r, p.a), p.g = std::min(p.g, p.a), p.b = std::min(p.b, p.a);
      image.pixels()[k] = p;
      ++filled[band];
    }
  });
  std::int64_t total = 0;
  for (const std::int64_t f : filled) total += f;
  return total;
}

}  // namespace oflab
