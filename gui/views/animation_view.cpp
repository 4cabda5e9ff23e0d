#include "views/animation_view.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QPushButton>
#include <QScrollArea>
#include <QShowEvent>
#include <QTimer>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "adapters/exact_frames.h"
#include "adapters/frame_images.h"
#include "adapters/painted_text.h"
#include "flow/limits.h"
#include "models/animation_model.h"
#include "models/window_model.h"
#include "player/policy_comparison.h"
#include "player/stage_times.h"
#include "scene/scene_animator.h"  // SceneSettings
#include "views/frame_inspector.h"
#include "views/image_canvas.h"
#include "views/panel_captions.h"
#include "views/panel_layout.h"

namespace oflab {

const double AnimationView::kNear = SceneSettings{}.near;

namespace {

// In presentation mode a view shorter than this (a 1366 x 768 projector under a lesson's
// caption) leaves out the engine's two rows of controls and the readout line, so the panels
// keep the height their titles, captions and legends need; pixels.
constexpr int kCompactBelowPx = 700;

// A canvas smaller than this (a view never shown) is painted at kDefaultCanvas instead.
constexpr int kMinCanvasWidth = 200, kMinCanvasHeight = 120;
const QSize kDefaultCanvas(1280, 640);

QColor qcolor(const RgbF& c) { return QColor::fromRgbF(c[0], c[1], c[2]); }

}  // namespace

AnimationView::AnimationView(WindowModel* window, QWidget* parent)
    : ViewPage(parent),
      window_(window),
      model_(window->animation()),
      comparison_(&window->comparison()),
      exact_kind_(find_exact_renderer(window->exact_renderer())),
      theme_(view_theme(false)) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(2, 2, 2, 2);
  controls_ = new AnimationControls(this);
  layout->addWidget(controls_);
  layout->addWidget(make_panels(), 1);
  show_model_state();
  blink_timer_ = new QTimer(this);
  blink_timer_->setInterval(kBlinkIntervalMs);
  connect(blink_timer_, &QTimer::timeout, this, [this] { set_blink_phase(!blink_phase_); });
  connect(model_, &AnimationModel::frame_changed, this, &AnimationView::refresh);
  connect(model_, &AnimationModel::source_changed, this, [this] {
    exact_.reset();
    exact_frame_index_ = -1;
    fit_known_ = false;
    show_model_state();
    refresh();
  });
  // A refused edit leaves the model as it was: show that again.
  connect(model_, &AnimationModel::input_rejected, this, &AnimationView::show_model_state);
  connect(controls_, &AnimationControls::settings_edited, this,
          [this] { model_->set_settings(controls_->settings()); });
  connect(controls_, &AnimationControls::display_edited, this,
          [this] { window_->set_panel_display(controls_->display()); });
  connect(controls_, &AnimationControls::source_edited, this,
          [this] { model_->set_source(controls_->source()); });
  connect(controls_, &AnimationControls::compared_edited, this, [this] {
    std::vector<std::string> names;
    for (const ReusePolicy* policy : controls_->compared()) names.push_back(policy->name);
    if (!window_->set_compared(names)) show_panels();
  });
  connect(controls_, &AnimationControls::refused, window_, &WindowModel::reject);
  connect(window_, &WindowModel::panels_changed, this, &AnimationView::show_panels);
  show_panels();
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
  row->addWidget(canvas_, 1);
  row->addWidget(make_inspector(box));
  layout->addLayout(row, 1);
  auto* bottom = new QHBoxLayout;
  readout_ = new QLabel(tr("Move the mouse over the frames for a readout."), box);
  readout_->setObjectName(QStringLiteral("pixel_readout"));
  // The readout has a row of its own, wrapped, so no control beside it cuts it; it never
  // sets the window's width.
  readout_->setWordWrap(true);
  readout_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Minimum);
  make_zoom_box(box);
  auto* fit = new QPushButton(tr("Fit"), box);
  fit->setToolTip(tr("Zoom to fit what the framing frames on every panel"));
  layout->addWidget(readout_);
  bottom->addStretch(1);
  bottom->addWidget(new QLabel(tr("Exact"), box));
  bottom->addWidget(make_exact_box(box));
  bottom->addWidget(new QLabel(tr("Framing"), box));
  bottom->addWidget(make_framing_box(box));
  bottom->addWidget(new QLabel(tr("Zoom"), box));
  bottom->addWidget(zoom_box_);
  bottom->addWidget(fit);
  layout->addLayout(bottom);
  connect_canvas();
  connect(fit, &QPushButton::clicked, this, [this] { window_->set_zoom(1.0); });
  return box;
}

QScrollArea* AnimationView::make_inspector(QWidget* parent) {
  inspector_ = new QLabel(parent);
  inspector_->setObjectName(QStringLiteral("frame_inspector"));
  inspector_->setWordWrap(true);
  inspector_->setAlignment(Qt::AlignTop | Qt::AlignLeft);
  inspector_->setTextFormat(Qt::RichText);
  // In a scroll area of fixed width: the new text of every frame then lays out the label
  // alone, not the whole window (a word-wrapped label's height changes with its text, and
  // relaying the window out took a tenth of a frame).
  inspector_area_ = new QScrollArea(parent);
  inspector_area_->setWidget(inspector_);
  inspector_area_->setWidgetResizable(true);
  inspector_area_->setFrameShape(QFrame::NoFrame);
  inspector_area_->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  inspector_area_->setFixedWidth(260);
  return inspector_area_;
}

QDoubleSpinBox* AnimationView::make_zoom_box(QWidget* parent) {
  zoom_box_ = new QDoubleSpinBox(parent);
  zoom_box_->setObjectName(QStringLiteral("animation_zoom"));
  // Wider than the zoom's limit, so a typed value out of range is refused by the model with a
  // message, not cut silently; applied when typing ends.
  zoom_box_->setRange(0.0, 1000.0);
  zoom_box_->setKeyboardTracking(false);
  zoom_box_->setSingleStep(0.25);
  zoom_box_->setValue(window_->zoom());
  zoom_box_->setSuffix(QStringLiteral(" x"));
  zoom_box_->setToolTip(
      tr("Zoom of every panel; 1 fits what the framing frames (mouse wheel "
         "over the panels)"));
  connect(zoom_box_, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this, [this](double z) {
    if (!window_->set_zoom(z)) show_panels();  // refused: the box shows the model's zoom
  });
  return zoom_box_;
}

void AnimationView::connect_canvas() {
  connect(canvas_, &ImageCanvas::hovered, this, &AnimationView::show_readout);
  connect(canvas_, &ImageCanvas::wheel_turned, this, [this](double notches) {
    // The wheel stops at the ends of the range (a gesture, not a typed value).
    const double zoom = window_->zoom() * std::pow(kWheelZoomStep, notches);
    window_->set_zoom(std::clamp(zoom, limits::kZoom.minimum, limits::kZoom.maximum));
  });
  connect(canvas_, &ImageCanvas::resized, this, &AnimationView::refresh);
}

QComboBox* AnimationView::make_exact_box(QWidget* parent) {
  exact_box_ = new QComboBox(parent);
  exact_box_->setObjectName(QStringLiteral("exact_renderer"));
  for (const ExactRendererKind& kind : exact_renderers()) {
    exact_box_->addItem(QString::fromStdString(kind.label));
  }
  exact_box_->setToolTip(
      tr("Who draws the exact panel: core's exact warp of the scene (the "
         "engine's own re-render, with its content) or VTK's OpenGL "
         "pipeline, an independent renderer that draws textures only"));
  connect(exact_box_, QOverload<int>::of(&QComboBox::activated), this, [this](int index) {
    window_->set_exact_renderer(exact_renderers().at(size_t(index)).name);
  });
  return exact_box_;
}

QComboBox* AnimationView::make_framing_box(QWidget* parent) {
  framing_box_ = new QComboBox(parent);
  framing_box_->setObjectName(QStringLiteral("animation_framing"));
  framing_box_->addItems(QString::fromStdString(panel_framing_names(",")).split(','));
  framing_box_->setToolTip(
      tr("What every panel frames, one zoom for all: loop, the plane's whole motion; content, "
         "what is drawn around the frame shown, so a far plane fills its panel; auto, content "
         "in presentation mode. Display only: no error figure changes"));
  connect(framing_box_, QOverload<int>::of(&QComboBox::activated), this, [this](int index) {
    PanelFraming framing = PanelFraming::kAuto;
    if (parse_panel_framing(framing_box_->itemText(index).toStdString(), &framing))
      window_->set_framing(framing);
  });
  return framing_box_;
}

PanelDisplay AnimationView::display() const { return window_->panel_display(); }

void AnimationView::show_panels() {
  const ExactRendererKind* kind = find_exact_renderer(window_->exact_renderer());
  if (kind != exact_kind_) {
    exact_kind_ = kind;
    exact_.reset();
    exact_frame_index_ = -1;
  }
  const PanelDisplay display = window_->panel_display();
  if (display != shown_display_) blink_phase_ = false;
  shown_display_ = display;
  {
    const QSignalBlocker block1(exact_box_), block2(zoom_box_), block3(framing_box_);
    exact_box_->setCurrentIndex(int(exact_kind_ - exact_renderers().data()));
    framing_box_->setCurrentText(QString::fromLatin1(panel_framing_name(window_->framing())));
    zoom_box_->setValue(window_->zoom());
  }
  controls_->set_display(display);
  controls_->set_compared(comparison_->policies());
  inspector_area_->setVisible(display != PanelDisplay::kComparison);
  if (display == PanelDisplay::kBlink && !external_clock_) {
    if (!blink_timer_->isActive()) blink_timer_->start();
  } else {
    blink_timer_->stop();
  }
  refresh();
}

void AnimationView::set_blink_phase(bool exact) {
  blink_phase_ = exact;
  refresh();
}

QString AnimationView::scene_panel_note() const { return oflab::scene_panel_note(*model_); }

bool AnimationView::blink_phase_at(int frame, int fps) {
  const int frames_per_phase = std::max(1, int(std::lround(kBlinkIntervalMs * 1e-3 * fps)));
  return (frame / frames_per_phase) % 2 == 1;
}

void AnimationView::set_external_clock(bool on) {
  external_clock_ = on;
  blink_phase_ = false;
  show_panels();
}

void AnimationView::set_theme(const ViewTheme& theme) {
  theme_ = theme;
  canvas_->set_background(qcolor(theme.background));
  QFont font = inspector_->font();
  font.setPixelSize(theme.presentation ? theme.label_size : 12);
  inspector_->setFont(font);
  inspector_area_->setFixedWidth(theme.presentation ? int(380 * theme.scale) : 260);
  show_compact(theme_.presentation && height() < kCompactBelowPx);
  refresh();
}

const Image& AnimationView::engine_image() {
  static const Image kEmpty;
  const Animator* animator = model_->animator();
  return animator ? animator->image() : kEmpty;
}

const Image* AnimationView::compared_exact_frame() {
  const Animator* animator = model_->animator();
  if (!animator || exact_kind_->name != "core" || model_->source_kind().name != "scene" ||
      window_->panel_display() != PanelDisplay::kComparison) {
    return nullptr;
  }
  for (const ComparedRun& run : comparison_->runs()) {
    if (std::string(run.policy->name) == "rerender" && run.animator() &&
        run.animator()->frame() == animator->frame()) {
      return &run.animator()->image();
    }
  }
  return nullptr;
}

const Image& AnimationView::exact_image() {
  const Animator* animator = model_->animator();
  if (const Image* compared = compared_exact_frame()) return *compared;
  if (!animator || exact_frame_index_ == animator->frame()) return exact_frame_;
  try {
    const StageTimer timer(FrameStage::kExactFrame);
    if (!exact_)
      exact_ = exact_kind_->make(animator->scene(), animator->camera(), model_->settings());
    exact_frame_ = exact_->render(animator->view());
  } catch (const std::exception& e) {  // no display for VTK: show the engine alone
    exact_frame_ = Image(animator->camera().width, animator->camera().height);
    readout_->setText(QString::fromStdString(e.what()));
  }
  exact_frame_index_ = animator->frame();
  return exact_frame_;
}

PanelContent AnimationView::engine_panel() {
  double pixels = 0.0, ms = 0.0, warped = 0.0;
  for (const AnimationFrame& f : model_->history()) {
    pixels += double(f.pixels_written);
    warped += double(f.pixels_written - f.pixels_not_warped);
    ms += f.time_ms;
  }
  const std::string title =
      fill_pattern(model_->source_kind().panel_title, model_->settings().policy->name);
  return {QString::fromStdString(title), image_view(engine_image()), model_->animator()->outlines(),
          run_caption(model_->current(), *model_->settings().policy, model_->settings(), pixels, ms,
                      warped)};
}

PanelContent AnimationView::exact_panel() {
  const Animator* animator = model_->animator();
  return {QString::fromStdString(exact_kind_->title),
          image_view(exact_image()),
          {},
          {tr("frame %1 of %2").arg(animator->frame()).arg(animator->frame_count())}};
}

std::vector<PanelContent> AnimationView::comparison_panels() {
  std::vector<PanelContent> shown, heat;
  const Image& exact = exact_image();
  const std::vector<ComparedRun>& runs = comparison_->runs();
  if (heat_maps_.size() < runs.size()) heat_maps_.resize(runs.size());  // no move under `map`
  for (const ComparedRun& run : runs) {
    const QString name = QString::fromLatin1(run.policy->name);
    if (!run.animator()) {
      shown.push_back({name, QImage(), {}, {QString::fromStdString(run.problem)}});
      continue;
    }
    shown.push_back(
        {tr("%1 policy").arg(name), image_view(run.animator()->image()), run.animator()->outlines(),
         run_caption(run.last, *run.policy, model_->settings(), double(run.pixels_written),
                     run.time_ms, double(run.pixels_warped))});
    const HeatMap& map = comparison_heat_map(heat.size(), run, exact);
    QStringList caption = map.agreement;
    caption << sub_pixel_note(run.last);
    if (map.holes >= 0) {
      hole_map_pixels_ += map.holes;
      caption << tr("holes (magenta): %1 px").arg(map.holes);
    }
    heat.push_back({map.holes >= 0 ? tr("%1 - exact, holes").arg(name) : tr("%1 - exact").arg(name),
                    map.image,
                    {},
                    caption});
  }
  shown.push_back(exact_panel());
  shown.insert(shown.end(), heat.begin(), heat.end());
  return shown;
}

std::vector<PanelContent> AnimationView::panels() {
  hole_map_pixels_ = 0;  // only the comparison draws hole maps
  switch (window_->panel_display()) {
    case PanelDisplay::kComparison:
      if (!comparison_->runs().empty()) return comparison_panels();
      break;
    case PanelDisplay::kDifference: {
      if (heat_maps_.empty()) heat_maps_.resize(1);
      HeatMap& map = heat_maps_[0];
      map.animator = nullptr;  // not a compared run's map
      map.blank = false;
      const StageTimer maps(FrameStage::kMaps);
      ++map_passes_;
      QStringList caption = agreement_caption(
          difference_map_and_agreement(engine_image(), exact_image(), kDifferenceScale, map.image));
      caption << sub_pixel_note(model_->current());
      const QString view = affine_view_line(model_->current(), *model_->settings().policy);
      if (!view.isEmpty()) caption << view;
      return {{tr("engine - exact"), map.image, {}, caption}};
    }
    case PanelDisplay::kBlink:
      return {blink_phase_ ? exact_panel() : engine_panel()};
    default:
      break;
  }
  return {engine_panel(), exact_panel()};
}

QImage AnimationView::compose(const QSize& size) {
  // Two reused images in turn: the canvas still shows the other one, so painting this one
  // neither copies nor allocates (a new image of the view's size each frame cost page faults).
  QImage& canvas = buffers_[next_buffer_];
  next_buffer_ = 1 - next_buffer_;
  if (canvas.size() != size) canvas = QImage(size, QImage::Format_RGB32);
  canvas.fill(qcolor(theme_.background));
  QPainter painter(&canvas);
  paint_canvas(painter, size);
  painter.end();  // a QImage copied while a painter is active on it is copied deeply
  return canvas;
}

QSize AnimationView::canvas_size() const {
  const QSize size = canvas_->size();
  return size.width() < kMinCanvasWidth || size.height() < kMinCanvasHeight ? kDefaultCanvas : size;
}

std::vector<PaintedText> AnimationView::painted_texts() {
  const QSize size = canvas_size();
  return record_painted_text(size, [&](QPainter& painter) { paint_canvas(painter, size); });
}

std::vector<QString> AnimationView::text_problems() {
  return oflab::text_problems(painted_texts(), canvas_size());
}

void AnimationView::paint_canvas(QPainter& painter, const QSize& size) {
  panel_rects_.clear();
  const Animator* animator = model_->animator();
  if (!animator) return;
  const std::vector<PanelContent> contents = panels();
  const QRectF content = framed_content();
  // The comparison puts the heat maps in a second row under their policies, unless every
  // panel in one row draws the framed content larger with every text whole (a wide canvas
  // under a lesson's caption leaves two rows of flat images); the other layouts have one row.
  const bool comparing =
      window_->panel_display() == PanelDisplay::kComparison && contents.size() > 2;
  PanelPlan plan = plan_panels(contents, size, comparing);
  if (comparing) {
    PanelPlan strip = plan_panels(contents, size, false);
    if (texts_fit(strip) && content_scale(strip, content) > content_scale(plan, content))
      plan = std::move(strip);
  }
  lines_ = plan.lines;
  const Camera& camera = animator->camera();
  shown_frame_ = panel_frame(
      content, QSizeF(camera.width, camera.height),
      hugging_aspect(plan.cells.front().image.width() / plan.cells.front().image.height(),
                     frame_box(content), window_->zoom()),
      window_->zoom());
  const auto outlines = exact_outlines(animator->scene(), animator->view(), camera, kNear);
  paint_panels(painter, plan, outlines);
  const bool levels = std::any_of(contents.begin(), contents.end(),
                                  [](const PanelContent& c) { return !c.levels.empty(); });
  paint_band(painter, plan.legends, levels,
             comparing || window_->panel_display() == PanelDisplay::kDifference);
}

void AnimationView::refresh() {
  if (!isVisible()) return;
  render_image();
}

QImage AnimationView::render_image() {
  const StageTimer drawing(FrameStage::kDrawing);
  if (model_->animator() && window_->panel_display() != PanelDisplay::kComparison) {
    const StageTimer text(FrameStage::kText);
    inspector_->setText(explain_frame(model_->current(), model_->settings()));
  }
  const QImage image = compose(canvas_size());
  canvas_->set_image(image);
  return image;
}

void AnimationView::resizeEvent(QResizeEvent* event) {
  ViewPage::resizeEvent(event);
  show_compact(theme_.presentation && height() < kCompactBelowPx);
}

void AnimationView::show_compact(bool compact) {
  controls_->set_engine_rows_shown(!compact);
  readout_->setVisible(!compact);
}

void AnimationView::showEvent(QShowEvent* event) {
  ViewPage::showEvent(event);
  refresh();
}

void AnimationView::show_readout(QPointF pixel) {
  const Animator* animator = model_->animator();
  if (!animator) return;
  for (const QRectF& r : panel_rects_) {
    if (!r.contains(pixel)) continue;
    const QPointF p = frame_to_panel(shown_frame_, r).inverted().map(pixel);
    readout_->setText(pixel_readout(*animator, Vec2(p.x(), p.y()), exact_image()));
    return;
  }
}

}  // namespace oflab
