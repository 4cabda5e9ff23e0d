#include "views/flow_view.h"

#include <QCheckBox>
#include <QComboBox>
#include <QGridLayout>
#include <QLabel>
#include <QSplitter>
#include <QVBoxLayout>
#include <cmath>

#include "models/scene_model.h"
#include "views/coefficient_table.h"
#include "views/image_canvas.h"
#include "views/paint_helpers.h"

namespace oflab {

FlowView::FlowView(SceneModel* model, QWidget* parent) : ViewPage(parent), model_(model) {
  setObjectName(QStringLiteral("flow_view"));
  canvas_ = new ImageCanvas(this);
  canvas_->setObjectName(QStringLiteral("flow_canvas"));
  renderer_ = std::make_unique<FlowRenderer>();
  renderer_->set_texture(model_->texture());
  table_ = new CoefficientTable(this);

  // Side panel: what to draw above the coefficient table, so the options never widen the
  // window (presentation mode doubles their size).
  auto* side = new QWidget(this);
  auto* side_layout = new QVBoxLayout(side);
  side_layout->setContentsMargins(4, 0, 0, 0);
  side_layout->addWidget(make_option_bar());
  outside_note_ =
      new QLabel(tr("The plane is outside the image. The terms below are those of its plane "
                    "extended beyond the picture, not of anything seen."),
                 side);
  outside_note_->setObjectName(QStringLiteral("flow_outside_note"));
  outside_note_->setWordWrap(true);
  outside_note_->setStyleSheet(
      QStringLiteral("QLabel { color: white; background: #D55E00; "
                     "padding: 4px; }"));
  outside_note_->hide();
  side_layout->addWidget(outside_note_);
  side_layout->addWidget(table_, 1);
  auto* splitter = new QSplitter(Qt::Horizontal, this);
  splitter->addWidget(canvas_);
  splitter->addWidget(side);
  splitter->setStretchFactor(0, 1);
  splitter->setStretchFactor(1, 0);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(2, 2, 2, 2);
  layout->addWidget(splitter, 1);

  connect(model_, &SceneModel::scene_changed, this, &FlowView::refresh);
  connect(model_, &SceneModel::texture_changed, this, [this] {
    renderer_->set_texture(model_->texture());
    refresh();
  });
  connect(canvas_, &ImageCanvas::resized, this, [this] {
    if (isVisible()) paint_canvas();
  });
}

FlowView::~FlowView() = default;

QWidget* FlowView::make_option_bar() {
  auto* bar = new QWidget(this);
  auto* grid = new QGridLayout(bar);
  grid->setContentsMargins(0, 0, 0, 0);
  grid->addWidget(new QLabel(tr("Show:"), bar), 0, 0, 1, 2);
  part_box_ = new QComboBox(bar);
  part_box_->setObjectName(QStringLiteral("flow_part"));
  for (int k = 0; k < kFlowPartCount; ++k) {
    part_box_->addItem(QString::fromUtf8(flow_part_title(static_cast<FlowPart>(k))));
  }
  part_box_->setToolTip(
      tr("Which part of the flow to draw: the exact flow, one order of its "
         "Taylor expansion, or a residual against an approximation"));
  grid->addWidget(part_box_, 1, 0, 1, 2);
  arrows_box_ = new QCheckBox(tr("Arrows"), bar);
  streamlines_box_ = new QCheckBox(tr("Streamlines"), bar);
  wheel_box_ = new QCheckBox(tr("Colour wheel"), bar);
  texture_box_ = new QCheckBox(tr("Texture"), bar);
  zoom_box_ = new QCheckBox(tr("Zoom to plane"), bar);
  common_scale_box_ = new QCheckBox(tr("Common scale"), bar);
  common_scale_box_->setToolTip(
      tr("Draw every part at the full flow's arrow scale, so parts compare by length"));
  zoom_box_->setToolTip(tr("Fit the view to the plane's image instead of the whole image"));
  arrows_box_->setToolTip(
      tr("Arrows of the chosen part of the flow, length in pixels per second "
         "times the arrow scale; colour is the magnitude, px/s"));
  streamlines_box_->setToolTip(tr("Paths a point would follow in the instantaneous field"));
  wheel_box_->setToolTip(
      tr("Colour the plane by the flow: hue is the direction, saturation "
         "the magnitude"));
  texture_box_->setToolTip(tr("Show the plane's texture under the flow"));
  const FlowDisplay defaults;
  arrows_box_->setChecked(defaults.arrows);
  texture_box_->setChecked(defaults.texture);
  zoom_box_->setChecked(defaults.zoom_to_plane);
  common_scale_box_->setChecked(defaults.common_scale);
  int cell = 0;
  for (QCheckBox* box :
       {arrows_box_, streamlines_box_, wheel_box_, texture_box_, zoom_box_, common_scale_box_}) {
    grid->addWidget(box, 2 + cell / 2, cell % 2);
    ++cell;
    connect(box, &QCheckBox::toggled, this, &FlowView::refresh);
  }
  connect(part_box_, QOverload<int>::of(&QComboBox::currentIndexChanged), this,
          [this](int) { refresh(); });
  return bar;
}

FlowDisplay FlowView::display() const {
  FlowDisplay d;
  d.part = static_cast<FlowPart>(part_box_->currentIndex());
  d.arrows = arrows_box_->isChecked();
  d.streamlines = streamlines_box_->isChecked();
  d.colour_wheel = wheel_box_->isChecked();
  d.texture = texture_box_->isChecked();
  d.zoom_to_plane = zoom_box_->isChecked();
  d.common_scale = common_scale_box_->isChecked();
  return d;
}

void FlowView::set_display(const FlowDisplay& d) {
  const QSignalBlocker b1(part_box_), b2(arrows_box_), b3(streamlines_box_), b4(wheel_box_),
      b5(texture_box_), b6(zoom_box_), b7(common_scale_box_);
  part_box_->setCurrentIndex(static_cast<int>(d.part));
  arrows_box_->setChecked(d.arrows);
  streamlines_box_->setChecked(d.streamlines);
  wheel_box_->setChecked(d.colour_wheel);
  texture_box_->setChecked(d.texture);
  zoom_box_->setChecked(d.zoom_to_plane);
  common_scale_box_->setChecked(d.common_scale);
  refresh();
}

void FlowView::update_scene() {
  const PlaneScene& scene = model_->scene();
  const FlowContext context =
      make_flow_context(scene.camera, model_->current_pose(), model_->current_motion());
  QString frame = tr("frame %1, t = %2 s").arg(model_->frame()).arg(model_->time(), 0, 'f', 2);
  if (!model_->script_name().isEmpty()) frame.prepend(tr("script %1, ").arg(model_->script_name()));
  renderer_->update(context, display(), frame);
  table_->show_terms(context.terms, 0.5 * std::hypot(scene.camera.width, scene.camera.height));
  const bool outside = !renderer_->plane_in_image();
  if (outside_note_->isVisibleTo(this) != outside) outside_note_->setVisible(outside);
  table_->setEnabled(!outside);
  dirty_ = false;
}

void FlowView::paint_canvas() { canvas_->set_image(renderer_->paint(canvas_->size())); }

void FlowView::refresh() {
  dirty_ = true;
  if (!isVisible()) return;
  update_scene();
  paint_canvas();
}

void FlowView::showEvent(QShowEvent* event) {
  ViewPage::showEvent(event);
  if (dirty_) refresh();
}

QImage FlowView::render_image() {
  if (dirty_) update_scene();
  paint_canvas();
  return canvas_->image();
}

double FlowView::smallest_text_px() const { return renderer_->smallest_text_px(); }

void FlowView::set_theme(const ViewTheme& theme) {
  renderer_->set_theme(theme);
  canvas_->set_background(to_qcolor(theme.background));
  refresh();
}

}  // namespace oflab
