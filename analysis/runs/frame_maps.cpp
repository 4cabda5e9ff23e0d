// Difference and hole maps of a frame (see analysis/runs/frame_maps.h).
#include "runs/frame_maps.h"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

#include "scene/scene_animator.h"

namespace oflab {

std::vector<std::uint8_t> channel_difference_map(const Image& shown, const Image& exact) {
  if (shown.width() != exact.width() || shown.height() != exact.height()) {
    throw std::invalid_argument("channel_difference_map: the two images differ in size");
  }
  std::vector<std::uint8_t> map(shown.pixel_count());
  for (std::size_t k = 0; k < map.size(); ++k) {
    const Pixel a = shown.pixels()[k], b = exact.pixels()[k];
    map[k] = static_cast<std::uint8_t>(std::max(
        {std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b), std::abs(a.a - b.a)}));
  }
  return map;
}

const std::vector<int>* reprojection_sources(const Animator& animator, const Image& exact) {
  // Only the scene animator reprojects by depth; its engine keeps the last reprojection's
  // source pixel of every pixel (-1: unreached), and nothing after a fresh render.
  const auto* scene = dynamic_cast<const SceneScriptAnimator*>(&animator);
  if (!scene) return nullptr;
  const std::vector<int>& source = scene->renderer().reprojection_sources();
  if (source.empty() || exact.empty() || source.size() != exact.pixels().size()) return nullptr;
  return &source;
}

std::vector<std::uint8_t> reprojection_hole_map(const Animator& animator, const Image& exact) {
  const std::vector<int>* source = reprojection_sources(animator, exact);
  if (!source) return {};
  std::vector<std::uint8_t> holes(source->size(), 0);
  const std::vector<Pixel>& seen = exact.pixels();
  for (std::size_t k = 0; k < source->size(); ++k) holes[k] = (*source)[k] < 0 && seen[k].a > 0;
  return holes;
}

}  // namespace oflab
