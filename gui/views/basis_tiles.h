// The basis gallery's picture: 12 tiles painted with Qt into one reused image, laid out as
// in the dissertation's figures: the 2 translation terms on top, the 4 first-order terms
// below, the 6 second-order terms at the bottom. Each tile draws a square grid deformed by
// its term alone (core's taylor_flow_at of the term's Taylor terms, used as a
// displacement), over the faint undeformed square, with the term's symbol and the current
// flow's coefficient. Each tile is framed on what it shows: zoomed so that the undeformed
// square and its grid at the framed amount (the largest the animation reaches) fill the tile
// between its title and value bands.
#pragma once

#include <QImage>
#include <QPolygonF>
#include <QRectF>
#include <QSize>
#include <QTransform>
#include <string>
#include <vector>

#include "adapters/view_theme.h"
#include "basis/basis_catalog.h"

class QPainter;

namespace oflab {

class BasisTiles {
 public:
  BasisTiles();
  BasisTiles(const BasisTiles&) = delete;
  BasisTiles& operator=(const BasisTiles&) = delete;

  void set_theme(const ViewTheme& theme);

  // Redraws every tile for basis `kind`. `flow` gives each term's coefficient (shown in
  // the tile; zero tiles are greyed, see is_negligible with radius_px); `amount` in [0, 1]
  // is the displacement of the grid as a fraction of half the tile (0 = undeformed). A
  // tile deforms in the direction of its coefficient's sign (positive when zero).
  // `framed_amount` in [0, 1] (at least `amount` for the grids to stay inside their tiles) is
  // the amount the tiles are zoomed for: each tile's grid at that amount and the undeformed
  // square fill the tile (so a playing grid moves inside a still frame).
  void update(BasisKind kind, const TaylorTerms& flow, double radius_px, double amount,
              double framed_amount);

  // Paints the last update at `size` (pixels; at least 1 x 1) into one of two reused images
  // and returns it.
  const QImage& paint(const QSize& size);

  // Number of tiles whose coefficient is not zero after the last update.
  int active_tile_count() const { return active_count_; }
  // 1 when the tile of the term with this symbol (basis_catalog.h BasisTerm::symbol) is lit
  // after the last update, 0 when it is grey, -1 when no tile has that symbol.
  int tile_state(const std::string& symbol) const;
  // The smallest font of the tiles' titles and values, screen pixels.
  double smallest_text_px() const;
  // The share (0..1) of its tile that the deformed square covers (the region inside the grid's
  // outer lines, clipped to the tile), the smallest over the 12 tiles, as the last paint drew
  // them: the gallery's panel_fill. 0 before the first paint.
  double smallest_fill() const;

  // Font sizes of the tiles' titles and value labels for the current theme, pixels: the
  // theme's label size (at least 18 px in presentation mode) and one more for titles.
  int title_font_size() const { return theme_.label_size + 1; }
  int value_font_size() const { return theme_.label_size; }

 private:
  struct Tile {
    std::vector<QPolygonF> grid;  // the deformed grid lines, half-tile units
    std::string title, value;     // the symbol; the coefficient's number ("0" when zero)
    const char* unit = "";        // its unit, or "(zero)"
    bool active = true;
    int order = 0;
    // The half width (x) and height (y) from the centre that the grid at the framed amount
    // and the undeformed square reach, half-tile units (1 when undeformed).
    QPointF reach{1.0, 1.0};
  };
  void paint_tile(QPainter& painter, const Tile& tile, const QRectF& cell) const;
  // Half-tile units to the pixels of `cell`: its centre, the zoom that fits a grid reaching
  // `reach` (Tile::reach) between the title and value bands.
  QTransform to_cell(const QRectF& cell, const QPointF& reach) const;
  // Tile `index`'s cell in a gallery of `size` pixels.
  static QRectF cell_rect(int index, const QSizeF& size);

  ViewTheme theme_;
  std::vector<Tile> tiles_;
  int active_count_ = 0;
  QSize painted_size_;  // the size of the last paint, empty before it
  QImage buffers_[2];   // painted galleries, used in turn so the shown one is not copied
  int next_buffer_ = 0;
};

}  // namespace oflab
