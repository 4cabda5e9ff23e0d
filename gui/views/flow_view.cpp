#include "views/flow_view.h"

#include <QCheckBox>
#include <QComboBox>
#include <QGridLayout>
#include <QLabel>
#include <QSplitter>
#include <QVBoxLayout>
#include <cmath>

#include "adapters/paint_helpers.h"
#include "models/scene_model.h"
#include "models/window_model.h"
#include "player/stage_times.h"
#include "views/coefficient_table.h"
#include "views/image_canvas.h"

namespace oflab {

FlowView::FlowView(WindowModel* window, QWidget* parent)
    : ViewPage(parent), window_(window), model_(window->scene()) {
  setObjectName(QStringLiteral("flow_view"));
  canvas_ = new ImageCanvas(this);
  canvas_->setObjectName(QStringLiteral("flow_canvas"));
  renderer_ = std::make_unique<FlowRenderer>();
  renderer_->set_texture(model_->texture());
  painter_.setMaxThreadCount(1);
  painter_.setExpiryTimeout(-1);
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
  connect(window_, &WindowModel::flow_display_changed, this, &FlowView::show_display);
  connect(model_, &SceneModel::texture_changed, this, [this] {
    renderer().set_texture(model_->texture());
    refresh();
  });
  connect(canvas_, &ImageCanvas::resized, this, [this] {
    if (isVisible()) paint_canvas();
  });
}

FlowView::~FlowView() { renderer(); }  // the painting thread done with it

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
  int cell = 0;
  for (const FlowDrawOption& option : flow_draw_options()) {
    auto* box = new QCheckBox(tr(option.label), bar);
    box->setObjectName(QStringLiteral("flow_draw_%1").arg(option.key));
    box->setToolTip(tr(option.tooltip));
    grid->addWidget(box, 2 + cell / 2, cell % 2);
    ++cell;
    draw_boxes_.push_back(box);
    connect(box, &QCheckBox::toggled, this, [this, member = option.member](bool on) {
      FlowDisplay d = window_->flow_display();
      d.*member = on;
      window_->set_flow_display(d);
    });
  }
  connect(part_box_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this](int k) {
    FlowDisplay d = window_->flow_display();
    d.part = static_cast<FlowPart>(k);
    window_->set_flow_display(d);
  });
  show_display();
  return bar;
}

FlowDisplay FlowView::display() const { return window_->flow_display(); }

void FlowView::show_display() {
  const FlowDisplay& d = window_->flow_display();
  {
    const QSignalBlocker block(part_box_);
    part_box_->setCurrentIndex(static_cast<int>(d.part));
  }
  for (size_t k = 0; k < draw_boxes_.size(); ++k) {
    const QSignalBlocker block(draw_boxes_[k]);
    draw_boxes_[k]->setChecked(d.*flow_draw_options()[k].member);
  }
  refresh();
}

void FlowView::update_scene() {
  const PlaneScene& scene = model_->scene();
  const FlowContext context =
      make_flow_context(scene.camera, model_->current_pose(), model_->current_motion());
  QString frame = tr("frame %1, t = %2 s").arg(model_->frame()).arg(model_->time(), 0, 'f', 2);
  if (!model_->script_name().isEmpty()) frame.prepend(tr("script %1, ").arg(model_->script_name()));
  {
    const StageTimer drawing(FrameStage::kDrawing);  // the streamlines and arrows
    renderer().update(context, display(), frame);
  }
  const StageTimer text(FrameStage::kText);  // the side table's numbers
  table_->show_terms(context.terms, 0.5 * std::hypot(scene.camera.width, scene.camera.height));
  const bool outside = !renderer().plane_in_image();
  if (outside_note_->isVisibleTo(this) != outside) outside_note_->setVisible(outside);
  table_->setEnabled(!outside);
  dirty_ = false;
}

double FlowView::plane_share() {
  render_image();
  return renderer().plane_share(canvas_->size());
}

void FlowView::paint_canvas() {
  const StageTimer drawing(FrameStage::kDrawing);
  canvas_->set_image(renderer().paint(canvas_->size()));
}

void FlowView::paint_canvas_later() {
  FlowRenderer* renderer = &this->renderer();
  auto promise = std::make_shared<std::promise<QImage>>();
  painting_ = promise->get_future().share();
  const QSize size = canvas_->size();
  painter_.start([promise, renderer, size] {
    try {
      promise->set_value(renderer->paint(size));
    } catch (...) {
      promise->set_exception(std::current_exception());
    }
  });
  canvas_->set_pending_image(painting_);
}

FlowRenderer& FlowView::renderer() const {
  if (painting_.valid()) {
    const StageTimer drawing(FrameStage::kDrawing);  // the rest of the painting thread's work
    painting_.wait();
    painting_ = std::shared_future<QImage>();
  }
  return *renderer_;
}

void FlowView::refresh() {
  dirty_ = true;
  if (!isVisible()) return;
  update_scene();
  paint_canvas_later();
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

double FlowView::smallest_text_px() const { return renderer().smallest_text_px(); }

void FlowView::set_theme(const ViewTheme& theme) {
  renderer().set_theme(theme);
  canvas_->set_background(to_qcolor(theme.background));
  refresh();
}

}  // namespace oflab
