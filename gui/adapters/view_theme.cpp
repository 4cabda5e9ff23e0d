#include "adapters/view_theme.h"

#include <algorithm>
#include <cmath>

namespace oflab {

double presentation_scale(int width, int height) {
  const double scale = std::min(width / 1920.0, height / 1080.0);
  return std::clamp(scale, kPresentationMinScale, 1.0);
}

int presentation_min_text_px(double scale) {
  return int(std::floor(kPresentationMinTextPx * scale + 1e-9));
}

ViewTheme view_theme(bool presentation, double scale) {
  ViewTheme t;
  t.presentation = presentation;
  if (presentation) {
    const auto px = [scale](int size) { return int(std::lround(size * scale)); };
    t.scale = scale;
    t.background = {0.97, 0.97, 0.95};
    t.text = {0.05, 0.05, 0.05};
    t.outline = {0.0, 0.0, 0.0};
    t.image_background = t.background;
    t.streamline = {0.25, 0.25, 0.25};
    t.tile_background = {1.0, 1.0, 1.0};
    t.muted_background = {0.86, 0.86, 0.86};
    t.muted = {0.62, 0.62, 0.62};
    t.font_size = px(22);
    t.label_size = px(20);
    t.control_font_px = px(20);
    t.line_width = 2.5;
  } else {
    t.background = {0.09, 0.10, 0.12};
    t.text = {0.92, 0.92, 0.92};
    t.outline = {1.0, 1.0, 1.0};
    t.image_background = {0.46, 0.48, 0.51};
    t.streamline = {0.80, 0.80, 0.80};
    t.tile_background = {0.13, 0.15, 0.18};
    t.muted_background = {0.20, 0.20, 0.20};
    t.muted = {0.42, 0.42, 0.42};
    t.font_size = 14;
    t.label_size = 12;
    t.control_font_px = 0;
    t.line_width = 1.5;
  }
  return t;
}

}  // namespace oflab
