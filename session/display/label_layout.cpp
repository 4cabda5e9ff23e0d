#include "display/label_layout.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "engine/affine_fit.h"

namespace oflab {
namespace {

LabelBox clamped(LabelBox box, const LabelBox& area) {
  box.x = std::max(area.x, std::min(box.x, area.right() - box.width));
  box.y = std::max(area.y, std::min(box.y, area.bottom() - box.height));
  return box;
}

// Area of the intersection of two boxes (0 when they do not meet).
double shared_area(const LabelBox& a, const LabelBox& b) {
  const double w = std::min(a.right(), b.right()) - std::max(a.x, b.x);
  const double h = std::min(a.bottom(), b.bottom()) - std::max(a.y, b.y);
  return w > 0.0 && h > 0.0 ? w * h : 0.0;
}

double overlap(const LabelBox& box, const std::vector<LabelBox>& taken) {
  double area = 0.0;
  for (const LabelBox& t : taken) area += shared_area(box, t);
  return area;
}

// `polygon` clipped to the half plane where `inside` holds (one step of Sutherland-Hodgman);
// `cross` gives where the edge from a to b meets the half plane's border.
template <typename Inside, typename Cross>
std::vector<Vec2> clip(const std::vector<Vec2>& polygon, Inside inside, Cross cross) {
  std::vector<Vec2> out;
  for (size_t k = 0; k < polygon.size(); ++k) {
    const Vec2 a = polygon[k], b = polygon[(k + 1) % polygon.size()];
    if (inside(a)) out.push_back(a);
    if (inside(a) != inside(b)) out.push_back(cross(a, b));
  }
  return out;
}

// The places a label of `size` may take next to `anchor`, most wanted first.
std::vector<LabelBox> candidates(const Vec2& size, const Vec2& anchor, double gap) {
  const double w = size.x, h = size.y;
  const Vec2 corners[4] = {
      {anchor.x + gap, anchor.y - gap - h},  // right, above
      {anchor.x + gap, anchor.y + gap},      // right, below
      {anchor.x - gap - w, anchor.y - gap - h},
      {anchor.x - gap - w, anchor.y + gap},
  };
  std::vector<LabelBox> all;
  for (int ring = 0; ring <= 6; ++ring) {
    for (const Vec2& c : corners) {
      const bool above = c.y < anchor.y;
      const double shift = ring * (h + gap) * (above ? -1.0 : 1.0);
      all.push_back({c.x, c.y + shift, w, h});
    }
  }
  // Then further out, sideways and along the diagonals too: the way past a picture or a
  // text may lie beside the point rather than above or below it.
  const double step = h + gap;
  for (int ring = 1; ring <= 16; ++ring) {
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        if (dx == 0 && dy == 0) continue;
        const Vec2& c = corners[(dx < 0 ? 2 : 0) + (dy > 0 ? 1 : 0)];
        all.push_back({c.x + dx * ring * step, c.y + dy * ring * step, w, h});
      }
    }
  }
  return all;
}

}  // namespace

double covered_area(const LabelBox& box, const std::vector<Vec2>& outline) {
  const auto at_x = [](double x) {
    return [x](Vec2 a, Vec2 b) { return Vec2(x, a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x)); };
  };
  const auto at_y = [](double y) {
    return [y](Vec2 a, Vec2 b) { return Vec2(a.x + (b.x - a.x) * (y - a.y) / (b.y - a.y), y); };
  };
  const double l = box.x, r = box.right(), t = box.y, b = box.bottom();
  std::vector<Vec2> p = outline;
  p = clip(
      p, [l](Vec2 q) { return q.x >= l; }, at_x(l));
  p = clip(
      p, [r](Vec2 q) { return q.x <= r; }, at_x(r));
  p = clip(
      p, [t](Vec2 q) { return q.y >= t; }, at_y(t));
  p = clip(
      p, [b](Vec2 q) { return q.y <= b; }, at_y(b));
  return p.size() < 3 ? 0.0 : std::abs(signed_area2(p)) / 2.0;
}

std::vector<LabelBox> place_labels(const std::vector<Vec2>& sizes, const std::vector<Vec2>& anchors,
                                   const LabelBox& area, std::vector<LabelBox> taken, double gap,
                                   const std::vector<std::vector<Vec2>>& avoid) {
  std::vector<LabelBox> boxes;
  for (size_t k = 0; k < sizes.size() && k < anchors.size(); ++k) {
    LabelBox best;
    std::pair<double, double> least{-1.0, 0.0};  // over texts, then over content
    for (const LabelBox& candidate : candidates(sizes[k], anchors[k], gap)) {
      const LabelBox box = clamped(candidate, area);
      // Touching is not covering: a pixel of margin each side.
      const LabelBox inner = box.grown(-1.0);
      std::pair<double, double> covered{overlap(inner, taken), 0.0};
      for (const std::vector<Vec2>& outline : avoid) covered.second += covered_area(inner, outline);
      if (least.first < 0.0 || covered < least) {
        best = box;
        least = covered;
      }
      if (covered.first == 0.0 && covered.second == 0.0) break;
    }
    boxes.push_back(best);
    // Labels keep a gap between them: two short labels side by side would read as one word.
    taken.push_back(best.grown(gap));
  }
  return boxes;
}

}  // namespace oflab
