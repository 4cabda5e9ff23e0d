#include "views/world_texts.h"

#include <QFontMetricsF>
#include <QPainter>
#include <algorithm>
#include <cmath>

#include "adapters/label_layout.h"
#include "adapters/paint_helpers.h"

namespace oflab {
namespace {

constexpr double kMargin = 10.0;  // between the texts and the canvas's edges, pixels
constexpr double kGap = 6.0;      // between a label and its point, pixels

QFont sized(const QFont& base, int px, bool bold) {
  QFont font = base;
  font.setPixelSize(std::max(1, px));
  font.setBold(bold);
  return font;
}

// The point of `box` nearest to `p`.
QPointF nearest_on(const QRectF& box, const QPointF& p) {
  return {std::clamp(p.x(), box.left(), box.right()), std::clamp(p.y(), box.top(), box.bottom())};
}

}  // namespace

void WorldTexts::lay_out(const QSize& size, const QFont& base, const ViewTheme& theme,
                         const Projector& project) {
  drawn_.clear();
  patch_ = to_qcolor(theme.background);
  patch_.setAlpha(220);  // the lines and textures behind show through, faintly
  leader_width_ = theme.line_width;
  std::vector<QRectF> taken;
  lay_out_legend(base, theme, taken);
  const double top = taken.empty() ? 0.0 : taken.back().bottom();
  const size_t legend_boxes = taken.size();
  lay_out_caption(size, base, theme, taken);
  double bottom = size.height();
  for (size_t k = legend_boxes; k < taken.size(); ++k) bottom = std::min(bottom, taken[k].top());
  free_area_ = QRectF(0.0, top, size.width(), std::max(0.0, bottom - top));
  lay_out_labels(size, base, theme, project, taken);
}

void WorldTexts::lay_out_legend(const QFont& base, const ViewTheme& theme,
                                std::vector<QRectF>& taken) {
  const QFont legend_font = sized(base, theme.font_size, true);
  const QFontMetricsF legend_metrics(legend_font);
  const QString legend_text = QString::fromStdString(legend);
  const QRectF legend_box(kMargin, kMargin, legend_metrics.horizontalAdvance(legend_text),
                          legend_metrics.height());
  drawn_.push_back({legend_text, legend_box, legend_font, to_qcolor(theme.text), false, {}});
  taken.push_back(legend_box);
}

void WorldTexts::lay_out_caption(const QSize& size, const QFont& base, const ViewTheme& theme,
                                 std::vector<QRectF>& taken) {
  const QColor text_colour = to_qcolor(theme.text);
  const QFont caption_font = sized(base, theme.label_size, false);
  const QFontMetricsF caption_metrics(caption_font);
  const QString text = QString::fromStdString(caption);
  const QString font_key = caption_font.key();
  const double width = size.width() - 2.0 * kMargin;
  WrappedCaption& wrapped = wrapped_caption_;
  if (wrapped.text != text || wrapped.font_key != font_key || wrapped.width != width) {
    wrapped.text = text;
    wrapped.font_key = font_key;
    wrapped.width = width;
    wrapped.lines = wrap_text(text, caption_metrics, width);
    wrapped.advances.clear();
    for (const QString& line : wrapped.lines)
      wrapped.advances.push_back(caption_metrics.horizontalAdvance(line));
  }
  const std::vector<QString>& lines = wrapped.lines;
  double top = size.height() - kMargin - caption_metrics.height() * double(lines.size());
  for (size_t k = 0; k < lines.size(); ++k) {
    const QString& line = lines[k];
    const QRectF box(kMargin, top, wrapped.advances[k], caption_metrics.height());
    if (!line.isEmpty()) {
      drawn_.push_back({line, box, caption_font, text_colour, false, {}});
      taken.push_back(box);
    }
    top += caption_metrics.height();
  }
}

void WorldTexts::lay_out_labels(const QSize& size, const QFont& base, const ViewTheme& theme,
                                const Projector& project, const std::vector<QRectF>& taken) {
  const QFont label_font = sized(base, theme.label_size, true);
  const QFontMetricsF label_metrics(label_font);
  std::vector<QSizeF> sizes;
  std::vector<QPointF> anchors;
  std::vector<const WorldLabel*> placed;
  for (const WorldLabel& label : labels) {
    QPointF at;
    if (!label.shown || label.text.empty() || !project(label.at, &at)) continue;
    const QString text = QString::fromStdString(label.text);
    sizes.emplace_back(label_metrics.horizontalAdvance(text), label_metrics.height());
    anchors.push_back(at);
    placed.push_back(&label);
  }
  const QRectF area(kMargin, kMargin, size.width() - 2.0 * kMargin, size.height() - 2.0 * kMargin);
  const std::vector<QRectF> boxes = place_labels(sizes, anchors, area, taken, kGap, content);
  for (size_t k = 0; k < boxes.size(); ++k) {
    const QPointF near = nearest_on(boxes[k], anchors[k]);
    const bool moved =
        std::hypot(near.x() - anchors[k].x(), near.y() - anchors[k].y()) > 2.0 * kGap + 1.0;
    // A shade further from the background than the arrow's own colour: the hue still names
    // the arrow, and the text reads from the back of a room (the palette's purple and
    // vermillion are too light on presentation mode's background, its blue too dark on the
    // normal one's).
    const QColor colour = theme.presentation ? to_qcolor(placed[k]->colour).darker(140)
                                             : to_qcolor(placed[k]->colour).lighter(140);
    drawn_.push_back({QString::fromStdString(placed[k]->text), boxes[k], label_font, colour, moved,
                      anchors[k], true});
  }
}

std::vector<QString> WorldTexts::labels_over_content() const {
  std::vector<QString> over;
  for (const Drawn& d : drawn_) {
    if (!d.label) continue;
    double covered = 0.0;
    for (const QPolygonF& outline : content)
      covered += covered_area(d.box.adjusted(1, 1, -1, -1), outline);
    if (covered >= 1.0)
      over.push_back(
          QStringLiteral("%1 covers %2 px of the pictures").arg(d.text).arg(std::lround(covered)));
  }
  return over;
}

void WorldTexts::paint(QPainter& painter) const {
  painter.save();
  for (const Drawn& d : drawn_) {
    if (d.leader) {
      painter.setPen(QPen(d.colour, leader_width_));
      painter.drawLine(d.anchor, nearest_on(d.box, d.anchor));
    }
    painter.fillRect(d.box, patch_);
    painter.setFont(d.font);
    painter.setPen(d.colour);
    painter.drawText(QPointF(d.box.left(), d.box.top() + QFontMetricsF(d.font).ascent()), d.text);
  }
  painter.restore();
}

}  // namespace oflab
