#include "views/panel_layout.h"

#include <QPolygonF>
#include <algorithm>
#include <cmath>

namespace oflab {

std::vector<PanelCell> panel_row(const QRectF& row, int columns, double gap, double title_px,
                                 double caption_px) {
  std::vector<PanelCell> cells;
  const double width = (row.width() - gap * (columns - 1)) / columns;
  for (int c = 0; c < columns; ++c) {
    const double left = row.left() + c * (width + gap);
    PanelCell cell;
    cell.title = QRectF(left, row.top(), width, title_px);
    cell.caption = QRectF(left, row.bottom() - caption_px, width, caption_px);
    cell.image = QRectF(left, cell.title.bottom(), width,
                        std::max(1.0, cell.caption.top() - cell.title.bottom()));
    cells.push_back(cell);
  }
  return cells;
}

QStringList wrapped_caption(const QString& text, const QFontMetrics& metrics, double width) {
  if (metrics.horizontalAdvance(text) <= width) return {text};
  struct Break {
    QString separator;
    int head_keeps;  // characters of the separator ending the first line
    int tail_skips;  // characters of the separator not starting the next line
  };
  const Break breaks[] = {{QStringLiteral(" \u00b7 "), 0, 3},
                          {QStringLiteral(" ("), 0, 1},
                          {QStringLiteral(", "), 1, 2}};
  for (const Break& b : breaks) {
    for (int at = text.lastIndexOf(b.separator); at > 0;
         at = text.lastIndexOf(b.separator, at - 1)) {
      const QString head = text.left(at + b.head_keeps);
      if (metrics.horizontalAdvance(head) > width) continue;
      return QStringList{head} + wrapped_caption(text.mid(at + b.tail_skips), metrics, width);
    }
  }
  return {text};
}

double hull_share(const std::vector<QPointF>& points, const QRectF& picture) {
  if (points.size() < 3 || picture.isEmpty()) return 0.0;
  // Andrew's monotone chain: the lower and the upper hull, counter-clockwise.
  std::vector<QPointF> sorted = points;
  std::sort(sorted.begin(), sorted.end(), [](const QPointF& a, const QPointF& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  const auto cross = [](const QPointF& o, const QPointF& a, const QPointF& b) {
    return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
  };
  std::vector<QPointF> hull(2 * sorted.size());
  size_t k = 0;
  for (size_t i = 0; i < sorted.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], sorted[i]) <= 0) --k;
    hull[k++] = sorted[i];
  }
  for (size_t i = sorted.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], sorted[i]) <= 0) --k;
    hull[k++] = sorted[i];
  }
  hull.resize(k > 0 ? k - 1 : 0);
  const QPolygonF inside =
      QPolygonF(QVector<QPointF>(hull.begin(), hull.end())).intersected(QPolygonF(picture));
  double twice_area = 0.0;
  for (int i = 0; i < inside.size(); ++i) {
    const QPointF& a = inside[i];
    const QPointF& b = inside[(i + 1) % inside.size()];
    twice_area += a.x() * b.y() - b.x() * a.y();
  }
  return std::abs(twice_area) / 2.0 / (picture.width() * picture.height());
}

QRectF frame_rect(const std::optional<BoundingBox>& box) {
  if (!box) return QRectF();
  return QRectF(QPointF(box->x_min, box->y_min), QPointF(box->x_max, box->y_max));
}

std::optional<BoundingBox> frame_box(const QRectF& rect) {
  if (rect.isEmpty()) return std::nullopt;
  return BoundingBox{rect.left(), rect.top(), rect.right(), rect.bottom()};
}

QRectF panel_frame(const QRectF& content, const QSizeF& camera_size, double aspect, double zoom) {
  return frame_rect(
      panel_frame(frame_box(content), camera_size.width(), camera_size.height(), aspect, zoom));
}

QTransform frame_to_panel(const QRectF& frame, const QRectF& target) {
  const double scale = target.width() / frame.width();
  return QTransform(scale, 0, 0, scale, target.left() - frame.left() * scale,
                    target.top() - frame.top() * scale);
}

QRectF script_image_bounds(const MotionScript& script, double near) {
  return frame_rect(bounds_around(script_frame_bounds(script, near), 0, -1));
}

QRectF scene_image_bounds(const Scene& scene, const ViewerScript& walk, double near) {
  return frame_rect(bounds_around(scene_frame_bounds(scene, walk, near), 0, -1));
}

}  // namespace oflab
