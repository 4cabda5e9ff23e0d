#include "views/world_view.h"

#include <vtkActor.h>
#include <vtkArrowSource.h>
#include <vtkCamera.h>
#include <vtkImageData.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkTexture.h>
#include <vtkUnsignedCharArray.h>

#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QPushButton>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "adapters/camera_moves.h"
#include "adapters/exact_frames.h"
#include "adapters/frame_images.h"
#include "adapters/label_layout.h"
#include "adapters/offscreen_vtk.h"
#include "adapters/paint_helpers.h"
#include "adapters/world_actors.h"
#include "adapters/world_geometry.h"
#include "display/palette.h"
#include "models/animation_model.h"
#include "models/scene_model.h"
#include "models/window_model.h"
#include "scene/scene_animator.h"
#include "scene_shifting/scene_shifting_renderer.h"
#include "views/image_canvas.h"
#include "views/world_texts.h"

namespace oflab {
namespace {

RgbF rgbf(const Rgb8& c) { return {c.r / 255.0, c.g / 255.0, c.b / 255.0}; }

constexpr double kPi = 3.14159265358979323846;

// The viewer script a scene source plays, or nullptr for other animators.
const ViewerScript* viewer_script_of(const Animator* animator) {
  if (const auto* scene = dynamic_cast<const SceneScriptAnimator*>(animator)) {
    return &scene->script();
  }
  if (const auto* shifting = dynamic_cast<const SceneShiftingAnimator*>(animator)) {
    return &shifting->script();
  }
  return nullptr;
}

// How a polygon of a scene is drawn: its level's colour when it was drawn this frame, pale
// when culled, dark when hidden by polygons in front.
std::array<unsigned char, 4> polygon_colour(PolygonStatus status, Level level) {
  switch (status) {
    case PolygonStatus::kAnimated:
    case PolygonStatus::kClipped: {
      const Rgb8 c = level_colour(status == PolygonStatus::kClipped ? Level::kRerender : level);
      return {c.r, c.g, c.b, 255};
    }
    case PolygonStatus::kBackFacing:
    case PolygonStatus::kOutsideFrustum:
      return {215, 215, 215, 255};
    case PolygonStatus::kHidden:
      return {70, 70, 70, 255};
    case PolygonStatus::kStarved:
      return {0, 0, 0, 255};
  }
  return {128, 128, 128, 255};
}

}  // namespace

struct WorldView::Impl {
  std::string display_problem = offscreen_vtk_problem();
  vtkSmartPointer<vtkRenderWindow> window =
      display_problem.empty() ? make_offscreen_window() : vtkSmartPointer<vtkRenderWindow>::New();
  vtkNew<vtkRenderer> renderer;
  // The paths, drawn over everything else with the same camera: the plane covers most of
  // its own path.
  vtkNew<vtkRenderer> overlay;
  vtkNew<vtkUnsignedCharArray> read_back;
  std::array<QImage, 2> pictures;  // used in turn: the one on screen is never written
  int next_picture = 0;
  int renders = 0;
  bool needs_render = true;  // something VTK draws changed since the last render
  QSize rendered_size;
  // The viewer's frame in the world: identity for the plane, the viewer's pose in a scene.
  vtkNew<vtkMatrix4x4> viewer_matrix;
  vtkNew<vtkActor> eye;
  PolyActor frustum, image_plane, plane, plane_outline, rays, ray_images, omega_axis;
  PolyActor path_past, path_future, polygons, polygon_edges;
  vtkNew<vtkImageData> frame_pixels, texture_pixels;
  vtkNew<vtkTexture> frame_texture, plane_texture;
  vtkNew<vtkArrowSource> arrow_source;
  struct Arrow {
    vtkSmartPointer<vtkActor> actor;
    vtkSmartPointer<vtkMatrix4x4> matrix;
  };
  Arrow velocity, omega, normal, up;
  WorldTexts texts;  // labels, legend and caption, painted over VTK's picture

  ViewTheme theme = view_theme(false);
  std::array<bool, kWorldPartCount> shown{true, true, true, true, true, true, true, true};

  // What the source gives for every frame (rebuilt when the source changes).
  bool source_dirty = true;
  bool scene_mode = false;
  std::vector<Vec3> path;  // plane centres, or the viewer's eye, per frame, world units
  double largest_velocity = 0.0, largest_omega = 0.0;  // per second
  double depth = 1.0;                                  // image plane, world units
  double full_arrow = 1.0;                             // longest arrow, world units
  Camera camera;
  PlanePose first_pose;
  std::unique_ptr<ExactFrameRenderer> exact;
  std::string problem;  // why the image plane is empty, "" when it is not
  Vec3 centre{0.0};

  Arrow add_arrow(const Rgb8& colour) {
    Arrow a{vtkSmartPointer<vtkActor>::New(), vtkSmartPointer<vtkMatrix4x4>::New()};
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputConnection(arrow_source->GetOutputPort());
    a.actor->SetMapper(mapper);
    a.actor->SetUserMatrix(a.matrix);
    a.actor->GetProperty()->SetColor(colour.r / 255.0, colour.g / 255.0, colour.b / 255.0);
    renderer->AddActor(a.actor);
    return a;
  }

  static void place(Arrow& arrow, const Vec3& origin, const Vec3& direction, double length) {
    arrow.matrix->DeepCopy(arrow_matrix(origin, direction, length).data());
    arrow.actor->Modified();
  }

  void place_label(WorldLabelId id, const Vec3& at, const std::string& text) {
    texts.labels[size_t(id)].at = at;
    texts.labels[size_t(id)].text = text;
  }

  ViewerPose view;         // the viewer now (identity for the plane)
  ViewerPose first_view;   // the viewer at frame 0
  Vec3 world_centre{0.0};  // what the reset view looks at

  void load_plane(WindowModel& window);
  void load_scene(AnimationModel& animation);
  void update_plane(const SceneModel& scene);
  void update_scene(AnimationModel& animation);
  void place_viewer(const ViewerPose& pose);
  void place_motion(const Vec3& at, const Vec3& velocity, const Vec3& omega, double arrow_scale);
  void split_path(int frame);
  void show_parts();
  void apply_theme();
  bool to_canvas(const Vec3& at, QPointF* canvas) const;
};

WorldView::WorldView(WindowModel* window, QWidget* parent)
    : ViewPage(parent), window_(window), impl_(std::make_unique<Impl>()) {
  setObjectName(QStringLiteral("world_view"));
  Impl& m = *impl_;
  // No multisampling: on software OpenGL (llvmpipe) it costs most of the frame.
  m.window->SetMultiSamples(0);
  m.window->SetNumberOfLayers(2);
  m.window->AddRenderer(m.renderer);
  m.overlay->SetLayer(1);
  m.overlay->InteractiveOff();
  m.overlay->SetActiveCamera(m.renderer->GetActiveCamera());
  m.window->AddRenderer(m.overlay);

  const ViewTheme& t = m.theme;
  vtkNew<vtkSphereSource> sphere;
  // A small ball: 16 x 8 facets read as round at its size on screen.
  sphere->SetThetaResolution(16);
  sphere->SetPhiResolution(8);
  vtkNew<vtkPolyDataMapper> sphere_mapper;
  sphere_mapper->SetInputConnection(sphere->GetOutputPort());
  m.eye->SetMapper(sphere_mapper);
  m.eye->SetUserMatrix(m.viewer_matrix);
  m.renderer->AddActor(m.eye);
  m.frustum = add_poly_actor(m.renderer, t.outline);
  m.image_plane = add_poly_actor(m.renderer, {1.0, 1.0, 1.0});
  m.frame_texture->SetInputData(m.frame_pixels);
  m.frame_texture->InterpolateOn();
  m.image_plane.actor->SetTexture(m.frame_texture);
  m.plane = add_poly_actor(m.renderer, {1.0, 1.0, 1.0});
  m.plane_texture->SetInputData(m.texture_pixels);
  m.plane_texture->InterpolateOn();
  // Opaque: translucent geometry would send every frame through VTK's order-independent
  // transparency passes, full-window float buffers that software OpenGL fills slowly.
  m.plane.actor->ForceOpaqueOn();
  m.plane.actor->SetTexture(m.plane_texture);
  for (PolyActor* p : {&m.frustum, &m.image_plane}) p->actor->SetUserMatrix(m.viewer_matrix);
  m.plane_outline = add_poly_actor(m.renderer, t.outline);
  m.rays = add_poly_actor(m.renderer, rgbf(okabe_ito::kYellow));
  m.ray_images = add_poly_actor(m.renderer, rgbf(okabe_ito::kYellow));
  m.omega_axis = add_poly_actor(m.renderer, rgbf(okabe_ito::kReddishPurple));
  m.path_past = add_poly_actor(m.overlay, rgbf(okabe_ito::kOrange));
  m.path_future = add_poly_actor(m.overlay, t.muted);
  m.polygons = add_poly_actor(m.renderer, {1.0, 1.0, 1.0});
  m.polygons.actor->GetMapper()->ScalarVisibilityOn();
  m.polygons.actor->GetMapper()->SetScalarModeToUseCellData();
  m.polygons.actor->GetMapper()->SetColorModeToDirectScalars();
  m.polygons.actor->ForceOpaqueOn();
  m.polygon_edges = add_poly_actor(m.renderer, t.outline);
  m.polygon_edges.actor->GetMapper()->SetInputDataObject(m.polygons.data);
  m.polygon_edges.actor->GetProperty()->SetRepresentationToWireframe();
  m.velocity = m.add_arrow(okabe_ito::kVermillion);
  m.omega = m.add_arrow(okabe_ito::kReddishPurple);
  m.normal = m.add_arrow(okabe_ito::kBlue);
  m.up = m.add_arrow(okabe_ito::kBluishGreen);
  m.texts.labels[kEyeLabel] = {"eye", Vec3(0.0), t.text, true};
  m.texts.labels[kImageLabel] = {"image plane", Vec3(0.0), t.text, true};
  m.texts.labels[kVelocityLabel] = {"V", Vec3(0.0), rgbf(okabe_ito::kVermillion), true};
  m.texts.labels[kOmegaLabel] = {"Omega", Vec3(0.0), rgbf(okabe_ito::kReddishPurple), true};
  m.texts.labels[kNormalLabel] = {"N", Vec3(0.0), rgbf(okabe_ito::kBlue), true};
  m.texts.labels[kUpLabel] = {"U", Vec3(0.0), rgbf(okabe_ito::kBluishGreen), true};

  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(2, 2, 2, 2);
  layout->addWidget(make_button_bar());
  canvas_ = new ImageCanvas(this);
  canvas_->setObjectName(QStringLiteral("world_canvas"));
  canvas_->setToolTip(tr("Drag to orbit, Shift+drag to pan, wheel to zoom"));
  layout->addWidget(canvas_, 1);
  connect(canvas_, &ImageCanvas::resized, this, [this] {
    if (isVisible()) draw();
  });
  connect(canvas_, &ImageCanvas::dragged, this,
          [this](QPointF delta, Qt::MouseButtons buttons, Qt::KeyboardModifiers modifiers) {
            if (buttons & Qt::MiddleButton ||
                (buttons & Qt::LeftButton && modifiers & Qt::ShiftModifier)) {
              pan_camera(impl_->renderer, delta);
            } else if (buttons & Qt::LeftButton) {
              orbit_camera(impl_->renderer, delta);
            } else if (buttons & Qt::RightButton) {
              drag_zoom_camera(impl_->renderer, delta);
            }
            camera_moved();
          });
  connect(canvas_, &ImageCanvas::wheel_turned, this, [this](double notches) {
    dolly_camera(impl_->renderer, notches);
    camera_moved();
  });

  SceneModel* scene = window_->scene();
  connect(scene, &SceneModel::scene_changed, this, &WorldView::refresh);
  const auto source_changed = [this] {
    impl_->source_dirty = true;
    camera_placed_ = false;
    refresh();
  };
  connect(scene, &SceneModel::source_changed, this, source_changed);
  connect(scene, &SceneModel::texture_changed, this, source_changed);
  connect(window_->animation(), &AnimationModel::source_changed, this, source_changed);
  connect(window_, &WindowModel::panels_changed, this, [this] {  // the exact renderer
    impl_->source_dirty = true;
    refresh();
  });
  set_theme(m.theme);
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
  connect(reset, &QPushButton::clicked, this, [this] {
    reset_camera();
    camera_moved();
  });
  connect(eye, &QPushButton::clicked, this, [this] {
    view_from_camera();
    camera_moved();
  });
  return bar;
}

vtkRenderer* WorldView::renderer() const { return impl_->renderer; }
bool WorldView::scene_mode() const { return impl_->scene_mode; }
Vec3 WorldView::drawn_centre() const { return impl_->centre; }
double WorldView::image_depth() const { return impl_->depth; }

void WorldView::set_part_shown(WorldPart part, bool shown) {
  impl_->shown[size_t(part)] = shown;
  refresh();
}

std::vector<PaintedText> WorldView::painted_texts() const {
  return record_painted_text(canvas_->size(),
                             [this](QPainter& painter) { impl_->texts.paint(painter); });
}

std::vector<QString> WorldView::text_problems() const {
  return oflab::text_problems(painted_texts(), canvas_->size());
}

int WorldView::render_count() const { return impl_->renders; }

void WorldView::refresh() {
  dirty_ = true;
  impl_->needs_render = true;
  if (!isVisible()) return;
  update_now();
  draw();
}

void WorldView::camera_moved() {
  impl_->needs_render = true;
  if (isVisible()) draw();
}

void WorldView::showEvent(QShowEvent* event) {
  ViewPage::showEvent(event);
  if (dirty_) {
    refresh();
  } else if (impl_->needs_render || impl_->rendered_size != canvas_->size()) {
    draw();
  }
}

QImage WorldView::render_image() {
  if (dirty_) update_now();
  if (impl_->needs_render || impl_->rendered_size != canvas_->size()) draw();
  return canvas_->image();
}

void WorldView::draw() {
  Impl& m = *impl_;
  const QSize size = canvas_->size();
  if (size.isEmpty()) return;
  if (dirty_) update_now();  // a resize may come before the first refresh
  m.window->SetSize(size.width(), size.height());
  if (!camera_placed_) {  // after the size: the framing depends on the picture's shape
    reset_camera();
    camera_placed_ = true;
  }
  QImage& picture = m.pictures[size_t(m.next_picture)];
  m.next_picture = 1 - m.next_picture;
  if (m.display_problem.empty()) {
    m.window->Render();
    ++m.renders;
    read_window_pixels(m.window, m.read_back, &picture);
  } else {
    picture = QImage(size, QImage::Format_RGB32);
    picture.fill(to_qcolor(m.theme.background));
  }
  m.texts.lay_out(size, font(), m.theme,
                  [&m](const Vec3& at, QPointF* canvas) { return m.to_canvas(at, canvas); });
  {
    QPainter painter(&picture);
    m.texts.paint(painter);
  }
  canvas_->set_image(picture);
  m.rendered_size = size;
  m.needs_render = false;
}

void WorldView::update_now() {
  Impl& m = *impl_;
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
  m.show_parts();
  m.needs_render = true;
  dirty_ = false;
}

void WorldView::reset_camera() {
  Impl& m = *impl_;
  const Mat3 to_world = glm::transpose(m.first_view.rotation);
  const Vec3 forward = to_world * Vec3(0, 0, 1), up = to_world * Vec3(0, -1, 0),
             right = to_world * Vec3(1, 0, 0);
  const Vec3 eye = viewer_to_world(m.first_view, Vec3(0.0));
  const Vec3 focus = 0.5 * (eye + m.world_centre);
  const double distance = std::max(1e-3, glm::length(m.world_centre - eye));
  // From the left of the eye, a little behind and above it: the frustum opens towards the
  // plane across the picture and the path is seen from its side.
  const Vec3 from = focus + distance * (-0.55 * forward + 0.45 * up - 1.0 * right);
  vtkCamera* camera = m.renderer->GetActiveCamera();
  camera->SetFocalPoint(focus.x, focus.y, focus.z);
  camera->SetPosition(from.x, from.y, from.z);
  camera->SetViewUp(up.x, up.y, up.z);
  camera->SetViewAngle(30.0);
  m.renderer->ResetCamera();
  // Closer in a wide view; a narrow one (the cause-and-effect layout) keeps the whole width.
  camera->Zoom(1.6 * std::clamp(m.renderer->GetTiledAspectRatio() / 1.6, 0.6, 1.0));
  m.renderer->ResetCameraClippingRange();
  m.needs_render = true;
}

void WorldView::view_from_camera() {
  Impl& m = *impl_;
  const Mat3 to_world = glm::transpose(m.view.rotation);
  const Vec3 eye = viewer_to_world(m.view, Vec3(0.0));
  const Vec3 ahead = eye + to_world * Vec3(0, 0, 4.0 * m.depth), up = to_world * Vec3(0, -1, 0);
  vtkCamera* camera = m.renderer->GetActiveCamera();
  camera->SetPosition(eye.x, eye.y, eye.z);
  camera->SetFocalPoint(ahead.x, ahead.y, ahead.z);
  camera->SetViewUp(up.x, up.y, up.z);
  camera->SetViewAngle(2.0 * std::atan(0.5 * m.camera.height / m.camera.focal_px) * 180.0 / kPi);
  m.renderer->ResetCameraClippingRange();
  m.needs_render = true;
}

void WorldView::set_theme(const ViewTheme& theme) {
  impl_->theme = theme;
  impl_->apply_theme();
  canvas_->set_background(to_qcolor(theme.background));
  refresh();
}

double WorldView::smallest_text_px() const {
  return std::min(impl_->theme.label_size, impl_->theme.font_size);
}

}  // namespace oflab

// The source: what every frame of the loop shows (the plane's path, the scene's polygons).

namespace oflab {

void WorldView::Impl::load_plane(WindowModel& window) {
  const SceneModel& scene = *window.scene();
  const MotionScript script = scene.as_script();
  const double dt = SceneModel::kSecondsPerFrame;
  camera = scene.scene().camera;
  path.clear();
  largest_velocity = largest_omega = 0.0;
  for (const ScriptFrame& f : script.frames) {
    path.push_back(f.pose.point);
    largest_velocity = std::max(largest_velocity, glm::length(eye_velocity(f.motion, f.pose)) / dt);
    largest_omega = std::max(largest_omega, glm::length(f.motion.omega) / dt);
  }
  first_pose = script.frames.empty() ? scene.current_pose() : script.frames.front().pose;
  first_view = ViewerPose{};
  depth = plane_image_depth(path);
  full_arrow = 0.6 * std::hypot(first_pose.size.x, first_pose.size.y);
  world_centre = Vec3(0.0);
  for (const Vec3& p : path) world_centre += p / double(path.size());
  copy_texture_pixels(scene.texture(), texture_pixels);
  exact.reset();
  problem.clear();
  const ExactRendererKind* kind = find_exact_renderer(window.exact_renderer());
  try {
    const Scene as_scene = plane_as_scene(first_pose, image_from_qimage(scene.texture()));
    exact = kind->make(as_scene, camera, window.animation()->settings());
  } catch (const std::exception& e) {  // VTK without a display, a refused scene
    problem = "The image plane is empty: the " + kind->name + " exact renderer cannot start (" +
              e.what() + ").";
  }
  set_coloured_polygons(polygons.data, {}, {});
}

void WorldView::Impl::load_scene(AnimationModel& animation) {
  path.clear();
  largest_velocity = largest_omega = 0.0;
  exact.reset();
  problem.clear();
  Animator* animator = animation.animator();
  if (!animator) {
    problem = "Nothing plays: the animation view's source cannot be played.";
    set_coloured_polygons(polygons.data, {}, {});
    return;
  }
  camera = animator->camera();
  std::vector<std::vector<Vec3>> outlines;
  std::vector<Vec3> points;
  for (const ScenePolygon& polygon : animator->scene().polygons) {
    outlines.push_back(polygon_vertices(polygon));
    points.insert(points.end(), outlines.back().begin(), outlines.back().end());
  }
  set_coloured_polygons(
      polygons.data, outlines,
      std::vector<std::array<unsigned char, 4>>(outlines.size(), {150, 150, 150, 255}));
  const double dt = SceneModel::kSecondsPerFrame;
  first_view = animator->view();
  if (const ViewerScript* script = viewer_script_of(animator)) {
    for (const ViewerFrame& f : script->frames) {
      path.push_back(viewer_to_world(f.pose, Vec3(0.0)));
      largest_velocity = std::max(largest_velocity, glm::length(f.motion.velocity) / dt);
      largest_omega = std::max(largest_omega, glm::length(f.motion.omega) / dt);
    }
    first_view = script->frames.front().pose;
  }
  depth = scene_image_depth(points);
  full_arrow = 2.0 * depth;
  world_centre = Vec3(0.0);
  for (const Vec3& p : points) world_centre += p / double(points.size());
}

// One frame: every actor keeps its identity; points, matrices and pixels change.

void WorldView::Impl::place_viewer(const ViewerPose& pose) {
  view = pose;
  viewer_matrix->DeepCopy(viewer_to_world_matrix(pose).data());
  for (vtkActor* a : {eye.Get(), frustum.actor.Get(), image_plane.actor.Get()}) a->Modified();
  eye->SetScale(0.05 * depth);
  const std::array<Vec3, 4> corners = image_plane_corners(camera, depth);
  set_textured_quad(image_plane.data, corners);
  std::vector<Vec3> from(4, Vec3(0.0)), to(corners.begin(), corners.end());
  for (int k = 0; k < 4; ++k) {  // the image's border
    from.push_back(corners[size_t(k)]);
    to.push_back(corners[size_t((k + 1) % 4)]);
  }
  set_segments(frustum.data, from, to);
  place_label(kEyeLabel, viewer_to_world(pose, Vec3(0.0)), "eye");
  place_label(kImageLabel, viewer_to_world(pose, corners[0]), "image plane");
}

void WorldView::Impl::place_motion(const Vec3& at, const Vec3& velocity, const Vec3& omega_w,
                                   double arrow_scale) {
  const double lv = arrow_length(glm::length(velocity), largest_velocity, arrow_scale);
  const double lo = arrow_length(glm::length(omega_w), largest_omega, arrow_scale);
  place(this->velocity, at, velocity, lv);
  place(omega, at, omega_w, lo);
  char text[96];
  std::snprintf(text, sizeof text, "V %.2f/s", glm::length(velocity));
  place_label(kVelocityLabel, lv > 0 ? at + glm::normalize(velocity) * lv : at, text);
  std::snprintf(text, sizeof text, "Omega %.2f rad/s about the eye", glm::length(omega_w));
  place_label(kOmegaLabel, lo > 0 ? at + glm::normalize(omega_w) * lo : at, text);
  // The axis Omega turns about passes through the eye, not through the arrow's foot.
  const Vec3 eye_w = viewer_to_world(view, Vec3(0.0));
  std::vector<Vec3> axis;
  if (lo > 0) {
    const double reach = 1.1 * glm::length(at - eye_w);
    axis = {eye_w, eye_w + reach * glm::normalize(omega_w)};
  }
  set_polyline(omega_axis.data, axis, false);
}

void WorldView::Impl::split_path(int frame) {
  const int k = path.empty() ? 0 : std::clamp(frame, 0, int(path.size()) - 1);
  set_polyline(
      path_past.data,
      std::vector<Vec3>(path.begin(), path.begin() + std::min<size_t>(path.size(), size_t(k) + 1)),
      false);
  set_polyline(
      path_future.data,
      std::vector<Vec3>(path.begin() + std::min<size_t>(path.size(), size_t(k)), path.end()),
      false);
}

void WorldView::Impl::update_plane(const SceneModel& scene) {
  place_viewer(ViewerPose{});
  const PlanePose pose = scene.current_pose();
  const RigidMotion motion = scene.current_motion();
  const std::array<Vec3, 4> corners = plane_corners(pose);
  centre = pose.point;
  set_textured_quad(plane.data, corners);
  const std::vector<Vec3> outline(corners.begin(), corners.end());
  set_polyline(plane_outline.data, outline, true);
  set_segments(rays.data, std::vector<Vec3>(4, Vec3(0.0)), outline);
  std::vector<Vec3> images;
  for (const Vec3& c : corners) {
    if (c.z > 0.0) images.push_back(ray_at_depth(c, depth));
  }
  set_polyline(ray_images.data, images, true);
  const PlaneAxes axes = plane_axes(pose);
  const double side = 0.3 * std::hypot(pose.size.x, pose.size.y);
  place(normal, pose.point, axes.normal, side);
  place(up, pose.point, axes.up, side);
  place_label(kNormalLabel, pose.point + axes.normal * side, "N");
  place_label(kUpLabel, pose.point + axes.up * side, "U");
  place_motion(pose.point, eye_velocity(motion, pose), motion.omega, full_arrow);
  split_path(scene.frame());
  if (exact) copy_frame_pixels(exact->render(viewer_for_pose(first_pose, pose)), frame_pixels);
  char text[400];
  std::snprintf(text, sizeof text,
                "The eye looks along +Z; the image plane is drawn at "
                "depth %.2f (f = %.0f px scaled to the scene).\n"
                "Omega turns about the eye, the viewer's origin (the theory's convention); "
                "V is the velocity of the body point at the eye.\n"
                "Path of the plane's centre: past thick, future thin. Rays: eye to the plane's "
                "corners through their images.",
                depth, camera.focal_px);
  texts.caption = text;
}

void WorldView::Impl::update_scene(AnimationModel& animation) {
  Animator* animator = animation.animator();
  if (!animator) return;
  place_viewer(animator->view());
  centre = viewer_to_world(view, Vec3(0.0));
  const size_t count = animator->scene().polygons.size();
  std::vector<std::array<unsigned char, 4>> colours(count, {150, 150, 150, 255});
  if (const auto* scene = dynamic_cast<const SceneScriptAnimator*>(animator)) {
    const std::vector<PolygonStatus>& statuses = scene->renderer().statuses();
    const std::vector<Level>& levels = scene->renderer().levels();
    for (size_t k = 0; k < count && k < statuses.size() && k < levels.size(); ++k) {
      colours[k] = polygon_colour(statuses[k], levels[k]);
    }
  }
  set_cell_colours(polygons.data, colours);
  const int frame = animator->frame();
  const ViewerScript* script = viewer_script_of(animator);
  const double dt = SceneModel::kSecondsPerFrame;
  if (script && frame >= 0 && frame < int(script->frames.size())) {
    const RigidMotion& motion = script->frames[size_t(frame)].motion;
    const Mat3 to_world = glm::transpose(view.rotation);
    place_motion(viewer_to_world(view, Vec3(0.0, 0.0, 1.5 * depth)),
                 to_world * motion.velocity / dt, to_world * motion.omega / dt, full_arrow);
  }
  split_path(frame);
  copy_frame_pixels(animator->image(), frame_pixels);
  char text[400];
  std::snprintf(text, sizeof text,
                "The viewer walks through the scene; its image plane shows the "
                "engine's frame.\n"
                "Polygons in their level's colour (translate sky blue, affine green, "
                "perspective orange, re-render vermillion); culled pale, hidden dark.\n"
                "V and Omega: the scene's motion seen by the viewer (Omega about the eye). "
                "Viewer's path: past thick, future thin.");
  texts.caption = text;
}

void WorldView::Impl::show_parts() {
  const auto on = [this](WorldPart part) { return shown[size_t(part)]; };
  const bool plane_mode = !scene_mode;
  for (vtkProp* p : {static_cast<vtkProp*>(eye.Get()), static_cast<vtkProp*>(frustum.actor)}) {
    p->SetVisibility(on(WorldPart::kFrustum));
  }
  texts.labels[kEyeLabel].shown = on(WorldPart::kFrustum);
  image_plane.actor->SetVisibility(on(WorldPart::kImagePlane));
  texts.labels[kImageLabel].shown = on(WorldPart::kImagePlane);
  for (vtkProp* p : {static_cast<vtkProp*>(plane.actor), static_cast<vtkProp*>(plane_outline.actor),
                     static_cast<vtkProp*>(normal.actor), static_cast<vtkProp*>(up.actor)}) {
    p->SetVisibility(plane_mode && on(WorldPart::kPlane));
  }
  texts.labels[kNormalLabel].shown = texts.labels[kUpLabel].shown =
      plane_mode && on(WorldPart::kPlane);
  velocity.actor->SetVisibility(on(WorldPart::kVelocity));
  texts.labels[kVelocityLabel].shown = on(WorldPart::kVelocity);
  for (vtkProp* p : {static_cast<vtkProp*>(omega.actor), static_cast<vtkProp*>(omega_axis.actor)}) {
    p->SetVisibility(on(WorldPart::kOmega));
  }
  texts.labels[kOmegaLabel].shown = on(WorldPart::kOmega);
  rays.actor->SetVisibility(plane_mode && on(WorldPart::kRays));
  ray_images.actor->SetVisibility(plane_mode && on(WorldPart::kRays));
  path_past.actor->SetVisibility(on(WorldPart::kPath));
  path_future.actor->SetVisibility(on(WorldPart::kPath));
  polygons.actor->SetVisibility(scene_mode && on(WorldPart::kScene));
  polygon_edges.actor->SetVisibility(scene_mode && on(WorldPart::kScene));
}

void WorldView::Impl::apply_theme() {
  const ViewTheme& t = theme;
  renderer->SetBackground(t.background[0], t.background[1], t.background[2]);
  const double thin = t.line_width, thick = 2.5 * t.line_width;
  for (PolyActor* p : {&frustum, &plane_outline, &polygon_edges}) {
    p->actor->GetProperty()->SetColor(t.outline[0], t.outline[1], t.outline[2]);
    p->actor->GetProperty()->SetLineWidth(thin);
  }
  path_future.actor->GetProperty()->SetColor(t.muted[0], t.muted[1], t.muted[2]);
  path_future.actor->GetProperty()->SetLineWidth(1.5 * thin);
  path_past.actor->GetProperty()->SetLineWidth(thick);
  omega_axis.actor->GetProperty()->SetLineWidth(thin);
  // Yellow rays vanish on the light background of presentation mode: sky blue there.
  const RgbF ray = rgbf(t.presentation ? okabe_ito::kSkyBlue : okabe_ito::kYellow);
  for (PolyActor* p : {&rays, &ray_images}) {
    p->actor->GetProperty()->SetColor(ray[0], ray[1], ray[2]);
    p->actor->GetProperty()->SetLineWidth(p == &rays ? thin : thick);
  }
  texts.labels[kEyeLabel].colour = texts.labels[kImageLabel].colour = t.text;
}

bool WorldView::Impl::to_canvas(const Vec3& at, QPointF* canvas) const {
  const int* size = window->GetSize();
  renderer->SetWorldPoint(at.x, at.y, at.z, 1.0);
  renderer->WorldToDisplay();
  const double* d = renderer->GetDisplayPoint();
  // VTK's display y runs upwards; depth outside [0, 1] is behind the eye or past the far plane.
  *canvas = QPointF(d[0], size[1] - d[1]);
  return d[2] >= 0.0 && d[2] <= 1.0 && d[0] >= 0.0 && d[0] <= size[0] && d[1] >= 0.0 &&
         d[1] <= size[1];
}

}  // namespace oflab
