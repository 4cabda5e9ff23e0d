#include "adapters/hole_map.h"

#include <algorithm>
#include <array>

#include "image/thread_pool.h"

namespace oflab {

QColor hole_colour() { return QColor(255, 0, 255); }

std::int64_t mark_holes(QImage& map, const std::vector<std::uint8_t>& holes) {
  const int width = map.width(), height = map.height();  // out-of-line calls: read once
  if (holes.empty() || std::size_t(width) * std::size_t(height) != holes.size()) return 0;
  const QRgb colour = hole_colour().rgb();
  std::int64_t marked = 0;
  for (int y = 0; y < height; ++y) {
    auto* line = reinterpret_cast<QRgb*>(map.scanLine(y));
    const std::uint8_t* row = holes.data() + std::size_t(y) * std::size_t(width);
    for (int x = 0; x < width; ++x) {
      if (!row[x]) continue;
      line[x] = colour;
      ++marked;
    }
  }
  return marked;
}

std::int64_t mark_reprojection_holes(QImage& map, const std::vector<int>& sources,
                                     const Image& exact) {
  const int width = map.width(), height = map.height();
  const std::size_t pixels = std::size_t(width) * std::size_t(height);
  if (sources.size() != pixels || exact.pixels().size() != pixels || exact.width() != width)
    return 0;
  const QRgb colour = hole_colour().rgb();
  map.bits();  // detached once, so that the bands' scanLine() only reads its sharing
  std::array<std::int64_t, kMaxBands> counts{};
  for_each_band(height, std::max(8, 65536 / std::max(1, width)), [&](int band, int begin, int end) {
    std::int64_t marked = 0;
    for (int y = begin; y < end; ++y) {
      auto* line = reinterpret_cast<QRgb*>(map.scanLine(y));
      const int* source = sources.data() + std::size_t(y) * std::size_t(width);
      const Pixel* seen = exact.row(y);
      for (int x = 0; x < width; ++x) {
        if (source[x] >= 0 || seen[x].a == 0) continue;
        line[x] = colour;
        ++marked;
      }
    }
    counts[std::size_t(band)] = marked;
  });
  std::int64_t marked = 0;
  for (std::int64_t c : counts) marked += c;
  return marked;
}

}  // namespace oflab
