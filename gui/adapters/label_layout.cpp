#include "adapters/label_layout.h"

#include <QStringList>
#include <utility>

#include "display/label_layout.h"

namespace oflab {
namespace {

LabelBox box_of(const QRectF& r) { return {r.x(), r.y(), r.width(), r.height()}; }
QRectF rect_of(const LabelBox& b) { return QRectF(b.x, b.y, b.width, b.height); }

std::vector<Vec2> points_of(const QPolygonF& polygon) {
  std::vector<Vec2> points;
  for (const QPointF& p : polygon) points.emplace_back(p.x(), p.y());
  return points;
}

}  // namespace

double covered_area(const QRectF& box, const QPolygonF& outline) {
  return covered_area(box_of(box), points_of(outline));
}

std::vector<QRectF> place_labels(const std::vector<QSizeF>& sizes,
                                 const std::vector<QPointF>& anchors, const QRectF& area,
                                 std::vector<QRectF> taken, double gap,
                                 const std::vector<QPolygonF>& avoid) {
  std::vector<Vec2> plain_sizes, plain_anchors;
  for (const QSizeF& s : sizes) plain_sizes.emplace_back(s.width(), s.height());
  for (const QPointF& a : anchors) plain_anchors.emplace_back(a.x(), a.y());
  std::vector<LabelBox> plain_taken;
  for (const QRectF& t : taken) plain_taken.push_back(box_of(t));
  std::vector<std::vector<Vec2>> plain_avoid;
  for (const QPolygonF& outline : avoid) plain_avoid.push_back(points_of(outline));
  std::vector<QRectF> boxes;
  for (const LabelBox& b : place_labels(plain_sizes, plain_anchors, box_of(area),
                                        std::move(plain_taken), gap, plain_avoid))
    boxes.push_back(rect_of(b));
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
