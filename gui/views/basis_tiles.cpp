#include "views/basis_tiles.h"

#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkTextProperty.h>

#include <QString>
#include <algorithm>
#include <cmath>

#include "views/palette.h"
#include "adapters/vtk_adapters.h"

namespace oflab {
namespace {

constexpr int kTileCount = 12;
constexpr int kColumns = 6;
constexpr int kGridLines = 9;       // lines per direction: 8 x 8 cells over [-1, 1]^2
constexpr int kLineSamples = 33;    // points per grid line
constexpr double kMaxShift = 0.5;   // displacement at amount 1, in half-tile units
constexpr double kHalfView = 1.75;  // half-height of a tile's view, in half-tile units

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
std::vector<std::vector<Vec3>> deformed_grid(const TaylorTerms& unit, double scale) {
  std::vector<std::vector<Vec3>> lines;
  for (int direction = 0; direction < 2; ++direction) {
    for (int k = 0; k < kGridLines; ++k) {
      std::vector<Vec3> line;
      for (int s = 0; s < kLineSamples; ++s) {
        const double a = -1.0 + 2.0 * k / (kGridLines - 1);
        const double b = -1.0 + 2.0 * s / (kLineSamples - 1);
        const Vec2 q = direction == 0 ? Vec2(a, b) : Vec2(b, a);
        const Vec2 moved = q + scale * taylor_flow_at(unit, q);
        line.emplace_back(moved.x, moved.y, 0.0);
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

}  // namespace

BasisTiles::BasisTiles(vtkRenderWindow* window) : window_(window), theme_(view_theme(false)) {
  background_ = vtkSmartPointer<vtkRenderer>::New();  // fills the cells without a tile
  background_->InteractiveOff();
  window_->AddRenderer(background_);
  for (int i = 0; i < kTileCount; ++i) create_tile(i);
  fit_callback_ = vtkSmartPointer<vtkCallbackCommand>::New();
  fit_callback_->SetCallback(&BasisTiles::on_render_start);
  fit_callback_->SetClientData(this);
  window_->AddObserver(vtkCommand::StartEvent, fit_callback_);
  set_theme(theme_);
}

BasisTiles::~BasisTiles() {
  window_->RemoveObserver(fit_callback_);
  for (Tile& tile : tiles_) window_->RemoveRenderer(tile.renderer);
  window_->RemoveRenderer(background_);
}

void BasisTiles::create_tile(int index) {
  Tile tile;
  tile.renderer = vtkSmartPointer<vtkRenderer>::New();
  int row = 0, column = 0;
  tile_cell(index, &row, &column);
  const double w = 1.0 / kColumns, h = 1.0 / 3.0;
  tile.renderer->SetViewport(column * w, (2 - row) * h, (column + 1) * w, (3 - row) * h);
  vtkCamera* camera = tile.renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetPosition(0.0, 0.0, -10.0);  // image convention: X right, Y down
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, -1.0, 0.0);
  camera->SetClippingRange(1.0, 20.0);
  for (auto* actor : {&tile.grid, &tile.square}) {
    *actor = vtkSmartPointer<vtkActor>::New();
    (*actor)->SetMapper(vtkSmartPointer<vtkPolyDataMapper>::New());
    tile.renderer->AddActor(*actor);
  }
  vtkPolyDataMapper::SafeDownCast(tile.square->GetMapper())
      ->SetInputData(closed_outline({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}));
  tile.title = vtkSmartPointer<vtkTextActor>::New();
  tile.value = vtkSmartPointer<vtkTextActor>::New();
  tile.title->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  tile.value->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  tile.title->SetPosition(0.04, 0.88);
  tile.value->SetPosition(0.04, 0.03);
  tile.renderer->AddViewProp(tile.title);
  tile.renderer->AddViewProp(tile.value);
  window_->AddRenderer(tile.renderer);
  tiles_.push_back(tile);
}

void BasisTiles::set_theme(const ViewTheme& theme) {
  theme_ = theme;
  background_->SetBackground(theme.background[0], theme.background[1], theme.background[2]);
  for (Tile& tile : tiles_) style_tile(tile);
}

void BasisTiles::style_tile(Tile& tile) {
  const RgbF& bg = tile.active ? theme_.tile_background : theme_.muted_background;
  tile.renderer->SetBackground(bg[0], bg[1], bg[2]);
  const RgbF grid = tile.active ? rgb(order_colour(tile.order)) : theme_.muted;
  set_line_style(tile.grid->GetProperty(), grid, theme_.line_width + 0.5);
  set_line_style(tile.square->GetProperty(), theme_.muted, 1.0);
  const RgbF& text = tile.active ? theme_.text : theme_.muted;
  set_text_style(tile.title->GetTextProperty(), text, title_font_size());
  tile.title->GetTextProperty()->BoldOn();
  set_text_style(tile.value->GetTextProperty(), text, value_font_size());
}

void BasisTiles::update(BasisKind kind, const TaylorTerms& flow, double radius_px, double amount) {
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
    const double scale =
        sign * std::clamp(amount, 0.0, 1.0) * kMaxShift * unit_normaliser(term.unit);
    vtkPolyDataMapper::SafeDownCast(tile.grid->GetMapper())
        ->SetInputData(polylines(deformed_grid(term.unit, scale)));
    tile.title->SetInput(term.symbol.c_str());
    const std::string shown =
        tile.active ? QString::number(value, 'g', 3).toStdString() + " " + order_unit(term.order)
                    : std::string("0 (zero)");
    tile.value->SetInput(shown.c_str());
    style_tile(tile);
  }
}

double BasisTiles::smallest_text_px() const {
  int points = tiles_.front().title->GetTextProperty()->GetFontSize();
  for (const Tile& tile : tiles_) {
    points = std::min({points, tile.title->GetTextProperty()->GetFontSize(),
                       tile.value->GetTextProperty()->GetFontSize()});
  }
  return font_points_to_px(points, window_);
}

void BasisTiles::fit_cameras() {
  const int* size = window_->GetSize();
  if (size[0] < 1 || size[1] < 1) return;
  const double aspect = (static_cast<double>(size[0]) / kColumns) / (size[1] / 3.0);
  const double scale = std::max(kHalfView, kHalfView / aspect);
  for (Tile& tile : tiles_) tile.renderer->GetActiveCamera()->SetParallelScale(scale);
}

void BasisTiles::on_render_start(vtkObject*, unsigned long, void* self, void*) {
  static_cast<BasisTiles*>(self)->fit_cameras();
}

}  // namespace oflab
