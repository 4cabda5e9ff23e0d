#include "views/basis_tiles.h"

#include <QPainter>
#include <QString>
#include <algorithm>
#include <cmath>

#include "adapters/paint_helpers.h"
#include "display/palette.h"

namespace oflab {
namespace {

constexpr int kTileCount = 12;
constexpr int kColumns = 6;
constexpr int kGridLines = 9;         // lines per direction: 8 x 8 cells over [-1, 1]^2
constexpr int kLineSamples = 33;      // points per grid line
constexpr double kMaxShift = 0.5;     // displacement at amount 1, in half-tile units
constexpr double kSideMargin = 0.04;  // of a tile's width, left and right of its grid

// Tile index -> (row from the top, column): rows of 2, 4 and 6 tiles, centred.
void tile_cell(int index, int* row, int* column) {
  if (index < 2) {
    *row = 0, *column = 2 + index;
  } else if (index < 6) {
    *row = 1, *column = 1 + (index - 2);
  } else {
    *row = 2, *column = index - 6;
  }
}

std::vector<Vec2> square_lattice_points() {
  std::vector<Vec2> points;
  for (int k = 0; k < kGridLines; ++k) {
    for (int s = 0; s < kLineSamples; ++s) {
      const double a = -1.0 + 2.0 * k / (kGridLines - 1);
      const double b = -1.0 + 2.0 * s / (kLineSamples - 1);
      points.emplace_back(a, b);
      points.emplace_back(b, a);
    }
  }
  return points;
}

// The grid lines displaced by scale * flow(q): vertical lines x = const, then horizontal.
std::vector<QPolygonF> deformed_grid(const TaylorTerms& unit, double scale) {
  std::vector<QPolygonF> lines;
  for (int direction = 0; direction < 2; ++direction) {
    for (int k = 0; k < kGridLines; ++k) {
      QPolygonF line;
      for (int s = 0; s < kLineSamples; ++s) {
        const double a = -1.0 + 2.0 * k / (kGridLines - 1);
        const double b = -1.0 + 2.0 * s / (kLineSamples - 1);
        const Vec2 q = direction == 0 ? Vec2(a, b) : Vec2(b, a);
        const Vec2 moved = q + scale * taylor_flow_at(unit, q);
        line << QPointF(moved.x, moved.y);
      }
      lines.push_back(line);
    }
  }
  return lines;
}

// Scale that makes the term's largest displacement over the square equal to 1.
double unit_normaliser(const TaylorTerms& unit) {
  double largest = 0.0;
  for (const Vec2& q : square_lattice_points()) {
    largest = std::max(largest, glm::length(taylor_flow_at(unit, q)));
  }
  return largest > 0.0 ? 1.0 / largest : 0.0;
}

// The region inside a deformed grid's outer lines (deformed_grid's order), as one polygon.
QPolygonF grid_outline(const std::vector<QPolygonF>& lines) {
  if (lines.size() < size_t(2 * kGridLines)) return {};
  const QPolygonF& left = lines[0];
  const QPolygonF& bottom = lines[size_t(2 * kGridLines - 1)];
  const QPolygonF& right = lines[size_t(kGridLines - 1)];
  const QPolygonF& top = lines[size_t(kGridLines)];
  QPolygonF outline = left;
  outline << bottom;
  for (int i = right.size() - 1; i >= 0; --i) outline << right[i];
  for (int i = top.size() - 1; i >= 0; --i) outline << top[i];
  return outline;
}

}  // namespace

BasisTiles::BasisTiles() : theme_(view_theme(false)), tiles_(kTileCount) {}

void BasisTiles::set_theme(const ViewTheme& theme) { theme_ = theme; }

void BasisTiles::update(BasisKind kind, const TaylorTerms& flow, double radius_px, double amount,
                        double framed_amount) {
  const std::vector<BasisTerm> terms = basis_terms(kind);
  active_count_ = 0;
  for (size_t i = 0; i < tiles_.size() && i < terms.size(); ++i) {
    const BasisTerm& term = terms[i];
    Tile& tile = tiles_[i];
    const double value = term.coefficient(flow);
    tile.active = !is_negligible(term.order, value, radius_px);
    tile.order = term.order;
    active_count_ += tile.active ? 1 : 0;
    const double sign = tile.active && value < 0.0 ? -1.0 : 1.0;
    const double unit = sign * kMaxShift * unit_normaliser(term.unit);
    tile.grid = deformed_grid(term.unit, std::clamp(amount, 0.0, 1.0) * unit);
    const QRectF framed =
        grid_outline(deformed_grid(term.unit, std::clamp(framed_amount, 0.0, 1.0) * unit))
            .boundingRect();
    tile.reach = QPointF(std::max({1.0, -framed.left(), framed.right()}),
                         std::max({1.0, -framed.top(), framed.bottom()}));
    tile.title = term.symbol;
    tile.value = tile.active ? QString::number(value, 'g', 3).toStdString() : std::string("0");
    tile.unit = tile.active ? order_unit(term.order) : "(zero)";
  }
}

int BasisTiles::tile_state(const std::string& symbol) const {
  for (const Tile& tile : tiles_) {
    if (tile.title == symbol) return tile.active ? 1 : 0;
  }
  return -1;
}

double BasisTiles::smallest_text_px() const {
  return std::min(title_font_size(), value_font_size());
}

double BasisTiles::smallest_fill() const {
  if (painted_size_.isEmpty()) return 0.0;
  double smallest = 1.0;
  for (int i = 0; i < kTileCount; ++i) {
    const QRectF cell = cell_rect(i, painted_size_);
    const Tile& tile = tiles_[size_t(i)];
    const QPolygonF drawn = to_cell(cell, tile.reach).map(grid_outline(tile.grid));
    const double area = polygon_area(drawn.intersected(QPolygonF(cell)));
    smallest = std::min(smallest, area / (cell.width() * cell.height()));
  }
  return smallest;
}

QRectF BasisTiles::cell_rect(int index, const QSizeF& size) {
  int row = 0, column = 0;
  tile_cell(index, &row, &column);
  const double w = size.width() / kColumns, h = size.height() / 3.0;
  return QRectF(column * w, row * h, w, h);
}

// The grid at the framed amount reaches `reach` half-tiles from the centre; it fills the cell's
// width but its side margins and its height but the title band above and the value band below.
QTransform BasisTiles::to_cell(const QRectF& cell, const QPointF& reach) const {
  const double band = 1.25 * title_font_size() + 0.03 * cell.height();
  const double scale = std::max(0.0, std::min((0.5 - kSideMargin) * cell.width() / reach.x(),
                                              (0.5 * cell.height() - band) / reach.y()));
  QTransform transform;
  transform.translate(cell.center().x(), cell.center().y());
  transform.scale(scale, scale);
  return transform;
}

const QImage& BasisTiles::paint(const QSize& wanted) {
  const QSize size = wanted.expandedTo(QSize(1, 1));
  QImage& image = buffers_[next_buffer_];
  next_buffer_ = 1 - next_buffer_;
  if (image.size() != size) image = QImage(size, QImage::Format_RGB32);
  image.fill(to_qcolor(theme_.background));  // the cells without a tile
  QPainter painter(&image);
  for (int i = 0; i < kTileCount; ++i) paint_tile(painter, tiles_[size_t(i)], cell_rect(i, size));
  painted_size_ = size;
  return image;
}

// One tile: its background, the undeformed square, the deformed grid (half-tile units,
// Y down, framed by to_cell), the symbol at the top left and the value at the bottom left.
void BasisTiles::paint_tile(QPainter& painter, const Tile& tile, const QRectF& cell) const {
  painter.fillRect(cell, to_qcolor(tile.active ? theme_.tile_background : theme_.muted_background));
  const QTransform to_cell = this->to_cell(cell, tile.reach);
  painter.save();
  painter.setClipRect(cell);
  painter.setRenderHint(QPainter::Antialiasing, true);
  painter.setBrush(Qt::NoBrush);
  painter.setPen(QPen(to_qcolor(theme_.muted), 1.0));
  painter.drawRect(to_cell.mapRect(QRectF(-1, -1, 2, 2)));
  const QColor grid = tile.active ? to_qcolor(order_colour(tile.order)) : to_qcolor(theme_.muted);
  painter.setPen(QPen(grid, theme_.line_width + 0.5));
  for (const QPolygonF& line : tile.grid) painter.drawPolyline(to_cell.map(line));
  const QColor text = to_qcolor(tile.active ? theme_.text : theme_.muted);
  painter.setPen(text);
  QFont font = painter.font();
  font.setPixelSize(title_font_size());
  font.setBold(true);
  painter.setFont(font);
  const QRectF inner = cell.adjusted(0.04 * cell.width(), 0.03 * cell.height(),
                                     -0.02 * cell.width(), -0.03 * cell.height());
  const QString title = QString::fromStdString(tile.title);
  if (painter.fontMetrics().horizontalAdvance(title) > inner.width()) {
    font.setPixelSize(value_font_size());  // a narrow tile: the titles at the values' size
    painter.setFont(font);
  }
  painter.drawText(inner, Qt::AlignLeft | Qt::AlignTop, title);
  font.setPixelSize(value_font_size());
  font.setBold(false);
  painter.setFont(font);
  // The value with its unit; in a tile too narrow for both, the value alone (the explorer's
  // small gallery: its sliders show the units).
  const QString value = QString::fromStdString(tile.value);
  const QString with_unit = value + QStringLiteral(" ") + QString::fromLatin1(tile.unit);
  const bool fits = painter.fontMetrics().horizontalAdvance(with_unit) <= inner.width();
  painter.drawText(inner, Qt::AlignLeft | Qt::AlignBottom, fits ? with_unit : value);
  painter.restore();
}

}  // namespace oflab
