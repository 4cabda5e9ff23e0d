// View 2, "Basis deformations": the gallery of basis terms (BasisTiles) for the chosen
// basis, with the amount of deformation on a slider and a play toggle that animates it
// (a QTimer). Each tile shows the current flow's coefficient of its term. With "Explore"
// on (WindowState::basis_explorer) the view is the basis explorer (views/explorer_panel.h):
// the planar gallery's tiles then show the explorer's dialled terms instead of the scene's,
// between the explorer's sliders and its solutions.
#pragma once

#include <QString>
#include <memory>
#include <vector>

#include "basis/basis_catalog.h"
#include "views/view_page.h"

class QCheckBox;
class QComboBox;
class QGridLayout;
class QLabel;
class QSlider;
class QTimer;

namespace oflab {

class BasisTiles;
class ExplorerPanel;
class ImageCanvas;
class SceneModel;
class WindowModel;

class BasisView : public ViewPage {
  Q_OBJECT

 public:
  // Shows and edits the window model's basis and its playing; the model must outlive the
  // view.
  BasisView(WindowModel* window, QWidget* parent = nullptr);
  ~BasisView() override;

  QImage render_image() override;
  void step_animation() override;
  void set_external_clock(bool on) override;
  void set_theme(const ViewTheme& theme) override;
  double smallest_text_px() const override;

  BasisKind basis() const;  // the window model's
  // Maximum amount of deformation, 0..1 (the slider).
  double amount() const;
  void set_amount(double amount);
  bool playing() const;  // the window model's basis_playing
  // Tiles with a non-zero coefficient after the last update.
  int active_tile_count() const;
  // 1 when the tile of the term with this symbol ("scale", "px", ...) is lit after the last
  // update, 0 when grey, NaN when the gallery has no such tile.
  double tile_active(const std::string& symbol) const;
  // The share (0..1) of its panel that what the view draws covers, as drawn now (it renders
  // first): without the explorer, the smallest over the gallery's 12 tiles of the share of the
  // tile inside its deformed square (BasisTiles::smallest_fill); with it, the share of the
  // explorer's deformation picture under its caption inside the deformed texture rectangle
  // (ExplorerPanel::deformation_fill; the explorer's small gallery there is an index of the
  // dialled terms and is not measured). The basis view's panel_fill.
  double drawn_share();
  // The line under the tiles; it starts by saying so when the plane is outside the image.
  QString summary() const;
  // The grids' displacement now: while playing it swings between 35 % and 100 % of
  // amount() (never through zero); paused it is amount().
  double animated_amount() const;
  // Font size of the tiles' value labels, pixels.
  int value_font_size() const;
  // The widget that shows the painted gallery.
  ImageCanvas* canvas() const { return canvas_; }
  // The explorer's widgets and what they show (shown when the model's basis_explorer is on).
  ExplorerPanel* explorer() const { return explorer_; }
  bool explorer_shown() const;
  // What is wrong with the explorer's texts (ExplorerPanel::text_problems) when it is shown;
  // empty otherwise. render_image first for the current values.
  std::vector<QString> text_problems() const;

  void refresh();

 protected:
  void showEvent(QShowEvent* event) override;

 private:
  QWidget* make_option_bar();
  void update_tiles();
  void update_explorer_tiles(double radius);
  void paint_canvas();
  // The controls show the model's basis and playing; the timer follows; redraws.
  void show_basis();
  // The explorer's widgets are shown or hidden as the model says; redraws.
  void show_explorer();

  WindowModel* window_;
  SceneModel* model_;
  ImageCanvas* canvas_;
  std::unique_ptr<BasisTiles> tiles_;
  QComboBox* basis_box_ = nullptr;
  QSlider* amount_slider_ = nullptr;
  QCheckBox* play_box_ = nullptr;
  QCheckBox* explore_box_ = nullptr;
  ExplorerPanel* explorer_ = nullptr;
  QGridLayout* body_ = nullptr;
  QLabel* summary_ = nullptr;
  QTimer* timer_;
  double phase_ = 3.14159265358979323846;  // 0.5 (1 - cos(phase)) = 1: full amount when paused
  bool dirty_ = true;
  bool external_clock_ = false;
};

}  // namespace oflab
