// The animation view's framing and panel layout (gui/views/animation_view.h): what the panels
// frame (the loop or the content around the frame shown), how much of the exact panel that
// fills, where the panels, their titles, captions and legends go, and the choice between two
// rows and one. Units: camera pixels for frames and outlines, canvas pixels for cells.
#include <QFontMetrics>
#include <QPainter>
#include <algorithm>
#include <cmath>

#include "adapters/frame_images.h"
#include "adapters/parallel_paint.h"
#include "image/thread_pool.h"
#include "models/animation_model.h"
#include "models/window_model.h"
#include "player/stage_times.h"
#include "views/animation_view.h"
#include "views/panel_layout.h"

namespace oflab {

namespace {

QColor qcolor(const RgbF& c) { return QColor::fromRgbF(c[0], c[1], c[2]); }

// The largest rectangle of `aspect` (width / height) centred in `within`, its corner moved to
// the nearest whole pixel (by half a pixel at most): panels of one size then draw their
// shared marks alike (paint_panels).
QRectF centred_with_aspect(const QRectF& within, double aspect) {
  double w = within.width(), h = within.height();
  if (w / h > aspect) {
    w = h * aspect;
  } else {
    h = w / aspect;
  }
  return QRectF(std::round(within.center().x() - w / 2), std::round(within.center().y() - h / 2), w,
                h);
}

// `lines` with every line wider than `width` in `metrics` broken at its spaces, each break as
// far right as fits (a title with none of wrapped_caption's separators).
QStringList broken_at_spaces(const QStringList& lines, const QFontMetrics& metrics, double width) {
  QStringList out;
  for (QString line : lines) {
    while (metrics.horizontalAdvance(line) > width) {
      int at = line.lastIndexOf(QLatin1Char(' '));
      while (at > 0 && metrics.horizontalAdvance(line.left(at)) > width)
        at = line.lastIndexOf(QLatin1Char(' '), at - 1);
      if (at <= 0) break;
      out << line.left(at);
      line = line.mid(at + 1);
    }
    out << line;
  }
  return out;
}

}  // namespace

QRectF AnimationView::fit_content() {
  if (fit_known_) return fit_;
  const Animator* animator = model_->animator();
  frame_bounds_ = source_frame_bounds(model_->source(), model_->player().panel(),
                                      animator ? &animator->scene() : nullptr, kNear);
  fit_ = frame_rect(bounds_around(frame_bounds_, 0, -1));
  fit_known_ = true;
  return fit_;
}

QRectF AnimationView::framed_content() {
  const QRectF loop = fit_content();
  if (!window_->frames_content() || !model_->animator()) return loop;
  return frame_rect(oflab::framed_content(frame_bounds_, model_->animator()->frame(), true));
}

std::vector<QRectF> AnimationView::drawn_content_rects() {
  QRectF covered;
  if (const Animator* animator = model_->animator()) {
    for (const std::vector<Vec2>& outline :
         exact_outlines(animator->scene(), animator->view(), animator->camera(), kNear)) {
      for (const Vec2& p : outline) covered |= QRectF(QPointF(p.x, p.y), QSizeF(1e-9, 1e-9));
    }
  }
  std::vector<QRectF> drawn;
  for (const QRectF& panel : panel_rects_) {
    const QRectF in_panel =
        covered.isEmpty() ? QRectF() : frame_to_panel(shown_frame_, panel).mapRect(covered);
    drawn.push_back(in_panel.intersected(panel));
  }
  return drawn;
}

double AnimationView::content_fill() {
  const Animator* animator = model_->animator();
  if (!animator || shown_frame_.isEmpty()) return 0.0;
  // The exact outlines of the frame shown (the plane's image, whatever its texture's alpha)
  // over the shown frame (session/display/panel_framing.h, as the page measures it).
  return outline_fill(
      exact_outlines(animator->scene(), animator->view(), animator->camera(), kNear),
      *frame_box(shown_frame_));
}

AnimationView::CaptionLines AnimationView::wrap_captions(std::vector<PanelContent>& contents,
                                                         int canvas_width, double gap,
                                                         bool heat_row) const {
  const StageTimer timer(FrameStage::kText);
  const int columns = heat_row ? int(contents.size() + 1) / 2 : int(contents.size());
  const double cell_width = (canvas_width - 2 * gap - (columns - 1) * gap) / std::max(1, columns);
  QFont font;
  font.setPixelSize(theme_.font_size);
  const QFontMetrics metrics(font);
  CaptionLines lines{2, 1, theme_.font_size, 1};
  for (size_t i = 0; i < contents.size(); ++i) {
    QStringList wrapped;
    // At the separators first; a piece still wider than the cell breaks at its spaces (a
    // caption the lesson refers to is never elided). A line wrapped before at this width and
    // font is not measured again.
    for (const QString& line : contents[i].caption) {
      wrapped += text_cache_.lines(font, cell_width, line, [&] {
        return broken_at_spaces(wrapped_caption(line, metrics, cell_width), metrics, cell_width);
      });
    }
    contents[i].caption = wrapped;
    int& row = heat_row && int(i) >= columns ? lines.heat : lines.top;
    row = std::max(row, int(wrapped.size()));
  }
  QFont bold = font;
  bold.setBold(true);
  for (double scale : {1.15, 1.0, 0.85}) {
    bold.setPixelSize(int(theme_.font_size * scale));
    const QFontMetrics title_metrics(bold);
    const bool fits = std::all_of(contents.begin(), contents.end(), [&](const PanelContent& c) {
      return text_cache_.advance(bold, c.title, [&] {
        return title_metrics.horizontalAdvance(c.title);
      }) <= cell_width;
    });
    if (fits) {
      lines.title_px = bold.pixelSize();
      return lines;
    }
  }
  bold.setPixelSize(theme_.font_size);
  for (PanelContent& c : contents) {
    const QStringList wrapped = broken_at_spaces(
        wrapped_caption(c.title, QFontMetrics(bold), cell_width), QFontMetrics(bold), cell_width);
    c.title = wrapped.join(QLatin1Char('\n'));
    lines.title_lines = std::max(lines.title_lines, int(wrapped.size()));
  }
  return lines;
}

void AnimationView::paint_texts(QPainter& painter, const PanelContent& panel,
                                const PanelCell& cell) {
  const StageTimer timer(FrameStage::kText);
  const int text_px = theme_.font_size;
  QFont font = painter.font();
  font.setBold(true);
  font.setPixelSize(lines_.title_px);
  painter.setFont(font);
  painter.setPen(qcolor(theme_.text));
  const QStringList title = panel.title.split(QLatin1Char('\n'));
  const double title_row = cell.title.height() / std::max(1, lines_.title_lines);
  const double title_top = cell.title.bottom() - title_row * title.size();
  for (int i = 0; i < title.size(); ++i) {
    const QRectF row(cell.title.left(), title_top + i * title_row, cell.title.width(), title_row);
    painter.drawText(row, Qt::AlignCenter, text_cache_.elided(font, title[i], int(row.width())));
  }
  font.setPixelSize(text_px);
  font.setBold(false);
  painter.setFont(font);
  const double line = text_px * kCaptionLine;
  for (int i = 0; i < panel.caption.size() && (i + 1) * line <= cell.caption.height() + 1; ++i) {
    const QRectF row(cell.caption.left(), cell.caption.top() + i * line, cell.caption.width(),
                     line);
    painter.drawText(row, Qt::AlignCenter,
                     text_cache_.elided(font, panel.caption[i], int(row.width())));
  }
}

void AnimationView::paint_band(QPainter& painter, const QRectF& band, bool levels, bool heat) {
  const QColor text = qcolor(theme_.text);
  const int text_px = theme_.font_size;
  // Side by side in a wide band, stacked (legend above the colour bar) in a cell.
  const bool stacked = band.height() >= 2 * text_px * 3.6;
  QRectF legend = band, bar = band;
  if (levels && heat && stacked) {
    legend.setBottom(band.bottom() -
                     difference_bar_height(std::min(band.width(), 30.0 * text_px), text_px));
    bar.setTop(legend.bottom());
  } else if (levels && heat) {
    legend.setWidth(band.width() * 0.55);
    bar.setLeft(band.right() - std::min(band.width() * 0.4, 30.0 * text_px));
  }
  if (levels) draw_level_legend(painter, legend, text, text_px);
  if (heat) {
    bar.setWidth(std::min(bar.width(), 30.0 * text_px));
    const double bar_height = difference_bar_height(bar.width(), text_px);
    draw_difference_bar(painter,
                        QRectF(bar.left(), bar.bottom() - std::min(bar.height(), bar_height),
                               bar.width(), std::min(bar.height(), bar_height)),
                        kDifferenceScale, text, text_px);
  }
}

AnimationView::PanelPlan AnimationView::plan_panels(std::vector<PanelContent> contents,
                                                    const QSize& size, bool heat_row) const {
  PanelPlan plan;
  const int text_px = theme_.font_size;
  const double gap = text_px;
  plan.lines = wrap_captions(contents, size.width(), gap, heat_row);
  const CaptionLines& lines = plan.lines;
  // One title line at 1.15 times the text size gets 1.8 text sizes, as the bands always had.
  const double title = lines.title_lines * lines.title_px * 1.3 + text_px * 0.3;
  const double caption = text_px * kCaptionLine * lines.top;
  const double heat_caption = text_px * kCaptionLine * lines.heat;
  // Below one row, the legends' band holds the colour bar of any heat maps.
  const PanelDisplay display = window_->panel_display();
  const bool heat = display == PanelDisplay::kComparison || display == PanelDisplay::kDifference;
  const double bar =
      heat ? difference_bar_height(std::min(0.4 * size.width(), 30.0 * text_px), text_px) : 0.0;
  const double band = heat_row ? 0.0 : std::max(text_px * 3.9, bar + gap);
  const QRectF area(gap, gap / 2, size.width() - 2 * gap, size.height() - gap - band);
  const int columns = heat_row ? int(contents.size() + 1) / 2 : int(contents.size());
  QRectF top = area;
  if (heat_row) {
    const double image = (area.height() - gap / 2 - 2 * title - caption - heat_caption) / 2;
    top.setHeight(title + caption + std::max(0.0, image));
  }
  plan.cells = panel_row(top, columns, gap, title, caption);
  plan.legends = QRectF(area.left(), area.bottom() + gap / 2, area.width(), band - gap);
  if (heat_row) {
    const QRectF bottom(area.left(), top.bottom() + gap / 2, area.width(),
                        area.bottom() - top.bottom() - gap / 2);
    const std::vector<PanelCell> more = panel_row(bottom, columns, gap, title, heat_caption);
    plan.cells.insert(plan.cells.end(), more.begin(), more.end() - 1);
    plan.legends = QRectF(more.back().title.topLeft(), more.back().caption.bottomRight());
  }
  plan.contents = std::move(contents);
  return plan;
}

bool AnimationView::texts_fit(const PanelPlan& plan) const {
  QFont font;
  font.setPixelSize(theme_.font_size);
  QFont bold = font;
  bold.setBold(true);
  bold.setPixelSize(plan.lines.title_px);
  const QFontMetrics text(font), title(bold);
  for (size_t i = 0; i < plan.contents.size(); ++i) {
    const PanelCell& cell = plan.cells[i];
    if (cell.image.height() < 3 * theme_.font_size) return false;
    for (const QString& line : plan.contents[i].title.split(QLatin1Char('\n'))) {
      const int width =
          text_cache_.advance(bold, line, [&] { return title.horizontalAdvance(line); });
      if (width > cell.title.width()) return false;
    }
    for (const QString& line : plan.contents[i].caption) {
      const int width =
          text_cache_.advance(font, line, [&] { return text.horizontalAdvance(line); });
      if (width > cell.caption.width()) return false;
    }
  }
  return true;
}

double AnimationView::content_scale(const PanelPlan& plan, const QRectF& content) const {
  const Camera& camera = model_->animator()->camera();
  const QRectF& image = plan.cells.front().image;
  const QRectF frame = panel_frame(content, QSizeF(camera.width, camera.height),
                                   image.width() / image.height(), 1.0);
  return image.width() / frame.width();
}

void AnimationView::paint_marks(QPainter& painter, const QSize& image_size, const QRectF& target,
                                const std::vector<std::vector<Vec2>>& outlines) const {
  const QTransform base = painter.transform();
  const QTransform to_panel = frame_to_panel(shown_frame_, target) * base;
  const QColor outline = qcolor(theme_.outline);
  painter.save();
  painter.setRenderHint(QPainter::Antialiasing, true);
  painter.setBrush(Qt::NoBrush);
  painter.setPen(QPen(outline, 1.0, Qt::DotLine));
  painter.drawRect(frame_to_panel(shown_frame_, target).mapRect(QRectF(QPointF(0, 0), image_size)));
  // The outlines' points mapped here, drawn untransformed (the pen's width in canvas pixels).
  painter.setTransform(QTransform());
  painter.setPen(QPen(outline, theme_.line_width, Qt::DashLine));
  for (const std::vector<Vec2>& points : outlines) {
    QPolygonF polygon;
    for (const Vec2& p : points) polygon << to_panel.map(QPointF(p.x, p.y));
    painter.drawPolygon(polygon);
  }
  painter.restore();
}

void AnimationView::paint_picture(QPainter& painter, const PanelContent& panel,
                                  const QRectF& target,
                                  const std::vector<std::vector<Vec2>>& outlines,
                                  const QImage* marks) const {
  const QTransform base = painter.transform();
  const QTransform to_panel = frame_to_panel(shown_frame_, target) * base;
  const QColor background = qcolor(theme_.background);
  painter.save();
  painter.setClipRect(target);
  // Outside the camera image: a shade apart from the image's own background.
  painter.fillRect(target,
                   background.lightness() > 128 ? background.darker(112) : background.lighter(160));
  const QRectF image_rect = frame_to_panel(shown_frame_, target)
                                .mapRect(QRectF(QPointF(0, 0), QSizeF(panel.image.size())));
  painter.fillRect(image_rect, qcolor(theme_.image_background));
  painter.setTransform(to_panel);
  painter.drawImage(QPointF(0, 0), panel.image);
  painter.setTransform(base);
  if (marks) {  // clipped to `target` when it was drawn: the edge pixels are not clipped twice
    painter.save();
    painter.setClipping(false);
    painter.drawImage(target.toAlignedRect().topLeft(), *marks);
    painter.restore();
  } else {
    paint_marks(painter, panel.image.size(), target, outlines);
  }
  painter.setTransform(QTransform());
  draw_level_outlines(painter, panel.levels, to_panel, theme_.line_width + 1.5);
  painter.restore();
}

namespace {

// The marks of panels that draw them alike (AnimationView::paint_marks): panels of the same
// window size, the same target within it and images of one size share one drawing.
struct MarksOverlay {
  QSize window;
  QRectF target;  // in the window's pixels
  QSize image;
  int first = 0;  // the first panel that draws it
  int panels = 0;
};

}  // namespace

std::vector<QImage> AnimationView::shared_marks(
    const PanelPlan& plan, const std::vector<QRectF>& targets, const std::vector<QRect>& windows,
    const std::vector<std::vector<Vec2>>& outlines) const {
  const size_t count = targets.size();
  std::vector<MarksOverlay> overlays;
  std::vector<size_t> overlay_of(count);
  for (size_t i = 0; i < count; ++i) {
    const MarksOverlay key{windows[i].size(), targets[i].translated(-windows[i].topLeft()),
                           plan.contents[i].image.size(), int(i), 0};
    size_t k = 0;
    while (k < overlays.size() &&
           !(overlays[k].window == key.window && overlays[k].target == key.target &&
             overlays[k].image == key.image))
      ++k;
    if (k == overlays.size()) overlays.push_back(key);
    ++overlays[k].panels;
    overlay_of[i] = k;
  }
  std::vector<QImage> drawn(overlays.size());
  for (size_t k = 0; k < overlays.size(); ++k) {
    const MarksOverlay& o = overlays[k];
    if (o.panels < 2) continue;  // a panel alone strokes its marks itself
    drawn[k] = QImage(o.window, QImage::Format_ARGB32_Premultiplied);
    drawn[k].fill(Qt::transparent);
    // As the first panel that draws it paints it on its window (paint_picture under
    // paint_in_windows's move), so that the clip's edges take the same pixels; in strips of
    // rows on the worker threads (the strokes' cost is their rasterising).
    const QPoint corner = windows[size_t(o.first)].topLeft();
    const QRectF& target = targets[size_t(o.first)];
    const auto marks = [&](QPainter& on, int) {
      on.translate(-corner);
      on.setClipRect(target);
      paint_marks(on, o.image, target, outlines);
    };
    const std::vector<QRect> strips = row_strips(drawn[k].rect(), worker_threads());
    if (!paint_image_in_windows(drawn[k], strips, marks)) {
      QPainter on(&drawn[k]);
      marks(on, 0);
    }
  }
  std::vector<QImage> marks;
  for (size_t i = 0; i < count; ++i) marks.push_back(drawn[overlay_of[i]]);  // shared, not copied
  return marks;
}

void AnimationView::paint_panels(QPainter& painter, const PanelPlan& plan,
                                 const std::vector<std::vector<Vec2>>& outlines) {
  const size_t count = plan.contents.size();
  std::vector<QRectF> targets;
  for (const PanelCell& cell : plan.cells)
    targets.push_back(
        centred_with_aspect(cell.image, shown_frame_.width() / shown_frame_.height()));
  panel_rects_.insert(panel_rects_.end(), targets.begin(), targets.end());
  // Each panel's picture on core's worker threads, into its own window of the canvas.
  std::vector<QRect> windows;
  for (const QRectF& target : targets) windows.push_back(target.toAlignedRect());
  // The panels' shared marks drawn once (only on an untransformed canvas: a scaled painter
  // strokes at the device's resolution).
  const std::vector<QImage> marks = shared_marks_ && painter.transform().isIdentity()
                                        ? shared_marks(plan, targets, windows, outlines)
                                        : std::vector<QImage>(count);
  const auto paint = [&](QPainter& on, int i) {
    const QImage& shared = marks[size_t(i)];
    paint_picture(on, plan.contents[size_t(i)], targets[size_t(i)], outlines,
                  shared.isNull() ? nullptr : &shared);
  };
  if (!panels_in_parallel_ || count < 2 || !paint_in_windows(painter, windows, paint)) {
    for (size_t i = 0; i < count; ++i) paint(painter, int(i));
  }
  // The texts here, on the window's thread (fonts are the GUI thread's).
  for (size_t i = 0; i < count; ++i) paint_texts(painter, plan.contents[i], plan.cells[i]);
}

}  // namespace oflab
