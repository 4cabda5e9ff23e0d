#include "views/world_scene.h"

#include <vtkCamera.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkSphereSource.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "adapters/frame_images.h"
#include "display/world_geometry.h"
#include "models/animation_model.h"
#include "models/scene_model.h"
#include "models/window_model.h"
#include "scene/scene_animator.h"
#include "scene_shifting/scene_shifting_renderer.h"
#include "views/panel_layout.h"

namespace oflab {
namespace {

RgbF rgbf(const Rgb8& c) { return {c.r / 255.0, c.g / 255.0, c.b / 255.0}; }

}  // namespace

WorldScene::WorldScene() {
  // No multisampling: on software OpenGL (llvmpipe) it costs most of the frame.
  window->SetMultiSamples(0);
  window->SetNumberOfLayers(2);
  window->AddRenderer(renderer);
  overlay->SetLayer(1);
  overlay->InteractiveOff();
  overlay->SetActiveCamera(renderer->GetActiveCamera());
  window->AddRenderer(overlay);

  add_viewer_actors();
  add_plane_actors();
  add_scene_actors();
  velocity = add_arrow(okabe_ito::kVermillion);
  // V starts at the plane's centre and often runs along it: on the overlay, as the paths,
  // the plane never hides it.
  renderer->RemoveActor(velocity.actor);
  overlay->AddActor(velocity.actor);
  omega = add_arrow(okabe_ito::kReddishPurple);
  normal = add_arrow(okabe_ito::kBlue);
  up = add_arrow(okabe_ito::kBluishGreen);
  name_labels();
}

void WorldScene::add_viewer_actors() {
  const ViewTheme& t = theme;
  vtkNew<vtkSphereSource> sphere;
  // A small ball: 16 x 8 facets read as round at its size on screen.
  sphere->SetThetaResolution(16);
  sphere->SetPhiResolution(8);
  vtkNew<vtkPolyDataMapper> sphere_mapper;
  sphere_mapper->SetInputConnection(sphere->GetOutputPort());
  eye->SetMapper(sphere_mapper);
  eye->SetUserMatrix(viewer_matrix);
  renderer->AddActor(eye);
  frustum = add_poly_actor(renderer, t.outline);
  image_plane = add_poly_actor(renderer, {1.0, 1.0, 1.0});
  frame_texture->SetInputData(frame_pixels);
  frame_texture->InterpolateOn();
  image_plane.actor->SetTexture(frame_texture);
  // The frame's texels are opaque (copy_frame_pixels): VTK need not scan their alpha each frame
  // to learn whether the plane is translucent.
  image_plane.actor->ForceOpaqueOn();
  for (PolyActor* p : {&frustum, &image_plane}) p->actor->SetUserMatrix(viewer_matrix);
}

void WorldScene::add_plane_actors() {
  const ViewTheme& t = theme;
  plane = add_poly_actor(renderer, {1.0, 1.0, 1.0});
  plane_texture->SetInputData(texture_pixels);
  plane_texture->InterpolateOn();
  // Opaque: translucent geometry would send every frame through VTK's order-independent
  // transparency passes, full-window float buffers that software OpenGL fills slowly.
  plane.actor->ForceOpaqueOn();
  plane.actor->SetTexture(plane_texture);
  plane_outline = add_poly_actor(renderer, t.outline);
  rays = add_poly_actor(renderer, rgbf(okabe_ito::kYellow));
  ray_images = add_poly_actor(renderer, rgbf(okabe_ito::kYellow));
  omega_axis = add_poly_actor(renderer, rgbf(okabe_ito::kReddishPurple));
}

void WorldScene::add_scene_actors() {
  const ViewTheme& t = theme;
  path_past = add_poly_actor(overlay, rgbf(okabe_ito::kOrange));
  path_future = add_poly_actor(overlay, t.muted);
  polygons = add_poly_actor(renderer, {1.0, 1.0, 1.0});
  polygons.actor->GetMapper()->ScalarVisibilityOn();
  polygons.actor->GetMapper()->SetScalarModeToUseCellData();
  polygons.actor->GetMapper()->SetColorModeToDirectScalars();
  polygons.actor->ForceOpaqueOn();
  polygon_edges = add_poly_actor(renderer, t.outline);
  polygon_edges.actor->GetMapper()->SetInputDataObject(polygons.data);
  polygon_edges.actor->GetProperty()->SetRepresentationToWireframe();
}

void WorldScene::name_labels() {
  const ViewTheme& t = theme;
  texts.labels[kEyeLabel] = {"eye", Vec3(0.0), t.text, true};
  texts.labels[kImageLabel] = {"image plane", Vec3(0.0), t.text, true};
  texts.labels[kVelocityLabel] = {"V", Vec3(0.0), rgbf(okabe_ito::kVermillion), true};
  texts.labels[kOmegaLabel] = {"Omega", Vec3(0.0), rgbf(okabe_ito::kReddishPurple), true};
  texts.labels[kNormalLabel] = {"N", Vec3(0.0), rgbf(okabe_ito::kBlue), true};
  texts.labels[kUpLabel] = {"U", Vec3(0.0), rgbf(okabe_ito::kBluishGreen), true};
}

WorldScene::Arrow WorldScene::add_arrow(const Rgb8& colour) {
  Arrow a{vtkSmartPointer<vtkActor>::New(), vtkSmartPointer<vtkMatrix4x4>::New()};
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputConnection(arrow_source->GetOutputPort());
  a.actor->SetMapper(mapper);
  a.actor->SetUserMatrix(a.matrix);
  a.actor->GetProperty()->SetColor(colour.r / 255.0, colour.g / 255.0, colour.b / 255.0);
  renderer->AddActor(a.actor);
  return a;
}

void WorldScene::place(Arrow& arrow, const Vec3& origin, const Vec3& direction, double length) {
  arrow.matrix->DeepCopy(arrow_matrix(origin, direction, length).data());
  arrow.actor->Modified();
}

void WorldScene::place_label(WorldLabelId id, const Vec3& at, const std::string& text) {
  texts.labels[size_t(id)].at = at;
  texts.labels[size_t(id)].text = text;
}

// The source: what every frame of the loop shows (the plane's path, the scene's polygons).

template <class Loop>
void WorldScene::take_loop(const Loop& loop) {
  camera = loop.camera;
  path = loop.path;
  largest_velocity = loop.largest_velocity;
  largest_omega = loop.largest_omega;
  depth = loop.depth;
  full_arrow = loop.full_arrow;
  world_centre = loop.world_centre;
}

void WorldScene::load_plane(WindowModel& window) {
  const SceneModel& scene = *window.scene();
  // The loop's numbers are the teaching layer's (display/world_geometry.h), as the page's.
  plane_loop = plane_world_loop(scene.as_script(), scene.scene().camera, scene.current_pose(),
                                SceneModel::kSecondsPerFrame);
  take_loop(plane_loop);
  loop_corners = plane_loop.loop_corners;
  first_pose = plane_loop.first_pose;
  first_view = ViewerPose{};
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

void WorldScene::load_scene(AnimationModel& animation) {
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
  // The walk's numbers are the teaching layer's (display/world_geometry.h), as the page's.
  scene_loop = scene_world_loop(*animator, SceneModel::kSecondsPerFrame);
  take_loop(scene_loop);
  first_view = scene_loop.first_view;
  const Rgb8 grey = kUnreportedPolygon;
  set_coloured_polygons(polygons.data, scene_loop.outlines,
                        std::vector<std::array<unsigned char, 4>>(scene_loop.outlines.size(),
                                                                  {grey.r, grey.g, grey.b, 255}));
}

// One frame: every actor keeps its identity; points, matrices and pixels change.

void WorldScene::place_viewer(const ViewerPose& pose) {
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

void WorldScene::show_frame(const Image& frame) {
  frame_shown_reduction = frame_reduction(frame.width(), frame.height());
  frame_size = QSize(frame.width(), frame.height());
  copy_frame_pixels(frame, frame_pixels, theme.image_background, frame_shown_reduction);
}

int WorldScene::frame_reduction(int width, int height) const {
  std::array<QPointF, 4> p;
  const std::array<Vec3, 4> corners = image_plane_in_world();
  for (size_t k = 0; k < corners.size(); ++k) {
    if (!to_display(corners[k], &p[k])) return 1;
  }
  // Corners top-left, top-right, bottom-right, bottom-left.
  const auto length = [](const QPointF& a, const QPointF& b) {
    return glm::length(Vec2(b.x() - a.x(), b.y() - a.y()));
  };
  const double across = std::max(length(p[0], p[1]), length(p[3], p[2]));
  const double down = std::max(length(p[0], p[3]), length(p[1], p[2]));
  int r = 1;
  while (r < kMaxFrameReduction && width >= 2.0 * r * across && height >= 2.0 * r * down) r *= 2;
  return r;
}

void WorldScene::place_motion(const MotionArrows& arrows) {
  place(this->velocity, arrows.velocity.origin, arrows.velocity.direction, arrows.velocity.length);
  place(omega, arrows.omega.origin, arrows.omega.direction, arrows.omega.length);
  // A vector that its label would print as 0.00 is neither drawn nor labelled.
  const auto tip = [](const WorldArrow& a) {
    return a.length > 0 ? a.origin + glm::normalize(a.direction) * a.length : a.origin;
  };
  place_label(kVelocityLabel, tip(arrows.velocity), velocity_label(arrows));
  place_label(kOmegaLabel, tip(arrows.omega), omega_label(arrows));
  set_polyline(omega_axis.data, arrows.omega_axis, false);
}

void WorldScene::split_path(int frame) {
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

void WorldScene::update_plane(const SceneModel& scene) {
  place_viewer(ViewerPose{});
  const PlanePose pose = scene.current_pose();
  // The frame's numbers are the teaching layer's (display/world_geometry.h), as the page's.
  const PlaneWorldFrame f =
      plane_world_frame(plane_loop, pose, scene.current_motion(), scene.frame());
  centre = pose.point;
  set_textured_quad(plane.data, f.plane_corners);
  const std::vector<Vec3> outline(f.plane_corners.begin(), f.plane_corners.end());
  set_polyline(plane_outline.data, outline, true);
  set_segments(rays.data, std::vector<Vec3>(4, Vec3(0.0)), outline);
  set_polyline(ray_images.data, f.ray_images, true);
  place(normal, f.normal.origin, f.normal.direction, f.normal.length);
  place(up, f.up.origin, f.up.direction, f.up.length);
  place_label(kNormalLabel, f.normal.origin + f.normal.direction * f.normal.length, "N");
  place_label(kUpLabel, f.up.origin + f.up.direction * f.up.length, "U");
  place_motion(f.motion);
  split_path(f.path_index);
  if (exact) show_frame(exact->render(viewer_for_pose(first_pose, pose)));
  caption_body = plane_world_caption(plane_loop);
}

void WorldScene::update_scene(AnimationModel& animation) {
  Animator* animator = animation.animator();
  if (!animator) return;
  const SceneWorldFrame f = scene_world_frame(scene_loop, *animator, SceneModel::kSecondsPerFrame);
  place_viewer(f.view);
  centre = f.eye;
  std::vector<std::array<unsigned char, 4>> colours;
  for (const Rgb8& c : f.colours) colours.push_back({c.r, c.g, c.b, 255});
  set_cell_colours(polygons.data, colours);
  if (f.walking) place_motion(f.motion);
  split_path(f.path_index);
  show_frame(animator->image());
  caption_body = scene_world_caption(true);
}

void WorldScene::show_parts() {
  const auto on = [this](WorldPart part) { return shown[size_t(part)]; };
  const bool plane_mode = !scene_mode;
  // Through the eye the ball would enclose the camera and the image plane would cover what
  // it shows; the frustum's border stays, as the frame of what the camera sees.
  eye->SetVisibility(on(WorldPart::kFrustum) && !from_eye);
  frustum.actor->SetVisibility(on(WorldPart::kFrustum));
  texts.labels[kEyeLabel].shown = on(WorldPart::kFrustum) && !from_eye;
  image_plane.actor->SetVisibility(on(WorldPart::kImagePlane) && !from_eye);
  texts.labels[kImageLabel].shown = from_eye ? on(WorldPart::kFrustum) : on(WorldPart::kImagePlane);
  texts.labels[kImageLabel].text = from_eye ? "the camera's image" : "image plane";
  for (vtkProp* p : {static_cast<vtkProp*>(plane.actor), static_cast<vtkProp*>(plane_outline.actor),
                     static_cast<vtkProp*>(normal.actor), static_cast<vtkProp*>(up.actor)}) {
    p->SetVisibility(plane_mode && on(WorldPart::kPlane));
  }
  texts.labels[kNormalLabel].shown = texts.labels[kUpLabel].shown =
      plane_mode && on(WorldPart::kPlane);
  velocity.actor->SetVisibility(on(WorldPart::kVelocity));
  texts.labels[kVelocityLabel].shown = on(WorldPart::kVelocity);
  // Omega's arrow starts at the eye: through the eye it would fill the view (the caption
  // gives its value instead).
  for (vtkProp* p : {static_cast<vtkProp*>(omega.actor), static_cast<vtkProp*>(omega_axis.actor)}) {
    p->SetVisibility(on(WorldPart::kOmega) && !from_eye);
  }
  texts.labels[kOmegaLabel].shown = on(WorldPart::kOmega) && !from_eye;
  rays.actor->SetVisibility(plane_mode && on(WorldPart::kRays) && !from_eye);
  ray_images.actor->SetVisibility(plane_mode && on(WorldPart::kRays) && !from_eye);
  path_past.actor->SetVisibility(on(WorldPart::kPath));
  path_future.actor->SetVisibility(on(WorldPart::kPath));
  polygons.actor->SetVisibility(scene_mode && on(WorldPart::kScene));
  polygon_edges.actor->SetVisibility(scene_mode && on(WorldPart::kScene));
}

void WorldScene::apply_theme() {
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

std::string WorldScene::caption() const {
  if (!from_eye) return caption_body;
  const std::string& omega_text = texts.labels[kOmegaLabel].text;
  // Short: through the eye the picture is smaller than the frame it is drawn in, and the
  // lines on the image plane, the rays and the depth do not apply.
  return "Seen through the eye: the frame is the image's border (" +
         (omega_text.empty() ? std::string("no Omega") : omega_text) +
         ", its arrow, the eye, the image plane and the rays left out). Drag to look "
         "around, or press Reset view.\n" +
         (scene_mode ? std::string("Polygons in their level's colour; culled pale, hidden dark.")
                     : std::string("V is the velocity of the body point at the eye. Path of "
                                   "the plane's centre: past thick, future thin."));
}

bool WorldScene::to_display(const Vec3& at, QPointF* display) const {
  renderer->SetWorldPoint(at.x, at.y, at.z, 1.0);
  renderer->WorldToDisplay();
  const double* d = renderer->GetDisplayPoint();
  *display = QPointF(d[0], d[1]);
  return d[2] >= 0.0 && d[2] <= 1.0;
}

bool WorldScene::to_canvas(const Vec3& at, QPointF* canvas) const {
  const int* size = window->GetSize();
  QPointF d;
  const bool in_front = to_display(at, &d);
  // VTK's display y runs upwards.
  *canvas = QPointF(d.x(), size[1] - d.y());
  return in_front && d.x() >= 0.0 && d.x() <= size[0] && d.y() >= 0.0 && d.y() <= size[1];
}

std::array<Vec3, 4> WorldScene::image_plane_in_world() const {
  std::array<Vec3, 4> corners = image_plane_corners(camera, depth);
  for (Vec3& c : corners) c = viewer_to_world(view, c);
  return corners;
}

double WorldScene::drawn_share() const {
  std::vector<Vec3> points;
  vtkPoints* drawn = (scene_mode ? polygons.data : plane.data)->GetPoints();
  for (vtkIdType i = 0; drawn && i < drawn->GetNumberOfPoints(); ++i) {
    const double* p = drawn->GetPoint(i);
    points.emplace_back(p[0], p[1], p[2]);
  }
  if (!from_eye) {
    points.push_back(viewer_to_world(view, Vec3(0.0)));
    for (const Vec3& c : image_plane_in_world()) points.push_back(c);
  }
  const int* size = window->GetSize();
  std::vector<QPointF> seen;
  for (const Vec3& p : points) {
    QPointF d;
    if (to_display(p, &d)) seen.emplace_back(d.x(), size[1] - d.y());
  }
  const QRectF free = texts.free_area();
  return hull_share(seen, free.isEmpty() ? QRectF(0, 0, size[0], size[1]) : free);
}

std::vector<QPolygonF> WorldScene::content_outlines() const {
  std::vector<std::vector<Vec3>> quads;
  if (image_plane.actor->GetVisibility()) {
    const std::array<Vec3, 4> corners = image_plane_in_world();
    quads.emplace_back(corners.begin(), corners.end());
  }
  vtkPoints* corners = plane.data->GetPoints();
  if (plane.actor->GetVisibility() && corners) {
    std::vector<Vec3> quad;
    for (vtkIdType i = 0; i < corners->GetNumberOfPoints(); ++i) {
      const double* p = corners->GetPoint(i);
      quad.emplace_back(p[0], p[1], p[2]);
    }
    quads.push_back(quad);
  }
  const int* size = window->GetSize();
  std::vector<QPolygonF> outlines;
  for (const std::vector<Vec3>& quad : quads) {
    QPolygonF outline;
    for (const Vec3& p : quad) {
      QPointF d;
      if (!to_display(p, &d)) break;
      outline << QPointF(d.x(), size[1] - d.y());
    }
    if (outline.size() == int(quad.size()) && outline.size() >= 3) outlines.push_back(outline);
  }
  return outlines;
}

}  // namespace oflab
