#include "web_slices.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "frame_pixels.h"

namespace oflab {
namespace {

using json = nlohmann::json;

json number_or_null(double value) { return std::isfinite(value) ? json(value) : json(nullptr); }

json diagram_json(const SliceDiagram& d) {
  json slices = json::array();
  for (const Slice& s : d.slices)
    slices.push_back({{"near", s.near}, {"far", number_or_null(s.far)}});
  json planes = json::array();
  for (const DiagramPlane& p : d.planes) {
    planes.push_back({{"depth", p.depth}, {"left", p.left}, {"right", p.right}});
  }
  return {{"slices", slices},
          {"asymptote", number_or_null(d.asymptote)},
          {"asymptote_label", asymptote_label(d)},
          {"title", slice_diagram_title(d)},
          {"max_depth", d.max_depth},
          {"ticks", d.ticks},
          {"half_width", kDiagramHalfWidth},
          {"planes", planes},
          {"focal_px", d.focal_px},
          {"epsilon_px", d.epsilon_px},
          {"speed", d.speed}};
}

}  // namespace

std::string WebSlices::update(double epsilon_px, double speed, int window_frame) {
  if (!cut_ || epsilon_px != walk_.epsilon_px() || speed != walk_.speed()) {
    walk_.set_slicing(epsilon_px, speed);
    cut_ = true;
  }
  walk_.go_to(window_frame);
  const Image& shifted = walk_.shifted_image();
  const Image& exact = walk_.exact_image();
  const Image& sized = shifted.empty() ? exact : shifted;
  json out;
  out["problem"] = walk_.problem();
  out["slicing_problem"] = walk_.slicing_problem();
  out["exact_problem"] = walk_.exact_problem();
  out["exact_title"] = SliceWalk::kExactTitle;
  out["frame"] = walk_.frame();
  out["frame_count"] = walk_.frame_count();
  out["caption"] = walk_.caption(window_frame);
  out["width"] = sized.width();
  out["height"] = sized.height();
  out["diagram"] = diagram_json(walk_.diagram());
  return out.dump();
}

const std::vector<std::uint8_t>& WebSlices::pixels(bool exact, int width, int height) {
  const Image& frame = exact ? walk_.exact_image() : walk_.shifted_image();
  if (frame.empty()) {
    pixels_.clear();
    return pixels_;
  }
  width = std::clamp(width, 1, 4096);
  height = std::clamp(height, 1, 4096);
  const std::uint8_t background[3] = {17, 19, 21};
  flatten_into(frame, display_sampling(frame.width(), frame.height(), width, height), background,
               pixels_);
  return pixels_;
}

}  // namespace oflab
