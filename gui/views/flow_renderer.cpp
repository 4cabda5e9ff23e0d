#include "views/flow_renderer.h"

#include <QFontMetricsF>
#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "adapters/frame_images.h"
#include "adapters/paint_helpers.h"
#include "adapters/parallel_paint.h"
#include "display/palette.h"
#include "engine/engine.h"
#include "flow/homography.h"
#include "image/warp.h"
#include "scene/view_culling.h"
#include "views/panel_layout.h"

namespace oflab {
namespace {

constexpr double kWheelStepPx = 3.0;  // wheel image resolution, image pixels per cell
constexpr double kNearPlane = 1e-3;   // world units: nearer than this counts as not seen
constexpr double kViewMargin = 1.12;  // the chosen region plus room for captions

// The display's spacing, or one that puts about 14 arrows across the plane's image.
double arrow_spacing(const FlowContext& context, const FlowDisplay& display) {
  if (display.spacing_px > 0.0) return std::max(4.0, display.spacing_px);
  Vec2 low(1e300), high(-1e300);
  for (const Vec2& c : projected_corners(context.camera, context.pose)) {
    low = glm::min(low, c);
    high = glm::max(high, c);
  }
  const double extent = std::min(std::max(high.x - low.x, high.y - low.y),
                                 double(std::max(context.camera.width, context.camera.height)));
  return std::clamp(extent / 14.0, 6.0, 48.0);
}

// The smallest 1, 2 or 5 times a power of ten at or above `value` (> 0), so the colour bar
// keeps its labels while the largest magnitude drifts from frame to frame.
double round_up_to_nice(double value) {
  if (!(value > 0.0)) return 1.0;
  const double decade = std::pow(10.0, std::floor(std::log10(value)));
  for (double step : {1.0, 2.0, 5.0, 10.0}) {
    if (step * decade >= value * (1.0 - 1e-12)) return step * decade;
  }
  return 10.0 * decade;
}

// The largest magnitude of `part` at the plane's projected corners that lie in the image and
// on the plane (each nudged a millionth towards the others' centre, so it is inside), px/s.
double largest_at_corners(const FlowContext& context, FlowPart part) {
  const auto corners = projected_corners(context.camera, context.pose);
  Vec2 centre(0.0);
  for (const Vec2& c : corners) centre += c / double(corners.size());
  const Vec2 half(0.5 * context.camera.width, 0.5 * context.camera.height);
  double largest = 0.0;
  for (const Vec2& c : corners) {
    const Vec2 p = c + 1e-6 * (centre - c);
    if (std::abs(p.x) > half.x || std::abs(p.y) > half.y || !sees_plane(context, p)) continue;
    const double m = glm::length(flow_part_at(context, part, p));
    if (std::isfinite(m)) largest = std::max(largest, m);
  }
  return largest;
}

// The length of a polyline, in its own units.
double path_length(const std::vector<Vec2>& path) {
  double length = 0.0;
  for (size_t k = 1; k < path.size(); ++k) length += glm::length(path[k] - path[k - 1]);
  return length;
}

// The plane's centre is in front of the camera and projects inside the image: a plane
// seen edge-on there covers no pixel but is not outside the picture.
bool centre_in_image(const Camera& camera, const PlanePose& pose) {
  if (!(pose.point.z > 0.0)) return false;
  const Vec2 p = project_centred(camera, pose.point);
  return std::abs(p.x) <= 0.5 * camera.width && std::abs(p.y) <= 0.5 * camera.height;
}

// Colour of magnitude `m` on a bar over [0, bar_max] that uses magnitude_colour up to `top`.
QColor magnitude_qcolor(double m, double bar_max, double top) {
  return to_qcolor(magnitude_colour(top * std::clamp(m / bar_max, 0.0, 1.0)));
}

// The bar uses the palest yellows only on a dark background.
double magnitude_top(const ViewTheme& theme) { return theme.presentation ? 0.8 : 1.0; }

QPointF qpoint(const Vec2& p) { return QPointF(p.x, p.y); }

// Gives every NaN cell of the nx x ny grid `cells` (row-major) next to a finite one that
// neighbour's value (the first of its eight neighbours, read before any cell is changed).
void extend_by_one_cell(std::vector<Vec2>& cells, int nx, int ny) {
  const std::vector<Vec2> inside = cells;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      Vec2& cell = cells[size_t(j) * nx + i];
      for (int k = 0; k < 9 && std::isnan(cell.x); ++k) {
        const int x = i + k % 3 - 1, y = j + k / 3 - 1;
        if (x >= 0 && y >= 0 && x < nx && y < ny) cell = inside[size_t(y) * nx + x];
      }
    }
  }
}

}  // namespace

FlowRenderer::FlowRenderer() : theme_(view_theme(false)) {}

void FlowRenderer::set_texture(const QImage& texture) {
  texture_image_ = texture;
  update_faded_texture();
}

// The texture faded towards the background, opaque: the picture of a translucent plane
// without blending every frame.
void FlowRenderer::update_faded_texture() {
  if (texture_image_.isNull()) {
    faded_texture_ = Layer();
    return;
  }
  QImage faded(texture_image_.size(), QImage::Format_RGB32);
  faded.fill(to_qcolor(theme_.background));
  QPainter painter(&faded);
  painter.setOpacity(theme_.presentation ? 0.6 : 0.45);
  painter.drawImage(0, 0, texture_image_);
  painter.end();
  faded_texture_ = make_layer(image_from_qimage(faded));
}

void FlowRenderer::set_theme(const ViewTheme& theme) {
  theme_ = theme;
  update_faded_texture();
  wheel_legend_ = QImage();
}

double FlowRenderer::smallest_text_px() const {
  return std::min(theme_.font_size, theme_.label_size);
}

void FlowRenderer::update(const FlowContext& context, const FlowDisplay& display,
                          const QString& frame_caption) {
  camera_ = context.camera;
  display_ = display;
  plane_in_image_ = plane_meets_image(context.camera, context.pose, kNearPlane) ||
                    centre_in_image(context.camera, context.pose);
  // With the plane out of the picture, the whole image is shown (there is nothing to zoom to).
  FlowDisplay framing = display;
  if (!plane_in_image_) framing.zoom_to_plane = false;
  choose_view_region(context, framing);
  outline_.clear();
  for (const Vec2& c : projected_corners(context.camera, context.pose)) outline_ << qpoint(c);
  outline_in_front_ = plane_visibility_problem(context.pose).empty();
  const double spacing = arrow_spacing(context, display);
  const std::vector<FlowSample> full = sample_flow_grid(context, FlowPart::kFull, spacing);
  const std::vector<FlowSample> shown =
      display.part == FlowPart::kFull ? full : sample_flow_grid(context, display.part, spacing);
  shown_samples_ = static_cast<int>(shown.size());
  shown_max_ = shown_samples_ == 0
                   ? 0.0
                   : std::max(max_flow_magnitude(shown), largest_at_corners(context, display.part));
  // Each part fills the grid unless the common scale is asked for, or the part is zero up
  // to rounding (a residual): then the full flow sets the scale, so parts compare by length
  // and rounding noise is never blown up into arrows.
  const double full_max =
      std::max(max_flow_magnitude(full),
               shown_samples_ == 0 ? 0.0 : largest_at_corners(context, FlowPart::kFull));
  rounding_only_ = shown_samples_ > 0 && shown_max_ <= 1e-9 * full_max;
  const double scale_max = display.common_scale || rounding_only_ ? full_max : shown_max_;
  const double arrow_seconds = scale_max > 0.0 ? 0.9 * spacing / scale_max : 0.0;
  // A plane that has left the picture has no flow to show: no arrows, lines, wheel or
  // colour bar, and the caption says so (the side table's terms are those of the plane
  // extended beyond the image).
  if (!plane_in_image_) display_.arrows = display_.streamlines = display_.colour_wheel = false;
  update_arrows(shown, arrow_seconds, display_.arrows);
  update_streamlines(context, display_, arrow_seconds);
  update_wheel(context, display_);
  // The wheel is opaque over the plane: the texture under it would not be seen.
  update_plane_image(context, display.texture && !display_.colour_wheel);
  update_caption(display, frame_caption);
}

// The faded texture warped exactly into a camera-sized image of the background, kept from
// frame to frame. A plane that cannot be warped (partly behind the eye, a sliver) keeps
// its outline only.
void FlowRenderer::update_plane_image(const FlowContext& context, bool wanted) {
  plane_drawn_ = false;
  if (!wanted || !plane_in_image_ || faded_texture_.empty() ||
      !plane_visibility_problem(context.pose).empty()) {
    return;
  }
  plane_image_.reshape(context.camera.width, context.camera.height);
  const QColor bg = to_qcolor(theme_.background);
  plane_image_.fill(
      Pixel{std::uint8_t(bg.red()), std::uint8_t(bg.green()), std::uint8_t(bg.blue()), 255});
  PlanePose sized = context.pose;
  sized.texture_size = glm::ivec2(faded_texture_.image.width(), faded_texture_.image.height());
  WarpOptions options;
  options.sampling = Sampling::kBilinear;
  try {
    warp_layer_into(faded_texture_, exact_texture_warp(context.camera, sized), plane_image_, 0, 0,
                    options);
  } catch (const std::invalid_argument&) {
    return;
  }
  const QPointF shift(context.camera.cx, context.camera.cy);
  plane_box_ = outline_.boundingRect().translated(shift).toAlignedRect().adjusted(-1, -1, 1, 1) &
               QRect(0, 0, context.camera.width, context.camera.height);
  plane_drawn_ = !plane_box_.isEmpty();
}

void FlowRenderer::update_arrows(const std::vector<FlowSample>& samples, double arrow_seconds,
                                 bool shown) {
  arrows_.clear();
  bar_max_ = round_up_to_nice(shown_max_);
  if (!shown) return;
  const double top = magnitude_top(theme_);
  for (const FlowSample& s : samples) {
    const QPointF tip = qpoint(s.position + arrow_seconds * s.flow);
    if (outline_in_front_ && !outline_.containsPoint(tip, Qt::OddEvenFill)) continue;
    arrows_.push_back(
        {qpoint(s.position), tip, magnitude_qcolor(glm::length(s.flow), bar_max_, top)});
  }
}

void FlowRenderer::update_streamlines(const FlowContext& context, const FlowDisplay& display,
                                      double arrow_seconds) {
  streamlines_.clear();
  if (!display.streamlines || arrow_seconds <= 0.0) return;
  const double seed_spacing = 2.0 * arrow_spacing(context, display);
  for (const FlowSample& seed : sample_flow_grid(context, FlowPart::kTranslation, seed_spacing)) {
    const std::vector<Vec2> path =
        trace_streamline(context, display.part, seed.position, 2.5 * arrow_seconds, 16);
    if (path.size() < 2) continue;
    // The line, then an arrow head at its end so the direction reads: at most half the
    // line's length, so a short line (a small part at the common scale) keeps its shaft.
    Streamline streamline;
    for (const Vec2& p : path) streamline.line << qpoint(p);
    const double head = std::min(0.3 * seed_spacing, 0.5 * path_length(path));
    for (const Vec2& p : streamline_arrow_head(path, head)) streamline.head << qpoint(p);
    streamlines_.push_back(streamline);
  }
}

// The wheel's colours over the part of the image the plane covers, one cell per
// kWheelStepPx pixels, the cells along the edge coloured as their neighbour inside (the
// wheel is painted clipped to the plane's outline, so the background never shows as a
// ragged band inside it), the background elsewhere.
void FlowRenderer::update_wheel(const FlowContext& context, const FlowDisplay& display) {
  wheel_caption_.clear();
  if (!display.colour_wheel) return;
  const Vec2 half(0.5 * context.camera.width, 0.5 * context.camera.height);
  const QRectF box = outline_.boundingRect() & QRectF(-half.x, -half.y, 2 * half.x, 2 * half.y);
  const int i0 = int(std::floor((box.left() + half.x) / kWheelStepPx));
  const int j0 = int(std::floor((box.top() + half.y) / kWheelStepPx));
  const int nx = std::max(1, int(std::ceil((box.right() + half.x) / kWheelStepPx)) - i0);
  const int ny = std::max(1, int(std::ceil((box.bottom() + half.y) / kWheelStepPx)) - j0);
  if (wheel_.width() != nx || wheel_.height() != ny) wheel_ = QImage(nx, ny, QImage::Format_RGB32);
  wheel_rect_ = QRectF(-half.x + i0 * kWheelStepPx, -half.y + j0 * kWheelStepPx, nx * kWheelStepPx,
                       ny * kWheelStepPx);
  auto centre_of = [&](int i, int j) {
    return Vec2(wheel_rect_.left() + (i + 0.5) * kWheelStepPx,
                wheel_rect_.top() + (j + 0.5) * kWheelStepPx);
  };
  std::vector<Vec2> flows(size_t(nx) * ny, Vec2(std::nan("")));
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      if (!sees_plane(context, centre_of(i, j))) continue;
      flows[size_t(j) * nx + i] = flow_part_at(context, display.part, centre_of(i, j));
    }
  }
  extend_by_one_cell(flows, nx, ny);
  const QRgb background = to_qcolor(theme_.background).rgb();
  for (int j = 0; j < ny; ++j) {
    auto* line = reinterpret_cast<QRgb*>(wheel_.scanLine(j));
    for (int i = 0; i < nx; ++i) {
      const Vec2& f = flows[size_t(j) * nx + i];
      line[i] = std::isnan(f.x) ? background : to_qcolor(flow_wheel_colour(f, shown_max_)).rgb();
    }
  }
  wheel_caption_ = QStringLiteral(
                       "Colour wheel (bottom right): hue = direction, "
                       "white to full colour = 0 to %1 px/s")
                       .arg(shown_max_, 0, 'g', 3);
}

void FlowRenderer::update_caption(const FlowDisplay& display, const QString& frame_caption) {
  if (!plane_in_image_ || shown_samples_ == 0) {
    // Outside, or seen so nearly edge-on that no grid sample falls inside it: there is no
    // flow to show and no residual to call zero.
    caption_text_ = plane_in_image_
                        ? QStringLiteral(
                              "%1: no grid sample falls inside the plane's image (seen "
                              "edge-on or too small), so there is nothing to compare")
                              .arg(QString::fromUtf8(flow_part_title(display.part)))
                        : QStringLiteral("The plane is outside the image: no flow to show");
    if (!frame_caption.isEmpty()) caption_text_ += QStringLiteral("\n") + frame_caption;
    return;
  }
  QString text = QStringLiteral("%1   max |v| = %2 px/s")
                     .arg(QString::fromUtf8(flow_part_title(display.part)))
                     .arg(shown_max_, 0, 'g', 3);
  if (rounding_only_) text += QStringLiteral(" (zero up to rounding)");
  if (!frame_caption.isEmpty()) text += QStringLiteral("\n") + frame_caption;
  caption_text_ = text;
}

void FlowRenderer::choose_view_region(const FlowContext& context, const FlowDisplay& display) {
  const Vec2 image_half(0.5 * context.camera.width, 0.5 * context.camera.height);
  if (!display.zoom_to_plane) {
    view_centre_ = Vec2(0.0);
    view_half_size_ = image_half;
    return;
  }
  Vec2 low(0.0), high(0.0);  // start from the principal point, so it stays in view
  for (const Vec2& c : projected_corners(context.camera, context.pose)) {
    low = glm::min(low, c);
    high = glm::max(high, c);
  }
  low = glm::max(low, -image_half);
  high = glm::min(high, image_half);
  view_centre_ = 0.5 * (low + high);
  view_half_size_ = glm::max(0.5 * (high - low), Vec2(40.0));
}

double FlowRenderer::side_width_px(int view_width) const {
  const double wanted = theme_.presentation ? 150.0 : 130.0;
  return std::clamp(0.14 * view_width, 80.0, wanted);
}

QRectF FlowRenderer::caption_rect(const QSize& size) const {
  QFont font;
  font.setPixelSize(theme_.font_size);
  const double pad = 0.01 * size.width();
  const int lines = int(caption_text_.count(QLatin1Char('\n'))) + 1;
  return QRectF(pad, pad, size.width() - side_width_px(size.width()) - 2 * pad,
                lines * QFontMetricsF(font).lineSpacing());
}

double FlowRenderer::wheel_caption_height() const {
  if (!display_.colour_wheel) return 0.0;
  QFont font;
  font.setPixelSize(theme_.label_size);
  return QFontMetricsF(font).lineSpacing();
}

QRectF FlowRenderer::outline_rect(const QSize& size) const {
  return image_to_view(size).map(outline_).boundingRect();
}

QRectF FlowRenderer::scene_rect(const QSize& size) const {
  const double pad = 0.01 * size.width();
  const double top = caption_rect(size).bottom() + pad;
  return QRectF(0.0, top, size.width() - side_width_px(size.width()),
                std::max(1.0, size.height() - top - wheel_caption_height() - pad));
}

double FlowRenderer::plane_share(const QSize& size) const {
  const QPolygonF outline = image_to_view(size).map(outline_);
  return hull_share(std::vector<QPointF>(outline.begin(), outline.end()), scene_rect(size));
}

// Centred image pixels -> view pixels: the chosen region, with a margin, centred in the
// part of the view left of the legend strip, below the caption and above the wheel's
// caption, so the scene never runs through their text.
QTransform FlowRenderer::image_to_view(const QSize& size) const {
  const QRectF scene = scene_rect(size);
  const double width = scene.width(), top = scene.top(), height = scene.height();
  const double aspect = width / height;
  const double half_h = kViewMargin * std::max(view_half_size_.y, view_half_size_.x / aspect);
  const double scale = 0.5 * height / half_h;
  QTransform t;
  t.translate(0.5 * width, top + 0.5 * height);
  t.scale(scale, scale);
  t.translate(-view_centre_.x, -view_centre_.y);
  return t;
}

const QImage& FlowRenderer::paint(const QSize& wanted) {
  const QSize size = wanted.expandedTo(QSize(1, 1));
  QImage& image = buffers_[next_buffer_];
  next_buffer_ = 1 - next_buffer_;
  if (image.size() != size) image = QImage(size, QImage::Format_RGB32);
  image.fill(to_qcolor(theme_.background));
  QPainter painter(&image);
  const double side = side_width_px(size.width());
  const QRectF scene_area(0, 0, size.width() - side, size.height());
  const QTransform to_view = image_to_view(size);
  // The plane's image and the colour wheel (smoothly scaled images) here, then the lines and
  // arrows (antialiased wide strokes) in kLineStrips strips of rows on core's worker threads:
  // the same picture on any number of threads. (Against the lines painted in one piece, the
  // few pixels a stroke covers on the rows either side of a seam may differ by one level.)
  painter.setClipRect(scene_area);
  paint_scene_images(painter, to_view);
  painter.setClipping(false);
  const auto lines = [&](QPainter& on, int) { paint_scene_lines(on, to_view); };
  const std::vector<QRect> strips = row_strips(QRect(QPoint(0, 0), size), kLineStrips);
  if (!paint_in_parallel_ || strips.size() < 2 ||
      !paint_in_windows(painter, strips, scene_area, lines)) {
    painter.setClipRect(scene_area);
    lines(painter, 0);
    painter.setClipping(false);
  }
  // The captions and the side antialiased, smooth images scaled (as the scene is).
  painter.setRenderHint(QPainter::Antialiasing, true);
  painter.setRenderHint(QPainter::SmoothPixmapTransform, true);
  QFont font = painter.font();
  font.setPixelSize(theme_.font_size);
  painter.setFont(font);
  painter.setPen(to_qcolor(theme_.text));
  const double pad = 0.01 * size.width();
  painter.drawText(QRectF(pad, pad, size.width() - side - 2 * pad, size.height()),
                   Qt::AlignLeft | Qt::AlignTop, caption_text_);
  if (display_.colour_wheel) {
    font.setPixelSize(theme_.label_size);
    painter.setFont(font);
    painter.drawText(QRectF(pad, 0, size.width() - side - 2 * pad, size.height() - pad),
                     Qt::AlignLeft | Qt::AlignBottom, wheel_caption_);
  }
  paint_side(painter, QRectF(size.width() - side, 0, side, size.height()));
  return image;
}

void FlowRenderer::paint_scene_images(QPainter& painter, const QTransform& to_view) const {
  const QPointF shift(camera_.cx, camera_.cy);
  painter.setRenderHint(QPainter::SmoothPixmapTransform, true);
  if (plane_drawn_) {
    const QImage plane(reinterpret_cast<const uchar*>(plane_image_.row(0)), plane_image_.width(),
                       plane_image_.height(), plane_image_.width() * 4, QImage::Format_RGBX8888);
    painter.drawImage(to_view.mapRect(QRectF(plane_box_).translated(-shift)), plane, plane_box_);
  }
  if (display_.colour_wheel) {
    painter.save();
    if (outline_in_front_) {
      QPainterPath plane;
      plane.addPolygon(to_view.map(outline_));
      painter.setClipPath(plane, Qt::IntersectClip);
    }
    painter.drawImage(to_view.mapRect(wheel_rect_), wheel_);
    painter.restore();
  }
}

void FlowRenderer::paint_scene_lines(QPainter& painter, const QTransform& to_view) const {
  painter.setRenderHint(QPainter::Antialiasing, true);
  painter.setBrush(Qt::NoBrush);
  const double w = theme_.line_width;
  const QRectF frame(-0.5 * camera_.width, -0.5 * camera_.height, camera_.width, camera_.height);
  painter.setPen(QPen(to_qcolor(theme_.muted), w));
  painter.drawPolygon(to_view.map(QPolygonF(frame)));
  painter.setPen(QPen(to_qcolor(theme_.outline), w + 1.0));
  painter.drawPolygon(to_view.map(outline_));
  // The principal point, where the coefficients of the side table are taken.
  const QPointF centre = to_view.map(QPointF(0, 0));
  const double r = 8.0 * to_view.m11();
  painter.setPen(QPen(to_qcolor(theme_.outline), w));
  painter.drawLine(centre - QPointF(r, 0), centre + QPointF(r, 0));
  painter.drawLine(centre - QPointF(0, r), centre + QPointF(0, r));
  painter.setPen(QPen(to_qcolor(theme_.streamline), w));
  for (const Streamline& line : streamlines_) {
    painter.drawPolyline(to_view.map(line.line));
    if (!line.head.isEmpty()) painter.drawPolyline(to_view.map(line.head));
  }
  paint_arrows(painter, to_view);
}

// Each arrow: a shaft from the sample point and a filled head at least a few line widths
// long (so short arrows still show their direction from afar), half as wide as long.
void FlowRenderer::paint_arrows(QPainter& painter, const QTransform& to_view) const {
  const double width = theme_.line_width + 0.5;
  for (const Arrow& arrow : arrows_) {
    const QPointF from = to_view.map(arrow.from), to = to_view.map(arrow.to);
    const QPointF along = to - from;
    const double length = std::hypot(along.x(), along.y());
    if (length < 0.5) continue;
    const double head = std::min(0.6 * length, std::max(0.3 * length, 4.0 * width));
    const QPointF unit = along / length, across(-unit.y(), unit.x());
    const QPointF base = to - head * unit;
    painter.setPen(QPen(arrow.colour, width, Qt::SolidLine, Qt::FlatCap));
    painter.drawLine(from, base);
    painter.setPen(Qt::NoPen);
    painter.setBrush(arrow.colour);
    const QPointF tip[3] = {base + 0.5 * head * across, to, base - 0.5 * head * across};
    painter.drawConvexPolygon(tip, 3);
  }
  painter.setBrush(Qt::NoBrush);
}

void FlowRenderer::paint_side(QPainter& painter, const QRectF& side) {
  if (display_.arrows && rounding_only_) {
    paint_rounding_note(painter, side);
  } else if (display_.arrows) {
    paint_colour_bar(painter, side);
  }
  if (!display_.colour_wheel) return;
  const double edge = std::min(side.width() - 8.0, 0.28 * side.height());
  paint_wheel_legend(painter, QRectF(side.right() - 4.0 - edge,
                                     side.bottom() - 0.03 * side.height() - edge, edge, edge));
}

// The magnitude colour bar: its title, the ramp from 0 (bottom) to the rounded largest
// magnitude (top) and five labels beside it.
void FlowRenderer::paint_colour_bar(QPainter& painter, const QRectF& side) {
  QFont font = painter.font();
  font.setPixelSize(theme_.label_size);
  painter.setFont(font);
  painter.setPen(to_qcolor(theme_.text));
  const double top = side.top() + 0.12 * side.height(), bottom = side.top() + 0.68 * side.height();
  painter.drawText(QRectF(side.left() + 4, top - 2.2 * theme_.label_size, side.width() - 8,
                          1.8 * theme_.label_size),
                   Qt::AlignLeft | Qt::AlignBottom, QStringLiteral("|v| px/s"));
  const QRectF bar(side.left() + 6, top, std::max(10.0, 0.22 * side.width()), bottom - top);
  const double ramp_top = magnitude_top(theme_);
  for (int y = 0; y < int(bar.height()); ++y) {
    const double t = 1.0 - (y + 0.5) / bar.height();
    painter.fillRect(QRectF(bar.left(), bar.top() + y, bar.width(), 1.0),
                     to_qcolor(magnitude_colour(ramp_top * t)));
  }
  const int labels = 5;
  for (int k = 0; k < labels; ++k) {
    const double t = double(k) / (labels - 1);
    const double y = bar.bottom() - t * bar.height();
    painter.drawLine(QPointF(bar.right(), y), QPointF(bar.right() + 4, y));
    painter.drawText(QRectF(bar.right() + 6, y - theme_.label_size, side.right() - bar.right() - 6,
                            2.0 * theme_.label_size),
                     Qt::AlignLeft | Qt::AlignVCenter, QString::asprintf("%.3g", t * bar_max_));
  }
}

// In place of the colour bar of a part that is zero up to rounding: that, in words, with
// the largest magnitude found (a colour bar from 0 to 1e-13 would only chart rounding).
void FlowRenderer::paint_rounding_note(QPainter& painter, const QRectF& side) {
  QFont font = painter.font();
  font.setPixelSize(theme_.label_size);
  painter.setFont(font);
  painter.setPen(to_qcolor(theme_.text));
  painter.drawText(
      QRectF(side.left() + 4, side.top() + 0.12 * side.height(), side.width() - 8,
             0.56 * side.height()),
      Qt::AlignLeft | Qt::AlignTop | Qt::TextWordWrap,
      QStringLiteral("|v| px/s\nzero up to rounding\n(at most %1)").arg(shown_max_, 0, 'g', 2));
}

// The colour-wheel legend: the coding of every direction and magnitude up to the largest
// (the disc's rim), y down as in the image. Made again only when its size changes.
void FlowRenderer::paint_wheel_legend(QPainter& painter, const QRectF& square) {
  const int edge = std::max(8, int(square.width()));
  if (wheel_legend_.width() != edge) {
    wheel_legend_ = QImage(edge, edge, QImage::Format_ARGB32_Premultiplied);
    wheel_legend_.fill(Qt::transparent);
    const double radius = 0.5 * edge / 1.05;
    for (int y = 0; y < edge; ++y) {
      auto* line = reinterpret_cast<QRgb*>(wheel_legend_.scanLine(y));
      for (int x = 0; x < edge; ++x) {
        const Vec2 offset((x + 0.5 - 0.5 * edge) / radius, (y + 0.5 - 0.5 * edge) / radius);
        if (glm::length(offset) <= 1.0) line[x] = to_qcolor(flow_wheel_colour(offset, 1.0)).rgb();
      }
    }
  }
  painter.drawImage(square.topLeft(), wheel_legend_);
}

}  // namespace oflab
