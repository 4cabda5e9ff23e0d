#include "adapters/hole_map.h"

#include "scene/scene_animator.h"

namespace oflab {

QColor hole_colour() { return QColor(255, 0, 255); }

std::vector<char> reprojection_holes(const Animator& animator, const Image& exact) {
  // Only the scene animator reprojects by depth; its engine keeps the last reprojection's
  // source pixel of every pixel (-1: unreached), and nothing after a fresh render.
  const auto* scene = dynamic_cast<const SceneScriptAnimator*>(&animator);
  if (!scene) return {};
  const std::vector<int>& source = scene->renderer().reprojection_sources();
  if (source.empty() || exact.empty() || source.size() != exact.pixels().size()) return {};
  std::vector<char> holes(source.size(), 0);
  const std::vector<Pixel>& seen = exact.pixels();
  for (std::size_t k = 0; k < source.size(); ++k) holes[k] = source[k] < 0 && seen[k].a > 0;
  return holes;
}

std::int64_t mark_holes(QImage& map, const std::vector<char>& holes) {
  if (holes.empty() || std::size_t(map.width()) * std::size_t(map.height()) != holes.size()) {
    return 0;
  }
  const QRgb colour = hole_colour().rgb();
  std::int64_t marked = 0;
  for (int y = 0; y < map.height(); ++y) {
    auto* line = reinterpret_cast<QRgb*>(map.scanLine(y));
    const char* row = holes.data() + std::size_t(y) * std::size_t(map.width());
    for (int x = 0; x < map.width(); ++x) {
      if (!row[x]) continue;
      line[x] = colour;
      ++marked;
    }
  }
  return marked;
}

}  // namespace oflab
