// The VTK side of the basis gallery: one render window split into 12 tiles (one renderer
// each), laid out as in the dissertation's figures: the 2 translation terms on top, the 4
// first-order terms below, the 6 second-order terms at the bottom. Each tile draws a
// square grid deformed by its term alone (core's taylor_flow_at of the term's Taylor
// terms, used as a displacement), over the faint undeformed square.
#pragma once

#include <vtkActor.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>

#include <vector>

#include "views/basis_catalog.h"
#include "views/view_theme.h"

class vtkCallbackCommand;
class vtkRenderWindow;

namespace oflab {

class BasisTiles {
 public:
  // Adds 12 renderers to `window`, which must outlive this object.
  explicit BasisTiles(vtkRenderWindow* window);
  ~BasisTiles();
  BasisTiles(const BasisTiles&) = delete;
  BasisTiles& operator=(const BasisTiles&) = delete;

  void set_theme(const ViewTheme& theme);

  // Redraws every tile for basis `kind`. `flow` gives each term's coefficient (shown in
  // the tile; zero tiles are greyed, see is_negligible with radius_px); `amount` in [0, 1]
  // is the displacement of the grid as a fraction of half the tile (0 = undeformed). A
  // tile deforms in the direction of its coefficient's sign (positive when zero).
  void update(BasisKind kind, const TaylorTerms& flow, double radius_px, double amount);

  // Number of tiles whose coefficient is not zero after the last update.
  int active_tile_count() const { return active_count_; }
  // The smallest font of the tiles' titles and values, screen pixels.
  double smallest_text_px() const;

  // Font sizes of the tiles' titles and value labels for the current theme, pixels: the
  // theme's label size (at least 18 px in presentation mode) and one more for titles.
  int title_font_size() const { return theme_.label_size + 1; }
  int value_font_size() const { return theme_.label_size; }

 private:
  struct Tile {
    vtkSmartPointer<vtkRenderer> renderer;
    vtkSmartPointer<vtkActor> grid, square;
    vtkSmartPointer<vtkTextActor> title, value;
    bool active = true;
    int order = 0;
  };
  void create_tile(int index);
  void style_tile(Tile& tile);
  void fit_cameras();
  static void on_render_start(vtkObject* caller, unsigned long event, void* self, void* data);

  vtkRenderWindow* window_;
  ViewTheme theme_;
  vtkSmartPointer<vtkRenderer> background_;  // whole window, behind the tiles
  std::vector<Tile> tiles_;
  vtkSmartPointer<vtkCallbackCommand> fit_callback_;
  int active_count_ = 0;
};

}  // namespace oflab
