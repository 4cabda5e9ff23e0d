#include "views/explorer_pictures.h"

#include <QFontMetrics>
#include <QPainter>
#include <QPainterPath>
#include <QString>
#include <algorithm>
#include <cmath>
#include <vector>

#include "adapters/paint_helpers.h"
#include "flow/plane.h"

namespace oflab {
namespace {

constexpr int kGridLines = 9;  // lines per direction: 8 x 8 cells
// The futures' pictures show when the canvas is at least this many label heights tall (the
// chart under them keeps 0.45 of it, over kChartPlotLines + 3.8 labels).
constexpr double kPicturesLines = 14.0;
constexpr double kChartPlotLines = 2.5;
constexpr int kLineSamples = 33;  // points per grid line

QColor solution_colour(int index) { return to_qcolor(policy_colour(index)); }

QImage blank(const QSize& wanted, const ViewTheme& theme) {
  QImage image(wanted.expandedTo(QSize(1, 1)), QImage::Format_RGB32);
  image.fill(to_qcolor(theme.background));
  return image;
}

void set_font(QPainter& painter, int pixels, bool bold = false) {
  QFont font = painter.font();
  font.setPixelSize(pixels);
  font.setBold(bold);
  painter.setFont(font);
}

// An arrow from `from` to `to` (screen pixels) with a head `head` pixels long.
void draw_arrow(QPainter& painter, const QPointF& from, const QPointF& to, double head) {
  painter.drawLine(from, to);
  const QPointF d = to - from;
  const double length = std::hypot(d.x(), d.y());
  if (length < 1e-6) return;
  const QPointF u = d / length, n(-u.y(), u.x());
  const double h = std::min(head, 0.5 * length);
  painter.drawLine(to, to - h * u + 0.5 * h * n);
  painter.drawLine(to, to - h * u - 0.5 * h * n);
}

// The texture rectangle's corners in centred pixels: the middle half of the image.
QRectF texture_rect(const Camera& camera) {
  return QRectF(-0.25 * camera.width, -0.25 * camera.height, 0.5 * camera.width,
                0.5 * camera.height);
}

// Fills the pixels of `region` (canvas pixels) with the texture carried by `deformation`:
// each pixel's centred position (`to_screen`'s inverse) taken back through the inverse
// homography, nearest texel; `empty` where no texel lands.
void warp_texture(QImage& image, const QImage& texture, const Mat3& deformation,
                  const QTransform& to_screen, const QRectF& region, const QRectF& rect,
                  QRgb empty) {
  const Mat3 back = glm::inverse(deformation);
  const QTransform to_centred = to_screen.inverted();
  const QImage source = texture.convertToFormat(QImage::Format_RGB32);
  const int top = std::max(0, int(region.top())),
            bottom = std::min(image.height(), int(std::ceil(region.bottom())));
  const int left = std::max(0, int(region.left())),
            right = std::min(image.width(), int(std::ceil(region.right())));
  for (int y = top; y < bottom; ++y) {
    auto* line = reinterpret_cast<QRgb*>(image.scanLine(y));
    for (int x = left; x < right; ++x) {
      const QPointF c = to_centred.map(QPointF(x + 0.5, y + 0.5));
      const Vec3 h = back * Vec3(c.x(), c.y(), 1.0);
      QRgb colour = empty;
      if (h.z > 0.0) {
        const double u = (h.x / h.z - rect.left()) / rect.width();
        const double v = (h.y / h.z - rect.top()) / rect.height();
        if (u >= 0.0 && u < 1.0 && v >= 0.0 && v < 1.0 && !source.isNull()) {
          const int tx = std::min(source.width() - 1, int(u * source.width()));
          const int ty = std::min(source.height() - 1, int(v * source.height()));
          colour = reinterpret_cast<const QRgb*>(source.constScanLine(ty))[tx];
        }
      }
      line[x] = colour;
    }
  }
}

QString deformation_caption() {
  return QObject::tr("After %1 s of this flow (dashed: the start)").arg(kDeformationSeconds);
}

// The texture rectangle's corners carried by `deformation` (centred pixels), in order; false
// when one of them goes behind (w <= 0), the quad then not a picture of the rectangle.
bool deformed_quad(const Mat3& deformation, const QRectF& rect, QPolygonF* quad) {
  for (const QPointF& c :
       {rect.topLeft(), rect.topRight(), rect.bottomRight(), rect.bottomLeft()}) {
    const Vec3 h = deformation * Vec3(c.x(), c.y(), 1.0);
    if (!(h.z > 0.0)) return false;
    *quad << QPointF(h.x / h.z, h.y / h.z);
  }
  return true;
}

}  // namespace

DeformationFraming explorer_deformation_framing(const Mat3& deformation, const Camera& camera,
                                                const QSize& size, const ViewTheme& theme) {
  constexpr double kMargin = 6.0, kContentMargin = 0.03;
  const QSize canvas = size.expandedTo(QSize(1, 1));
  QFont bold;
  bold.setPixelSize(theme.label_size);
  bold.setBold(true);
  // As tall as the caption's wrapped lines need at this width, and a little room.
  const QRect wrapped = QFontMetrics(bold).boundingRect(
      QRect(0, 0, std::max(1, int(canvas.width() - 2 * kMargin)), 100000), Qt::TextWordWrap,
      deformation_caption());
  DeformationFraming framing;
  framing.caption = wrapped.height() + 0.6 * theme.label_size;
  framing.picture = QRectF(kMargin, framing.caption, canvas.width() - 2 * kMargin,
                           canvas.height() - framing.caption - kMargin);
  // What is framed: the texture rectangle before and after, grown a little, within the image.
  const QRectF image(-0.5 * camera.width, -0.5 * camera.height, camera.width, camera.height);
  const QRectF rect = texture_rect(camera);
  QPolygonF quad;
  QRectF content = image;
  if (deformed_quad(deformation, rect, &quad)) {
    const QRectF both = rect.united(quad.boundingRect());
    content = both.adjusted(-kContentMargin * both.width(), -kContentMargin * both.height(),
                            kContentMargin * both.width(), kContentMargin * both.height())
                  .intersected(image);
    if (content.isEmpty()) content = image;
  }
  framing.scale = std::min(framing.picture.width() / content.width(),
                           framing.picture.height() / content.height());
  if (!(framing.scale > 0.0)) return framing;
  framing.to_screen.translate(framing.picture.center().x(), framing.picture.center().y());
  framing.to_screen.scale(framing.scale, framing.scale);
  framing.to_screen.translate(-content.center().x(), -content.center().y());
  framing.frame = framing.to_screen.mapRect(image);
  return framing;
}

double explorer_deformation_fill(const Mat3& deformation, const Camera& camera, const QSize& size,
                                 const ViewTheme& theme) {
  const DeformationFraming framing = explorer_deformation_framing(deformation, camera, size, theme);
  QPolygonF quad;
  if (!(framing.scale > 0.0) || !deformed_quad(deformation, texture_rect(camera), &quad))
    return 0.0;
  const QPolygonF seen = framing.to_screen.map(quad).intersected(
      QPolygonF(framing.frame.intersected(framing.picture)));
  return polygon_area(seen) / (framing.picture.width() * framing.picture.height());
}

QImage paint_explorer_deformation(const QImage& texture, const Mat3& deformation,
                                  const Camera& camera, const QSize& size, const ViewTheme& theme) {
  QImage image = blank(size, theme);
  const DeformationFraming framing = explorer_deformation_framing(deformation, camera, size, theme);
  if (!(framing.scale > 0.0)) return image;
  const QRectF shown = framing.frame.intersected(framing.picture);
  const QRectF rect = texture_rect(camera);
  warp_texture(image, texture, deformation, framing.to_screen, shown, rect,
               to_qcolor(theme.image_background).rgb());
  QPainter painter(&image);
  painter.setRenderHint(QPainter::Antialiasing, true);
  painter.setClipRect(shown);
  painter.setPen(QPen(to_qcolor(theme.muted), 1.0, Qt::DashLine));
  painter.drawRect(framing.to_screen.mapRect(rect));
  painter.setPen(QPen(to_qcolor(order_colour(1)), theme.line_width + 0.5));
  for (int direction = 0; direction < 2; ++direction) {
    for (int k = 0; k < kGridLines; ++k) {
      QPolygonF line;
      for (int s = 0; s < kLineSamples; ++s) {
        const double a = double(k) / (kGridLines - 1), b = double(s) / (kLineSamples - 1);
        const Vec2 p = direction == 0
                           ? Vec2(rect.left() + a * rect.width(), rect.top() + b * rect.height())
                           : Vec2(rect.left() + b * rect.width(), rect.top() + a * rect.height());
        const Vec2 moved = apply_homography(deformation, p);
        line << framing.to_screen.map(QPointF(moved.x, moved.y));
      }
      painter.drawPolyline(line);
    }
  }
  // The image's border where it is in the picture (zoomed in, it may lie beyond).
  const double pen = theme.line_width;
  painter.setClipRect(framing.picture.adjusted(-pen, -pen, pen, pen));
  painter.setPen(QPen(to_qcolor(theme.outline), pen));
  painter.drawRect(framing.frame);
  painter.setClipping(false);
  painter.setPen(to_qcolor(theme.text));
  set_font(painter, theme.label_size, true);
  painter.drawText(QRectF(framing.picture.left(), 0, framing.picture.width(), framing.caption),
                   Qt::AlignLeft | Qt::AlignVCenter | Qt::TextWordWrap, deformation_caption());
  return image;
}

namespace {

QPointF view_of(const Vec3& p) {
  const Vec2 q = explorer_view_of(p);
  return QPointF(q.x, q.y);
}

const QString kLegend[4] = {QObject::tr("dot: the eye"), QObject::tr("N normal"),
                            QObject::tr("V/d velocity"), QObject::tr("Omega spin")};

// The legend's lines: 1 when it fits the width, else 2 (two items a line).
int legend_lines(QPainter& painter, double width, const ViewTheme& theme) {
  double needed = 0.0;
  for (const QString& part : kLegend) {
    needed += painter.fontMetrics().horizontalAdvance(part) + theme.label_size;
  }
  return needed <= width - 12 ? 1 : 2;
}

void paint_legend(QPainter& painter, const QRectF& band, int lines, const ViewTheme& theme) {
  const QColor colours[4] = {to_qcolor(theme.text), to_qcolor(theme.text),
                             to_qcolor(okabe_ito::kVermillion), to_qcolor(okabe_ito::kBlue)};
  const double line_height = band.height() / lines;
  double x = band.left();
  for (int k = 0; k < 4; ++k) {
    const int line = lines == 1 ? 0 : k / 2;
    if (lines == 2 && k == 2) x = band.left();
    painter.setPen(colours[k]);
    painter.drawText(QRectF(x, band.top() + line * line_height, band.right() - x, line_height),
                     Qt::AlignLeft | Qt::AlignVCenter, kLegend[k]);
    x += painter.fontMetrics().horizontalAdvance(kLegend[k]) + theme.label_size;
  }
}

// The sketch's points of a solution (session/basis/basis_explorer.h explorer_sketch): the
// plane's four corners, its centre, the tips of N, V/d and Omega.
std::vector<QPointF> sketch_of(const PlanarMotionSolution& s, double arrow) {
  const SolutionSketch k = explorer_sketch(s, arrow);
  std::vector<QPointF> points;
  for (const Vec2& c : k.corners) points.emplace_back(c.x, c.y);
  for (const Vec2& p : {k.centre, k.normal_tip, k.velocity_tip, k.spin_tip}) {
    points.emplace_back(p.x, p.y);
  }
  return points;
}

// One solution's sketch (points of sketch_of, mapped by to_cell) in the colour of solution
// `index`.
void paint_sketch(QPainter& painter, const std::vector<QPointF>& points, const QTransform& to_cell,
                  int index, const ViewTheme& theme) {
  const auto at = [&](size_t k) { return to_cell.map(points[k]); };
  const QPointF eye = to_cell.map(view_of(Vec3(0.0)));
  painter.setPen(QPen(to_qcolor(theme.muted), 1.0, Qt::DashLine));
  painter.drawLine(eye, at(4));
  QColor fill = solution_colour(index);
  fill.setAlpha(90);
  painter.setBrush(fill);
  painter.setPen(QPen(solution_colour(index), theme.line_width + 0.5));
  painter.drawPolygon(QPolygonF({at(0), at(1), at(2), at(3)}));
  painter.setBrush(Qt::NoBrush);
  const double head = 0.9 * theme.label_size;
  painter.setPen(QPen(to_qcolor(theme.text), theme.line_width + 0.5));
  draw_arrow(painter, at(4), at(5), head);
  painter.setPen(QPen(to_qcolor(okabe_ito::kVermillion), theme.line_width + 1.5));
  draw_arrow(painter, at(4), at(6), head);
  painter.setPen(QPen(to_qcolor(okabe_ito::kBlue), theme.line_width + 1.5));
  draw_arrow(painter, eye, at(7), head);
  painter.setBrush(to_qcolor(theme.text));
  painter.drawEllipse(eye, 4.0, 4.0);
  painter.setBrush(Qt::NoBrush);
}

}  // namespace

QImage paint_explorer_solutions(const ExplorerResult& result, const QSize& size,
                                const ViewTheme& theme) {
  QImage image = blank(size, theme);
  QPainter painter(&image);
  painter.setRenderHint(QPainter::Antialiasing, true);
  draw_explorer_solutions(painter, result, image.size(), theme);
  return image;
}

void draw_explorer_solutions(QPainter& painter, const ExplorerResult& result, const QSize& size,
                             const ViewTheme& theme) {
  const QRect image(QPoint(0, 0), size);
  const std::vector<PlanarMotionSolution>& solutions = result.inverse.solutions;
  const int count = std::max<int>(1, int(solutions.size()));
  set_font(painter, theme.label_size);
  const int lines = legend_lines(painter, image.width(), theme);
  const double title = 1.5 * theme.label_size, legend = 1.4 * theme.label_size * lines;
  const double w = double(image.width()) / count, cell_h = image.height() - title - legend;
  // One arrow scale for both: the longest of V/d and Omega is 0.8 units (d = 1); one drawing
  // scale for both: every point of every sketch fits its cell.
  const double arrow = explorer_arrow_scale(solutions);
  std::vector<std::vector<QPointF>> points(solutions.size());
  QRectF bounds(view_of(Vec3(0.0)), QSizeF(1e-9, 1e-9));  // the eye
  for (size_t i = 0; i < solutions.size(); ++i) {
    if (!solutions[i].normal_known) continue;
    points[i] = sketch_of(solutions[i], arrow);
    for (const QPointF& q : points[i]) bounds |= QRectF(q, QSizeF(1e-9, 1e-9));
  }
  const double scale = 0.9 * std::min((w - 12.0) / std::max(bounds.width(), 1e-9),
                                      cell_h / std::max(bounds.height(), 1e-9));
  const QString names[2] = {QObject::tr("Solution A"), QObject::tr("Solution B")};
  for (int i = 0; i < count; ++i) {
    const QRectF cell(i * w, title, w, cell_h);
    set_font(painter, theme.label_size, true);
    painter.setPen(i < int(solutions.size()) ? solution_colour(i) : to_qcolor(theme.text));
    painter.drawText(QRectF(i * w + 6, 0, w - 12, title), Qt::AlignLeft | Qt::AlignVCenter,
                     solutions.empty() ? QObject::tr("No motion") : names[i]);
    set_font(painter, theme.label_size);
    if (i >= int(solutions.size()) || !solutions[size_t(i)].normal_known) {
      painter.setPen(to_qcolor(theme.text));
      painter.drawText(cell.adjusted(6, 6, -6, -6), Qt::AlignCenter | Qt::TextWordWrap,
                       i < int(solutions.size()) && solutions[size_t(i)].omega == Vec3(0.0)
                           ? QObject::tr("No motion: any plane, at rest")
                           : QObject::tr("Any plane: a pure rotation says nothing about it"));
      continue;
    }
    QTransform to_cell;
    to_cell.translate(cell.center().x(), cell.center().y());
    to_cell.scale(scale, scale);
    to_cell.translate(-bounds.center().x(), -bounds.center().y());
    paint_sketch(painter, points[size_t(i)], to_cell, i, theme);
  }
  paint_legend(painter, QRectF(6, image.height() - legend, image.width() - 12, legend), lines,
               theme);
}

namespace {

// The corner whose two images are furthest apart at the last frame played.
int parting_corner(const FutureSeparation& f) {
  const auto& last = f.corner_images_px.back();
  int best = 0;
  for (int i = 1; i < 4; ++i) {
    if (glm::length(last[0][i] - last[1][i]) > glm::length(last[0][best] - last[1][best])) best = i;
  }
  return best;
}

// Solution `s`'s camera image at `frame`, in `area` under a title: the camera's frame on the
// image background, the texture on the quad its rectangle's corners reach (a homography
// of the texture's pixels, as the plane's image is), the other solution's quad dashed.
void paint_future_picture(QPainter& painter, const ExplorerResult& result, int frame, int s,
                          const QImage& texture, const Camera& camera, const QRectF& area,
                          const ViewTheme& theme) {
  const FutureSeparation& f = result.futures;
  const double title = 1.5 * theme.label_size;
  set_font(painter, theme.label_size, true);
  painter.setPen(solution_colour(s));
  painter.drawText(QRectF(area.left() + 4, area.top(), area.width() - 8, title),
                   Qt::AlignLeft | Qt::AlignVCenter,
                   QObject::tr("%1, frame %2").arg(s == 0 ? "A" : "B").arg(frame));
  set_font(painter, theme.label_size);
  const QRectF box = area.adjusted(4, title, -4, -2);
  const double scale = std::min(box.width() / camera.width, box.height() / camera.height);
  if (!(scale > 0.0)) return;
  const QRectF picture(box.center().x() - 0.5 * scale * camera.width,
                       box.top() + 0.5 * (box.height() - scale * camera.height),
                       scale * camera.width, scale * camera.height);
  QTransform to_picture;
  to_picture.translate(picture.center().x(), picture.center().y());
  to_picture.scale(scale, scale);
  painter.fillRect(picture, to_qcolor(theme.image_background));
  const auto quad = [&](int solution) {
    QPolygonF q;
    for (const Vec2& p : f.corner_images_px[size_t(frame)][size_t(solution)]) {
      q << to_picture.map(QPointF(p.x, p.y));
    }
    return q;
  };
  const QRectF rect = texture_rect(camera);
  QPolygonF source;
  for (const Vec2& c : result.corners) {
    source << QPointF((c.x - rect.left()) / rect.width() * texture.width(),
                      (c.y - rect.top()) / rect.height() * texture.height());
  }
  QTransform to_quad;
  painter.save();
  painter.setClipRect(picture);
  if (!texture.isNull() && QTransform::quadToQuad(source, quad(s), to_quad)) {
    painter.setTransform(to_quad, true);
    painter.drawImage(QPointF(0, 0), texture);
  }
  painter.restore();
  painter.setPen(QPen(solution_colour(1 - s), theme.line_width, Qt::DashLine));
  painter.drawPolygon(quad(1 - s));
  painter.setPen(QPen(solution_colour(s), theme.line_width + 0.5));
  painter.drawPolygon(quad(s));
  painter.setPen(QPen(to_qcolor(theme.outline), 1.0));
  painter.drawRect(picture);
}

void paint_tracks(QPainter& painter, const FutureSeparation& f, int frame, const QRectF& area,
                  const ViewTheme& theme) {
  const int corner = parting_corner(f);
  QRectF bounds;
  for (const auto& images : f.corner_images_px) {
    for (int s = 0; s < 2; ++s) {
      bounds |= QRectF(QPointF(images[s][corner].x, images[s][corner].y), QSizeF(1e-9, 1e-9));
    }
  }
  const double side = std::max({bounds.width(), bounds.height(), 1.0});
  const double scale = 0.85 * std::min(area.width(), area.height()) / side;
  QTransform to_area;
  to_area.translate(area.center().x(), area.center().y());
  to_area.scale(scale, scale);
  to_area.translate(-bounds.center().x(), -bounds.center().y());
  painter.setPen(QPen(to_qcolor(theme.muted), 1.0));
  painter.drawRect(area);
  for (int s = 0; s < 2; ++s) {
    QPolygonF track;
    for (int k = 0; k <= frame; ++k) {
      const Vec2& p = f.corner_images_px[size_t(k)][s][corner];
      track << to_area.map(QPointF(p.x, p.y));
    }
    painter.setPen(QPen(solution_colour(s), theme.line_width + 1.0));
    painter.drawPolyline(track);
    painter.setBrush(solution_colour(s));
    painter.drawEllipse(track.back(), 4.0, 4.0);
    painter.setBrush(Qt::NoBrush);
  }
}

void paint_chart(QPainter& painter, const FutureSeparation& f, int frame, const QRectF& area,
                 const ViewTheme& theme) {
  const double label = theme.label_size;
  const QRectF plot = area.adjusted(3.2 * label, 2.2 * label, -8, -1.6 * label);
  const double top = std::max(2.0 * kFuturesApartPx, f.corner_distance_px.back());
  const auto at = [&](int k, double px) {
    return QPointF(plot.left() + plot.width() * k / std::max(1, kFutureFrames),
                   plot.bottom() - plot.height() * px / top);
  };
  painter.setPen(QPen(to_qcolor(theme.muted), 1.0));
  painter.drawRect(plot);
  painter.setPen(QPen(to_qcolor(theme.text), 1.0, Qt::DashLine));
  painter.drawLine(at(0, kFuturesApartPx), at(kFutureFrames, kFuturesApartPx));
  QPolygonF curve;
  for (int k = 0; k <= frame; ++k) curve << at(k, f.corner_distance_px[size_t(k)]);
  painter.setPen(QPen(to_qcolor(okabe_ito::kVermillion), theme.line_width + 1.0));
  painter.drawPolyline(curve);
  painter.setPen(to_qcolor(theme.text));
  painter.drawText(QRectF(area.left(), area.top(), area.width(), 1.5 * label),
                   Qt::AlignLeft | Qt::AlignVCenter, QObject::tr("px apart, per frame"));
  // The axis values and the mark's text need the plot at least kChartPlotLines labels high:
  // lower, they would be drawn over each other.
  if (plot.height() < kChartPlotLines * label) return;
  painter.drawText(
      QRectF(area.left(), plot.top() - 0.8 * label, plot.left() - area.left() - 4, 1.6 * label),
      Qt::AlignRight | Qt::AlignVCenter, QString::number(top, 'f', 1));
  painter.drawText(
      QRectF(area.left(), plot.bottom() - 0.8 * label, plot.left() - area.left() - 4, 1.6 * label),
      Qt::AlignRight | Qt::AlignVCenter, QStringLiteral("0"));
  painter.drawText(QRectF(plot.left(), plot.bottom(), plot.width(), 1.6 * label),
                   Qt::AlignLeft | Qt::AlignVCenter, QStringLiteral("0"));
  painter.drawText(QRectF(plot.left(), plot.bottom(), plot.width(), 1.6 * label),
                   Qt::AlignRight | Qt::AlignVCenter, QObject::tr("frame %1").arg(kFutureFrames));
  if (f.first_frame_apart >= 0 && f.first_frame_apart <= frame) {
    const QPointF mark = at(f.first_frame_apart, f.corner_distance_px[size_t(f.first_frame_apart)]);
    painter.setPen(QPen(to_qcolor(theme.text), 1.0, Qt::DotLine));
    painter.drawLine(QPointF(mark.x(), plot.top()), QPointF(mark.x(), plot.bottom()));
    painter.setPen(to_qcolor(theme.text));
    // In the plot's top left, where the curve (growing from zero) never is.
    QString text = QObject::tr("over 1 px at frame %1").arg(f.first_frame_apart);
    if (painter.fontMetrics().horizontalAdvance(text) > plot.width() - 8) {
      text = QObject::tr("1 px: %1").arg(f.first_frame_apart);
    }
    painter.drawText(QRectF(plot.left() + 4, plot.top() + 2, plot.width() - 8, 1.5 * label),
                     Qt::AlignLeft | Qt::AlignVCenter, text);
  }
}

}  // namespace

QImage paint_explorer_futures(const ExplorerResult& result, int frame, const QImage& texture,
                              const Camera& camera, const QSize& size, const ViewTheme& theme) {
  QImage image = blank(size, theme);
  QPainter painter(&image);
  painter.setRenderHint(QPainter::Antialiasing, true);
  draw_explorer_futures(painter, result, frame, texture, camera, image.size(), theme);
  return image;
}

void draw_explorer_futures(QPainter& painter, const ExplorerResult& result, int frame,
                           const QImage& texture, const Camera& camera, const QSize& size,
                           const ViewTheme& theme) {
  const QRect image(QPoint(0, 0), size);
  set_font(painter, theme.label_size);
  if (!result.futures_played || result.futures.corner_images_px.empty()) {
    painter.setPen(to_qcolor(theme.text));
    painter.drawText(
        QRectF(image).adjusted(6, 6, -6, -6), Qt::AlignCenter | Qt::TextWordWrap,
        QObject::tr("Nothing to compare: %1").arg(QString::fromStdString(result.futures_note)));
    return;
  }
  const FutureSeparation& f = result.futures;
  const int shown = std::clamp(frame, 0, f.frames_played);
  // The two pictures side by side above, the magnified track and the chart below; the
  // pictures only when the chart keeps room for its texts (kChartLines label heights).
  const double label = theme.label_size;
  const double pictures =
      image.height() >= kPicturesLines * label ? std::round(0.55 * image.height()) : 0.0;
  for (int s = 0; s < 2 && pictures > 0.0; ++s) {
    paint_future_picture(painter, result, shown, s, texture, camera,
                         QRectF(0.5 * s * image.width(), 0, 0.5 * image.width(), pictures), theme);
  }
  const double below = image.height() - pictures;
  const double track_side = std::min(0.3 * image.width(), below);
  paint_tracks(painter, f, shown, QRectF(2, pictures + 2, track_side - 4, below - 4), theme);
  paint_chart(painter, f, shown,
              QRectF(track_side + 4, pictures, image.width() - track_side - 4, below), theme);
}

}  // namespace oflab
