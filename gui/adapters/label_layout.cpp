#include "adapters/label_layout.h"

#include <QStringList>
#include <algorithm>
#include <cmath>
#include <utility>

#include "adapters/paint_helpers.h"

namespace oflab {
namespace {

QRectF clamped(QRectF box, const QRectF& area) {
  box.moveLeft(std::max(area.left(), std::min(box.left(), area.right() - box.width())));
  box.moveTop(std::max(area.top(), std::min(box.top(), area.bottom() - box.height())));
  return box;
}

double overlap(const QRectF& box, const std::vector<QRectF>& taken) {
  double area = 0.0;
  for (const QRectF& t : taken) {
    const QRectF both = box.intersected(t);
    area += both.width() * both.height();
  }
  return area;
}

// `polygon` clipped to the half plane where `inside` holds (one step of Sutherland-Hodgman);
// `cross` gives where the edge from a to b meets the half plane's border.
template <typename Inside, typename Cross>
QPolygonF clip(const QPolygonF& polygon, Inside inside, Cross cross) {
  QPolygonF out;
  for (int k = 0; k < polygon.size(); ++k) {
    const QPointF a = polygon[k], b = polygon[(k + 1) % polygon.size()];
    if (inside(a)) out << a;
    if (inside(a) != inside(b)) out << cross(a, b);
  }
  return out;
}

// The places a label of `size` may take next to `anchor`, most wanted first.
std::vector<QRectF> candidates(const QSizeF& size, const QPointF& anchor, double gap) {
  const double w = size.width(), h = size.height();
  const QPointF corners[4] = {
      {anchor.x() + gap, anchor.y() - gap - h},  // right, above
      {anchor.x() + gap, anchor.y() + gap},      // right, below
      {anchor.x() - gap - w, anchor.y() - gap - h},
      {anchor.x() - gap - w, anchor.y() + gap},
  };
  std::vector<QRectF> all;
  for (int ring = 0; ring <= 6; ++ring) {
    for (const QPointF& c : corners) {
      const bool above = c.y() < anchor.y();
      const double shift = ring * (h + gap) * (above ? -1.0 : 1.0);
      all.emplace_back(QPointF(c.x(), c.y() + shift), size);
    }
  }
  // Then further out, sideways and along the diagonals too: the way past a picture or a
  // text may lie beside the point rather than above or below it.
  const double step = h + gap;
  for (int ring = 1; ring <= 16; ++ring) {
    for (int dx = -1; dx <= 1; ++dx) {
      for (int dy = -1; dy <= 1; ++dy) {
        if (dx == 0 && dy == 0) continue;
        const QPointF& c = corners[(dx < 0 ? 2 : 0) + (dy > 0 ? 1 : 0)];
        all.emplace_back(QPointF(c.x() + dx * ring * step, c.y() + dy * ring * step), size);
      }
    }
  }
  return all;
}

}  // namespace

double covered_area(const QRectF& box, const QPolygonF& outline) {
  QPolygonF p = outline;
  const auto at_x = [](double x) {
    return [x](QPointF a, QPointF b) {
      return QPointF(x, a.y() + (b.y() - a.y()) * (x - a.x()) / (b.x() - a.x()));
    };
  };
  const auto at_y = [](double y) {
    return [y](QPointF a, QPointF b) {
      return QPointF(a.x() + (b.x() - a.x()) * (y - a.y()) / (b.y() - a.y()), y);
    };
  };
  const double l = box.left(), r = box.right(), t = box.top(), b = box.bottom();
  p = clip(
      p, [l](QPointF q) { return q.x() >= l; }, at_x(l));
  p = clip(
      p, [r](QPointF q) { return q.x() <= r; }, at_x(r));
  p = clip(
      p, [t](QPointF q) { return q.y() >= t; }, at_y(t));
  p = clip(
      p, [b](QPointF q) { return q.y() <= b; }, at_y(b));
  return p.size() < 3 ? 0.0 : polygon_area(p);
}

std::vector<QRectF> place_labels(const std::vector<QSizeF>& sizes,
                                 const std::vector<QPointF>& anchors, const QRectF& area,
                                 std::vector<QRectF> taken, double gap,
                                 const std::vector<QPolygonF>& avoid) {
  std::vector<QRectF> boxes;
  for (size_t k = 0; k < sizes.size() && k < anchors.size(); ++k) {
    QRectF best;
    std::pair<double, double> least{-1.0, 0.0};  // over texts, then over content
    for (const QRectF& candidate : candidates(sizes[k], anchors[k], gap)) {
      const QRectF box = clamped(candidate, area);
      // Touching is not covering: a pixel of margin each side.
      const QRectF inner = box.adjusted(1, 1, -1, -1);
      std::pair<double, double> covered{overlap(inner, taken), 0.0};
      for (const QPolygonF& outline : avoid) covered.second += covered_area(inner, outline);
      if (least.first < 0.0 || covered < least) {
        best = box;
        least = covered;
      }
      if (covered.first == 0.0 && covered.second == 0.0) break;
    }
    boxes.push_back(best);
    // Labels keep a gap between them: two short labels side by side would read as one word.
    taken.push_back(best.adjusted(-gap, -gap, gap, gap));
  }
  return boxes;
}

std::vector<QString> wrap_text(const QString& text, const QFontMetricsF& metrics, double width) {
  std::vector<QString> lines;
  for (const QString& paragraph : text.split(QLatin1Char('\n'))) {
    QString line;
    for (const QString& word : paragraph.split(QLatin1Char(' '), Qt::SkipEmptyParts)) {
      const QString longer = line.isEmpty() ? word : line + QLatin1Char(' ') + word;
      if (!line.isEmpty() && metrics.horizontalAdvance(longer) > width) {
        lines.push_back(line);
        line = word;
      } else {
        line = longer;
      }
    }
    lines.push_back(line);
  }
  return lines;
}

}  // namespace oflab
