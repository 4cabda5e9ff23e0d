#include "adapters/hole_map.h"

namespace oflab {

QColor hole_colour() { return QColor(255, 0, 255); }

std::int64_t mark_holes(QImage& map, const std::vector<std::uint8_t>& holes) {
  if (holes.empty() || std::size_t(map.width()) * std::size_t(map.height()) != holes.size()) {
    return 0;
  }
  const QRgb colour = hole_colour().rgb();
  std::int64_t marked = 0;
  for (int y = 0; y < map.height(); ++y) {
    auto* line = reinterpret_cast<QRgb*>(map.scanLine(y));
    const std::uint8_t* row = holes.data() + std::size_t(y) * std::size_t(map.width());
    for (int x = 0; x < map.width(); ++x) {
      if (!row[x]) continue;
      line[x] = colour;
      ++marked;
    }
  }
  return marked;
}

}  // namespace oflab
