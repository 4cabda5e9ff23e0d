#include "adapters/label_layout.h"

#include <QStringList>
#include <algorithm>

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
  return all;
}

}  // namespace

std::vector<QRectF> place_labels(const std::vector<QSizeF>& sizes,
                                 const std::vector<QPointF>& anchors, const QRectF& area,
                                 std::vector<QRectF> taken, double gap) {
  std::vector<QRectF> boxes;
  for (size_t k = 0; k < sizes.size() && k < anchors.size(); ++k) {
    QRectF best;
    double least = -1.0;
    for (const QRectF& candidate : candidates(sizes[k], anchors[k], gap)) {
      const QRectF box = clamped(candidate, area);
      // Touching is not covering: a pixel of margin each side.
      const double covered = overlap(box.adjusted(1, 1, -1, -1), taken);
      if (least < 0.0 || covered < least) {
        best = box;
        least = covered;
      }
      if (covered == 0.0) break;
    }
    boxes.push_back(best);
    taken.push_back(best);
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
