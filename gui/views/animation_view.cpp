#include "views/animation_view.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QShowEvent>
#include <QTimer>
#include <QVBoxLayout>

#include "adapters/frame_images.h"
#include "models/animation_model.h"
#include "runs/vtk_scene_renderer.h"
#include "views/frame_inspector.h"
#include "views/image_canvas.h"

namespace oflab {
namespace {

constexpr int kPanelGap = 16;          // pixels between the two panels
constexpr int kDifferenceScale = 128;  // grey levels at the top of the heat map's colour bar
constexpr double kNear = 0.05;         // near plane of the exact render (SceneSettings::near)
// Panel text in presentation mode, times the normal size: legible from the back of a
// classroom when the panels are scaled down to fit a 1920 x 1080 window.
constexpr double kPresentationText = 2.0;

QColor qcolor(const RgbF& c) { return QColor::fromRgbF(c[0], c[1], c[2]); }

}  // namespace

AnimationView::AnimationView(AnimationModel* model, QWidget* parent)
    : ViewPage(parent), model_(model), theme_(view_theme(false)) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(2, 2, 2, 2);
  controls_ = new AnimationControls(this);
  layout->addWidget(controls_);
  layout->addWidget(make_panels(), 1);
  show_model_state();
  blink_timer_ = new QTimer(this);
  blink_timer_->setInterval(500);
  connect(blink_timer_, &QTimer::timeout, this, [this] { set_blink_phase(!blink_phase_); });
  connect(model_, &AnimationModel::frame_changed, this, &AnimationView::refresh);
  connect(model_, &AnimationModel::source_changed, this, [this] {
    exact_.reset();
    exact_frame_index_ = -1;
    show_model_state();
    refresh();
  });
  // A refused edit leaves the model as it was: show that again.
  connect(model_, &AnimationModel::input_rejected, this, &AnimationView::show_model_state);
  connect(controls_, &AnimationControls::settings_edited, this,
          [this] { model_->set_settings(controls_->settings()); });
  connect(controls_, &AnimationControls::display_edited, this,
          [this] { set_display(controls_->display()); });
  connect(controls_, &AnimationControls::source_edited, this,
          [this] { model_->set_source(controls_->source()); });
}

AnimationView::~AnimationView() = default;

void AnimationView::show_model_state() {
  controls_->set_settings(model_->settings());
  controls_->set_source(model_->source());
}

QWidget* AnimationView::make_panels() {
  auto* box = new QWidget(this);
  auto* layout = new QVBoxLayout(box);
  layout->setContentsMargins(0, 0, 0, 0);
  auto* row = new QHBoxLayout;
  canvas_ = new ImageCanvas(box);
  canvas_->setObjectName(QStringLiteral("animation_canvas"));
  inspector_ = new QLabel(box);
  inspector_->setObjectName(QStringLiteral("frame_inspector"));
  inspector_->setWordWrap(true);
  inspector_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
  inspector_->setTextFormat(Qt::RichText);
  inspector_->setFixedWidth(260);
  row->addWidget(canvas_, 1);
  row->addWidget(inspector_);
  layout->addLayout(row, 1);
  readout_ = new QLabel(tr("Move the mouse over the frames for a readout."), box);
  readout_->setObjectName(QStringLiteral("pixel_readout"));
  layout->addWidget(readout_);
  connect(canvas_, &ImageCanvas::hovered, this, &AnimationView::show_readout);
  return box;
}

void AnimationView::set_display(PanelDisplay display) {
  display_ = display;
  controls_->set_display(display);
  blink_phase_ = false;
  if (display == PanelDisplay::kBlink && !external_clock_) {
    blink_timer_->start();
  } else {
    blink_timer_->stop();
  }
  refresh();
}

void AnimationView::set_blink_phase(bool exact) {
  blink_phase_ = exact;
  if (isVisible()) canvas_->set_image(compose());
}

void AnimationView::set_external_clock(bool on) {
  external_clock_ = on;
  set_display(display_);
}

void AnimationView::set_theme(const ViewTheme& theme) {
  theme_ = theme;
  canvas_->set_background(qcolor(theme.background));
  QFont font = inspector_->font();
  font.setPixelSize(theme.presentation ? theme.label_size : 12);
  inspector_->setFont(font);
  inspector_->setFixedWidth(theme.presentation ? 380 : 260);
  refresh();
}

const Image& AnimationView::engine_image() {
  static const Image kEmpty;
  const Animator* animator = model_->animator();
  return animator ? animator->image() : kEmpty;
}

const Image& AnimationView::exact_image() {
  const Animator* animator = model_->animator();
  if (!animator || exact_frame_index_ == animator->frame()) return exact_frame_;
  try {
    if (!exact_) exact_ = std::make_unique<VtkSceneRenderer>(animator->scene(), animator->camera(), kNear);
    exact_->render(animator->view());
    exact_frame_ = exact_->image();
  } catch (const std::runtime_error& e) {  // no display for VTK: show the engine alone
    exact_frame_ = Image(animator->camera().width, animator->camera().height);
    readout_->setText(QString::fromStdString(e.what()));
  }
  exact_frame_index_ = animator->frame();
  return exact_frame_;
}

QImage AnimationView::panel(bool exact) {
  const QColor text = qcolor(theme_.text);
  const double text_scale = theme_.presentation ? kPresentationText : 1.0;
  QImage image = flatten_image(exact ? exact_image() : engine_image(), qcolor(theme_.background));
  if (exact) {
    draw_panel_title(image, tr("exact projection (VTK)"), text, text_scale);
    return image;
  }
  draw_level_overlay(image, model_->animator()->outlines(), model_->current().levels, text,
                     theme_.line_width + 1.0, text_scale);
  const std::string title =
      fill_pattern(model_->source_kind().panel_title, model_->settings().policy->name);
  draw_panel_title(image, QString::fromStdString(title), text, text_scale);
  return image;
}

QImage AnimationView::compose() {
  if (!model_->animator()) return QImage();
  panel_split_ = 0.0;
  if (display_ == PanelDisplay::kDifference) {
    return difference_heat_map(engine_image(), exact_image(), kDifferenceScale, qcolor(theme_.text));
  }
  if (display_ == PanelDisplay::kBlink) return panel(blink_phase_);
  const QImage left = panel(false);
  const QImage right = panel(true);
  QImage both(left.width() + kPanelGap + right.width(), left.height(), QImage::Format_RGB32);
  both.fill(qcolor(theme_.background).darker(130));
  QPainter painter(&both);
  painter.drawImage(0, 0, left);
  painter.drawImage(left.width() + kPanelGap, 0, right);
  panel_split_ = left.width() + kPanelGap;
  return both;
}

void AnimationView::refresh() {
  if (!isVisible()) return;
  render_image();
}

QImage AnimationView::render_image() {
  if (model_->animator()) inspector_->setText(explain_frame(model_->current(), model_->settings()));
  const QImage image = compose();
  canvas_->set_image(image);
  return image;
}

void AnimationView::showEvent(QShowEvent* event) {
  ViewPage::showEvent(event);
  refresh();
}

void AnimationView::show_readout(QPointF pixel) {
  const Animator* animator = model_->animator();
  if (!animator) return;
  double x = pixel.x();
  if (panel_split_ > 0.0 && x >= panel_split_) x -= panel_split_;
  readout_->setText(pixel_readout(*animator, Vec2(x, pixel.y()), exact_image()));
}

}  // namespace oflab
