#include "views/world_view.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QPushButton>
#include <QVBoxLayout>
#include <algorithm>

#include "adapters/camera_moves.h"
#include "adapters/offscreen_vtk.h"
#include "adapters/paint_helpers.h"
#include "models/animation_model.h"
#include "models/scene_model.h"
#include "models/window_model.h"
#include "player/stage_times.h"
#include "views/image_canvas.h"
#include "views/world_scene.h"

namespace oflab {

WorldView::WorldView(WindowModel* window, QWidget* parent)
    : ViewPage(parent), window_(window), world_(std::make_unique<WorldScene>()) {
  setObjectName(QStringLiteral("world_view"));
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(2, 2, 2, 2);
  layout->addWidget(make_button_bar());
  layout->addWidget(make_canvas(), 1);
  follow_models();
  set_theme(world_->theme);
}

WorldView::~WorldView() = default;

QWidget* WorldView::make_button_bar() {
  auto* bar = new QWidget(this);
  auto* row = new QHBoxLayout(bar);
  row->setContentsMargins(0, 0, 0, 0);
  auto* reset = new QPushButton(tr("Reset view"), bar);
  reset->setObjectName(QStringLiteral("world_reset"));
  reset->setToolTip(
      tr("Frame the whole world again (drag to orbit, Shift+drag to pan, wheel "
         "to zoom)"));
  auto* eye = new QPushButton(tr("View from the camera"), bar);
  eye->setObjectName(QStringLiteral("world_from_camera"));
  eye->setToolTip(tr("Look through the eye with the camera's field of view"));
  note_ = new QLabel(bar);
  note_->setObjectName(QStringLiteral("world_note"));
  row->addWidget(reset);
  row->addWidget(eye);
  row->addWidget(note_, 1);
  connect(reset, &QPushButton::clicked, this, &WorldView::reset_camera);
  connect(eye, &QPushButton::clicked, this, &WorldView::view_from_camera);
  return bar;
}

ImageCanvas* WorldView::make_canvas() {
  canvas_ = new ImageCanvas(this);
  canvas_->setObjectName(QStringLiteral("world_canvas"));
  canvas_->setToolTip(tr("Drag to orbit, Shift+drag to pan, wheel to zoom"));
  connect(canvas_, &ImageCanvas::resized, this, [this] {
    if (isVisible()) draw();
  });
  connect(canvas_, &ImageCanvas::dragged, this,
          [this](QPointF delta, Qt::MouseButtons buttons, Qt::KeyboardModifiers modifiers) {
            leave_eye();
            if (buttons & Qt::MiddleButton ||
                (buttons & Qt::LeftButton && modifiers & Qt::ShiftModifier)) {
              pan_camera(world_->renderer, delta);
            } else if (buttons & Qt::LeftButton) {
              orbit_camera(world_->renderer, delta);
            } else if (buttons & Qt::RightButton) {
              drag_zoom_camera(world_->renderer, delta);
            }
            camera_moved();
          });
  connect(canvas_, &ImageCanvas::wheel_turned, this, [this](double notches) {
    leave_eye();
    dolly_camera(world_->renderer, notches);
    camera_moved();
  });
  return canvas_;
}

void WorldView::follow_models() {
  SceneModel* scene = window_->scene();
  connect(scene, &SceneModel::scene_changed, this, &WorldView::refresh);
  const auto source_changed = [this] {
    world_->source_dirty = true;
    camera_placed_ = false;
    refresh();
  };
  connect(scene, &SceneModel::source_changed, this, source_changed);
  connect(scene, &SceneModel::texture_changed, this, source_changed);
  connect(window_->animation(), &AnimationModel::source_changed, this, source_changed);
  connect(window_, &WindowModel::panels_changed, this, [this] {  // the exact renderer
    world_->source_dirty = true;
    refresh();
  });
  connect(window_, &WindowModel::world_camera_changed, this, [this] {
    if (window_->world_camera() == placed_camera_) return;
    camera_placed_ = false;
    camera_moved();
  });
}

void WorldView::place_camera() {
  placed_camera_ = window_->world_camera();
  if (placed_camera_ == WorldCamera::kEye) {
    world_->view_from_camera();
  } else {
    world_->reset_camera();
  }
  camera_placed_ = true;
}

void WorldView::leave_eye() {
  if (placed_camera_ != WorldCamera::kEye) return;
  placed_camera_ = WorldCamera::kOrbit;
  world_->leave_eye();
  window_->set_world_camera(WorldCamera::kOrbit);
}

vtkRenderer* WorldView::renderer() const { return world_->renderer; }
bool WorldView::scene_mode() const { return world_->scene_mode; }
Vec3 WorldView::drawn_centre() const { return world_->centre; }
double WorldView::image_depth() const { return world_->depth; }

void WorldView::set_part_shown(WorldPart part, bool shown) {
  world_->shown[size_t(part)] = shown;
  refresh();
}

std::vector<PaintedText> WorldView::painted_texts() const {
  return record_painted_text(canvas_->size(),
                             [this](QPainter& painter) { world_->texts.paint(painter); });
}

std::vector<QString> WorldView::text_problems() const {
  return oflab::text_problems(painted_texts(), canvas_->size());
}

std::vector<QString> WorldView::labels_over_content() {
  render_image();
  return world_->texts.labels_over_content();
}

double WorldView::drawn_share() {
  render_image();
  return world_->drawn_share();
}

int WorldView::render_count() const { return world_->renders; }

void WorldView::refresh() {
  dirty_ = true;
  world_->needs_render = true;
  if (!isVisible()) return;
  update_now();
  draw();
}

void WorldView::camera_moved() {
  world_->needs_render = true;
  if (isVisible()) draw();
}

void WorldView::showEvent(QShowEvent* event) {
  ViewPage::showEvent(event);
  if (dirty_) {
    refresh();
  } else if (world_->needs_render || world_->rendered_size != canvas_->size()) {
    draw();
  }
}

QImage WorldView::render_image() {
  if (dirty_) update_now();
  if (world_->needs_render || world_->rendered_size != canvas_->size()) draw();
  return canvas_->image();
}

void WorldView::draw() {
  WorldScene& m = *world_;
  const QSize size = canvas_->size();
  if (size.isEmpty()) return;
  if (dirty_) update_now();  // a resize may come before the first refresh
  m.window->SetSize(size.width(), size.height());
  const auto project = [&m](const Vec3& at, QPointF* canvas) { return m.to_canvas(at, canvas); };
  if (!camera_placed_) {
    // After the size, and the legend and caption laid out: the framing fits the picture between
    // them (WorldScene::framed_picture).
    m.texts.caption = m.caption();
    m.texts.content.clear();  // the camera is not placed yet
    m.texts.lay_out(size, font(), m.theme, project);
    place_camera();
  }
  // The frame on the image plane at the texels the image plane now takes on the screen (a
  // zoom or a resize may change them).
  if (!m.frame_size.isEmpty() &&
      m.frame_reduction(m.frame_size.width(), m.frame_size.height()) != m.frame_shown_reduction) {
    update_now();
  }
  QImage& picture = m.pictures[size_t(m.next_picture)];
  m.next_picture = 1 - m.next_picture;
  const StageTimer drawing(FrameStage::kDrawing);  // VTK's render and its read-back
  if (m.display_problem.empty()) {
    m.window->Render();
    ++m.renders;
    read_window_pixels(m.window, m.read_back, &picture);
  } else {
    picture = QImage(size, QImage::Format_RGB32);
    picture.fill(to_qcolor(m.theme.background));
  }
  const StageTimer text(FrameStage::kText);
  m.texts.caption = m.caption();
  m.texts.content = m.content_outlines();
  m.texts.lay_out(size, font(), m.theme, project);
  {
    QPainter painter(&picture);
    m.texts.paint(painter);
  }
  canvas_->set_image(picture);
  m.rendered_size = size;
  m.needs_render = false;
}

void WorldView::update_now() {
  const StageTimer drawing(FrameStage::kDrawing);  // the actors' transforms and geometry
  WorldScene& m = *world_;
  AnimationModel* animation = window_->animation();
  const bool scene = animation->source_kind().uses_viewer;
  if (m.source_dirty || scene != m.scene_mode) {
    m.scene_mode = scene;
    if (scene) {
      m.load_scene(*animation);
    } else {
      m.load_plane(*window_);
    }
    m.source_dirty = false;
    const std::string problem =
        m.display_problem.empty() ? m.problem : "The world cannot be drawn: " + m.display_problem;
    note_->setText(QString::fromStdString(problem));
  }
  if (scene) {
    m.update_scene(*animation);
  } else {
    m.update_plane(*window_->scene());
  }
  if (camera_placed_ && placed_camera_ == WorldCamera::kEye) m.view_from_camera();  // follows
  m.show_parts();
  m.needs_render = true;
  dirty_ = false;
}

void WorldView::reset_camera() {
  camera_placed_ = false;  // placed again even when the model already says "orbit"
  window_->set_world_camera(WorldCamera::kOrbit);
  camera_moved();
}

void WorldView::view_from_camera() {
  camera_placed_ = false;
  window_->set_world_camera(WorldCamera::kEye);
  camera_moved();
}

bool WorldView::from_eye() const { return world_->from_eye; }

void WorldView::set_theme(const ViewTheme& theme) {
  world_->theme = theme;
  world_->apply_theme();
  canvas_->set_background(to_qcolor(theme.background));
  refresh();
}

double WorldView::smallest_text_px() const {
  return std::min(world_->theme.label_size, world_->theme.font_size);
}

}  // namespace oflab
