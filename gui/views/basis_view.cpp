#include "views/basis_view.h"

#include <QCheckBox>
#include <QComboBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSlider>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "adapters/paint_helpers.h"
#include "display/flow_parts.h"
#include "models/scene_model.h"
#include "models/window_model.h"
#include "scene/view_culling.h"
#include "views/basis_tiles.h"
#include "views/explorer_panel.h"
#include "views/image_canvas.h"

namespace oflab {
namespace {

constexpr double kPhaseStep = 2.0 * 3.14159265358979323846 / 48.0;  // 48 steps per cycle
constexpr int kTimerMs = 40;

}  // namespace

BasisView::BasisView(WindowModel* window, QWidget* parent)
    : ViewPage(parent), window_(window), model_(window->scene()) {
  setObjectName(QStringLiteral("basis_view"));
  canvas_ = new ImageCanvas(this);
  canvas_->setObjectName(QStringLiteral("basis_canvas"));
  tiles_ = std::make_unique<BasisTiles>();
  timer_ = new QTimer(this);
  timer_->setInterval(kTimerMs);
  connect(timer_, &QTimer::timeout, this, &BasisView::step_animation);

  summary_ = new QLabel(this);
  summary_->setWordWrap(true);
  explorer_ = new ExplorerPanel(window_, this);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(2, 2, 2, 2);
  layout->addWidget(make_option_bar());
  // The explorer's dials down the left, its deformation above the gallery and its worlds down
  // the right, tall enough for the two futures side by side (the explorer's widgets are
  // hidden without it, and the gallery then spans the whole body: show_explorer).
  body_ = new QGridLayout;
  body_->addWidget(explorer_->dials(), 0, 0, 2, 1);
  body_->addWidget(explorer_->deformation(), 0, 1);
  body_->addWidget(explorer_->worlds(), 0, 2, 2, 1);
  body_->addWidget(canvas_, 1, 1, 1, 2);
  body_->setColumnStretch(1, 3);
  body_->setColumnStretch(2, 2);
  layout->addLayout(body_, 1);
  layout->addWidget(summary_);
  connect(model_, &SceneModel::scene_changed, this, [this] {
    if (explorer_shown()) explorer_->refresh(isVisible());  // the camera's size and focus
    refresh();
  });
  connect(window_, &WindowModel::basis_changed, this, &BasisView::show_basis);
  connect(window_, &WindowModel::explorer_changed, this, &BasisView::show_explorer);
  show_explorer();
  show_basis();
  connect(canvas_, &ImageCanvas::resized, this, [this] {
    if (isVisible()) paint_canvas();
  });
}

BasisView::~BasisView() = default;

QWidget* BasisView::make_option_bar() {
  auto* bar = new QWidget(this);
  auto* row = new QHBoxLayout(bar);
  row->setContentsMargins(0, 0, 0, 0);
  row->addWidget(new QLabel(tr("Basis:"), bar));
  basis_box_ = new QComboBox(bar);
  basis_box_->setObjectName(QStringLiteral("gallery_basis"));
  for (int k = 0; k < kBasisKindCount; ++k) {
    basis_box_->addItem(QString::fromUtf8(basis_title(static_cast<BasisKind>(k))));
  }
  basis_box_->setCurrentIndex(static_cast<int>(BasisKind::kPlanar));
  row->addWidget(basis_box_);
  row->addWidget(new QLabel(tr("Amount:"), bar));
  amount_slider_ = new QSlider(Qt::Horizontal, bar);
  amount_slider_->setObjectName(QStringLiteral("gallery_amount"));
  amount_slider_->setRange(0, 100);
  amount_slider_->setValue(60);
  amount_slider_->setMinimumWidth(160);
  row->addWidget(amount_slider_);
  play_box_ = new QCheckBox(tr("Play"), bar);
  play_box_->setObjectName(QStringLiteral("gallery_play"));
  row->addWidget(play_box_);
  explore_box_ = new QCheckBox(tr("Explore"), bar);
  explore_box_->setObjectName(QStringLiteral("basis_explore"));
  explore_box_->setToolTip(
      tr("Set the eight planar terms by hand and see every plane and motion that makes them"));
  row->addWidget(explore_box_);
  row->addStretch(1);
  basis_box_->setToolTip(
      tr("The basis the flow's Taylor terms are shown in (dissertation "
         "Fig. 14-16)"));
  amount_slider_->setToolTip(
      tr("How far each tile deforms its grid, as a fraction of half a "
         "tile"));
  play_box_->setToolTip(tr("Animate every tile from undeformed to the chosen amount and back"));
  connect(basis_box_, QOverload<int>::of(&QComboBox::currentIndexChanged), this,
          [this](int k) { window_->set_basis(static_cast<BasisKind>(k)); });
  connect(amount_slider_, &QSlider::valueChanged, this, [this](int) { refresh(); });
  connect(play_box_, &QCheckBox::toggled, window_, &WindowModel::set_basis_playing);
  connect(explore_box_, &QCheckBox::toggled, window_, &WindowModel::set_basis_explorer);
  return bar;
}

BasisKind BasisView::basis() const { return window_->basis(); }
double BasisView::amount() const { return amount_slider_->value() / 100.0; }
void BasisView::set_amount(double amount) {
  amount_slider_->setValue(static_cast<int>(std::lround(amount * 100.0)));
}
bool BasisView::playing() const { return window_->basis_playing(); }
int BasisView::active_tile_count() const { return tiles_->active_tile_count(); }
double BasisView::tile_active(const std::string& symbol) const {
  const int state = tiles_->tile_state(symbol);
  return state < 0 ? std::nan("") : double(state);
}
QString BasisView::summary() const { return summary_->text(); }

void BasisView::show_basis() {
  const bool playing = window_->basis_playing();
  {
    const QSignalBlocker block1(play_box_), block2(basis_box_);
    play_box_->setChecked(playing);
    basis_box_->setCurrentIndex(static_cast<int>(window_->basis()));
  }
  if (playing && !external_clock_) {
    timer_->start();
  } else {
    timer_->stop();
  }
  if (!playing) phase_ = 3.14159265358979323846;  // paused: show the full amount
  refresh();
}

void BasisView::set_external_clock(bool on) {
  external_clock_ = on;
  explorer_->set_external_clock(on);
  show_basis();
}

bool BasisView::explorer_shown() const { return window_->basis_explorer(); }

std::vector<QString> BasisView::text_problems() const {
  return explorer_shown() ? explorer_->text_problems() : std::vector<QString>{};
}

void BasisView::show_explorer() {
  const bool on = window_->basis_explorer();
  {
    const QSignalBlocker block(explore_box_);
    explore_box_->setChecked(on);
  }
  basis_box_->setEnabled(!on);  // the explorer dials the planar basis
  explorer_->dials()->setVisible(on);
  explorer_->deformation()->setVisible(on);
  explorer_->worlds()->setVisible(on);
  body_->setRowStretch(0, on ? 3 : 0);
  body_->setRowStretch(1, 2);
  body_->removeWidget(canvas_);
  body_->addWidget(canvas_, 1, 1, 1, on ? 1 : 2);
  explorer_->refresh(on && isVisible());
  refresh();
}

// Between kLowestShare and all of the amount, never zero: a tile passing through zero
// amplitude looks undeformed, and its term would seem to do nothing.
double BasisView::animated_amount() const {
  constexpr double kLowestShare = 0.35;
  const double swing = 0.5 * (1.0 - std::cos(phase_));  // 0 .. 1
  return amount() * (kLowestShare + (1.0 - kLowestShare) * swing);
}

int BasisView::value_font_size() const { return tiles_->value_font_size(); }

void BasisView::step_animation() {
  phase_ += kPhaseStep;
  if (explorer_shown()) explorer_->step_futures();
  refresh();
}

void BasisView::update_tiles() {
  const PlaneScene& scene = model_->scene();
  const double radius = 0.5 * std::hypot(scene.camera.width, scene.camera.height);
  if (explorer_shown()) {
    update_explorer_tiles(radius);
    return;
  }
  const FlowContext context =
      make_flow_context(scene.camera, model_->current_pose(), model_->current_motion());
  tiles_->update(basis(), context.terms, radius, animated_amount(), amount());
  int second_order_active = 0;
  const std::vector<BasisTerm> terms = basis_terms(basis());
  for (const BasisTerm& term : terms) {
    if (term.order == 2 && !is_negligible(2, term.coefficient(context.terms), radius)) {
      ++second_order_active;
    }
  }
  QString outside;
  if (!plane_meets_image(scene.camera, context.pose, 1e-3)) {
    outside =
        tr("The plane is outside the image: these are the terms of its plane extended "
           "beyond the picture, not of anything seen. ");
  }
  summary_->setText(outside +
                    tr("%1: %2 of 12 terms are non-zero for the current motion, %3 of the 6 "
                       "second-order ones. Grey tiles are terms this flow does not excite.")
                        .arg(QString::fromUtf8(basis_title(basis())))
                        .arg(tiles_->active_tile_count())
                        .arg(second_order_active));
  dirty_ = false;
}

// The planar gallery of the explorer's terms: a tile lights up while its term is dialled.
void BasisView::update_explorer_tiles(double radius) {
  const TaylorTerms terms = taylor_terms(explorer_coefficients(window_->explorer_terms()));
  tiles_->update(BasisKind::kPlanar, terms, radius, animated_amount(), amount());
  summary_->setText(tr("Explorer: %1 of the 8 planar terms are dialled; their tiles in the "
                       "gallery light up. The four second-order tiles that no plane makes stay "
                       "grey.")
                        .arg(tiles_->active_tile_count()));
  dirty_ = false;
}

void BasisView::paint_canvas() { canvas_->set_image(tiles_->paint(canvas_->size())); }

void BasisView::refresh() {
  dirty_ = true;
  if (!isVisible()) return;
  update_tiles();
  paint_canvas();
}

void BasisView::showEvent(QShowEvent* event) {
  ViewPage::showEvent(event);
  if (explorer_shown()) explorer_->refresh(true);
  if (dirty_) refresh();
}

QImage BasisView::render_image() {
  if (dirty_) update_tiles();
  paint_canvas();
  return canvas_->image();
}

double BasisView::drawn_share() {
  render_image();
  return explorer_shown() ? explorer_->deformation_fill() : tiles_->smallest_fill();
}

double BasisView::smallest_text_px() const {
  const double gallery = tiles_->smallest_text_px();
  return explorer_shown() ? std::min(gallery, explorer_->smallest_text_px()) : gallery;
}

void BasisView::set_theme(const ViewTheme& theme) {
  tiles_->set_theme(theme);
  explorer_->set_theme(theme);
  canvas_->set_background(to_qcolor(theme.background));
  refresh();
}

}  // namespace oflab
