#include "views/animation_view.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QShowEvent>
#include <QTimer>
#include <QVBoxLayout>
#include <cmath>
#include <cstring>

#include "formats/datasets.h"
#include "formats/scene_file.h"
#include "formats/script_file.h"
#include "formats/viewer_script_file.h"
#include "runs/vtk_scene_renderer.h"
#include "models/animation_session.h"
#include "adapters/frame_images.h"
#include "views/frame_inspector.h"
#include "views/image_canvas.h"
#include "models/scene_model.h"

namespace oflab {
namespace {

constexpr int kPanelGap = 16;          // pixels between the two panels
constexpr int kDifferenceScale = 128;  // grey levels at the top of the heat map's colour bar
constexpr double kNear = 0.05;         // near plane of the exact render (SceneSettings::near)

QColor qcolor(const RgbF& c) { return QColor::fromRgbF(c[0], c[1], c[2]); }

Image image_from_qimage(const QImage& texture) {
  const QImage rgba = texture.convertToFormat(QImage::Format_RGBA8888_Premultiplied);
  Image image(rgba.width(), rgba.height());
  for (int y = 0; y < rgba.height(); ++y) {
    std::memcpy(image.row(y), rgba.constScanLine(y), size_t(rgba.width()) * 4);
  }
  return image;
}

// The source a choice names: the model's plane (kinds "plane" and "script", whose script
// the view has already loaded into the model) or a scene with its viewer script.
AnimationSource load_source(const SourceChoice& choice, const SceneModel& model) {
  AnimationSource source;
  if (choice.kind == "scene") {
    source.scene = std::make_shared<const Scene>(read_scene_file(resolve_scene_path(choice.name)));
    source.viewer = read_viewer_script_file(resolve_viewer_script_path(choice.viewer));
    source.scene_name = choice.name;
    source.script_name = choice.viewer;
  } else {
    source.plane_script = model.as_script();
    source.plane_texture = image_from_qimage(model.texture());
    source.script_name = model.script_name().toStdString();
  }
  const std::string problem = animation_source_problem(source);
  if (!problem.empty()) throw std::runtime_error(problem);
  return source;
}

}  // namespace

AnimationView::AnimationView(SceneModel* model, QWidget* parent)
    : ViewPage(parent), model_(model), theme_(view_theme(false)) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(2, 2, 2, 2);
  controls_ = new AnimationControls(this);
  layout->addWidget(controls_);
  layout->addWidget(make_panels(), 1);
  settings_ = controls_->settings();
  blink_timer_ = new QTimer(this);
  blink_timer_->setInterval(500);
  connect(blink_timer_, &QTimer::timeout, this, [this] { set_blink_phase(!blink_phase_); });
  connect(model_, &SceneModel::scene_changed, this, &AnimationView::refresh);
  connect(model_, &SceneModel::source_changed, this, [this] {
    if (source_.kind != "scene") stale_ = true;
  });
  connect(controls_, &AnimationControls::settings_edited, this,
          [this] { set_settings(controls_->settings()); });
  connect(controls_, &AnimationControls::display_edited, this,
          [this] { set_display(controls_->display()); });
  connect(controls_, &AnimationControls::source_edited, this,
          [this] { set_source(controls_->source()); });
}

AnimationView::~AnimationView() = default;

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

bool AnimationView::rebuild(const SourceChoice& choice, const EngineSettings& settings) {
  try {
    AnimationSource source = load_source(choice, *model_);
    auto session = std::make_unique<AnimationSession>(std::move(source), settings);
    auto exact = std::make_unique<VtkSceneRenderer>(session->reference_scene(),
                                                    session->source().camera(), kNear);
    session_ = std::move(session);
    exact_ = std::move(exact);
    exact_frame_index_ = -1;
    source_ = choice;
    settings_ = settings;
    stale_ = false;
    return true;
  } catch (const std::exception& e) {  // unreadable files, invalid scenes, no display
    emit input_rejected(QString::fromStdString(e.what()));
    return false;
  }
}

bool AnimationView::set_settings(const EngineSettings& settings) {
  for (double t : settings.thresholds) {
    if (!std::isfinite(t) || t < 0.0) {
      emit input_rejected(tr("thresholds must be finite and not negative"));
      controls_->set_settings(settings_);
      return false;
    }
  }
  if (!rebuild(source_, settings)) {
    controls_->set_settings(settings_);
    return false;
  }
  controls_->set_settings(settings_);
  refresh();
  return true;
}

bool AnimationView::set_source(const SourceChoice& choice) {
  const SourceChoice before = source_;
  if (choice.kind == "script") {
    try {
      const MotionScript script = read_script_file(resolve_script_path(choice.name));
      if (!model_->set_script(script, QString::fromStdString(choice.name))) {
        controls_->set_source(before);
        return false;
      }
    } catch (const std::runtime_error& e) {
      emit input_rejected(QString::fromStdString(e.what()));
      controls_->set_source(before);
      return false;
    }
  }
  if (!rebuild(choice, settings_)) {
    controls_->set_source(before);
    return false;
  }
  controls_->set_source(source_);
  model_->set_loop_override(source_.kind == "scene" ? session_->frame_count() : 0);
  if (source_.kind == "scene") model_->set_frame(0);
  refresh();
  return true;
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
  font.setPointSize(theme.presentation ? 13 : 9);
  inspector_->setFont(font);
  inspector_->setFixedWidth(theme.presentation ? 380 : 260);
  refresh();
}

AnimationSession* AnimationView::session() {
  if ((stale_ || !session_) && !rebuild(source_, settings_)) return session_.get();
  if (session_) session_->seek(model_->frame() % session_->frame_count());
  return session_.get();
}

const Image& AnimationView::engine_image() {
  static const Image kEmpty;
  AnimationSession* s = session();
  return s ? s->frame_image() : kEmpty;
}

const Image& AnimationView::exact_image() {
  AnimationSession* s = session();
  if (!s) return exact_frame_;
  if (exact_frame_index_ != s->frame()) {
    exact_->render(s->reference_view());
    exact_frame_ = exact_->image();
    exact_frame_index_ = s->frame();
  }
  return exact_frame_;
}

QImage AnimationView::panel(bool exact) {
  AnimationSession* s = session();
  const QColor text = qcolor(theme_.text);
  QImage image = flatten_image(exact ? exact_image() : engine_image(), qcolor(theme_.background));
  if (exact) {
    draw_panel_title(image, tr("exact projection (VTK)"), text);
  } else {
    const FrameRecord& r = s->current();
    draw_level_overlay(image, s->outlines(), r.levels, text, theme_.line_width + 1.0);
    draw_panel_title(image, tr("optic-flow animation (%1)").arg(settings_.policy->name), text);
  }
  return image;
}

QImage AnimationView::compose() {
  if (!session()) return QImage();
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

void AnimationView::sync_engine() {
  AnimationSession* s = session();
  if (!s) return;
  inspector_->setText(explain_frame(s->current(), settings_));
  emit frame_shown();
}

void AnimationView::refresh() {
  if (!isVisible()) return;
  sync_engine();
  canvas_->set_image(compose());
}

QImage AnimationView::render_image() {
  sync_engine();
  const QImage image = compose();
  canvas_->set_image(image);
  return image;
}

void AnimationView::showEvent(QShowEvent* event) {
  ViewPage::showEvent(event);
  refresh();
}

void AnimationView::show_readout(QPointF pixel) {
  AnimationSession* s = session();
  if (!s) return;
  double x = pixel.x();
  if (panel_split_ > 0.0 && x >= panel_split_) x -= panel_split_;
  readout_->setText(pixel_readout(*s, Vec2(x, pixel.y()), exact_image()));
}

}  // namespace oflab
