// Scene shifting for planes parallel to the image plane (dissertation chapter 3; the slice
// calculus and per-slice decisions are core/scene_shifting/scene_shifting.h).
#include "scene_shifting/scene_shifting_renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "engine/engine.h"
#include "engine/wall_clock.h"
#include "image/composite.h"
#include "scene/scene_resources.h"

namespace oflab {
namespace {

using Clock = WallClock;

constexpr double kMinDepth = 1e-6;  // corners at or behind this depth are not drawn

bool is_identity(const SliceTransform& t) {
  return t.scale == 1.0 && t.translation.x == 0.0 && t.translation.y == 0.0;
}

// `second` after `first`: p -> s2 (s1 p + t1) + t2.
SliceTransform then(const SliceTransform& first, const SliceTransform& second) {
  return {second.scale * first.scale, second.scale * first.translation + second.translation};
}

// A pure shift is placed on whole pixels (no resampling); a scaling is applied as it is.
SliceTransform placed(const SliceTransform& t) {
  if (t.scale != 1.0) return t;
  return {1.0, Vec2(std::round(t.translation.x), std::round(t.translation.y))};
}

Mat3 layer_origin_shift(double x, double y) {
  Mat3 m(1.0);
  m[2][0] = x;  // glm is column-major: column 2 holds the translation
  m[2][1] = y;
  return m;
}

// The level a polygon of a slice is counted at (see the header's "Levels").
Level layer_level(LayerUpdate update) {
  switch (update) {
    case LayerUpdate::kStill:
      return Level::kNone;
    case LayerUpdate::kShifted:
      return Level::kTranslate;
    case LayerUpdate::kScaled:
      return Level::kAffine;
    case LayerUpdate::kRebuilt:
      break;
  }
  return Level::kRerender;
}

}  // namespace

struct SceneShiftingRenderer::SliceLayer {
  std::vector<int> polygons;       // far to near
  Slice current;                   // the slice's depth range seen from the current view
  Layer layer;                     // the rendered slice, empty when nothing is drawn
  int origin_x = 0, origin_y = 0;  // frame pixel of layer pixel (0, 0) when built
  bool clipped = false;            // the guard band cut the layer
  SliceTransform moved;            // built view -> current view, centred pixels
  double accumulated_error_px = 0.0;
};

ViewerStep viewer_step(const RigidMotion& motion) {
  ViewerStep step;
  step.translation = -motion.velocity;
  step.rotation = -motion.omega;
  return step;
}

double scene_shifting_memory_bytes(const Scene& scene, const Camera& camera, double guard_band,
                                   int occupied_slices) {
  double bytes = 4.0 * camera.width * camera.height;  // the frame
  for (const Image& t : scene.textures) bytes += 4.0 * t.pixel_count();
  bytes += polygon_texture_copy_bytes(scene);
  if (occupied_slices > 0) {
    const double grown = 1.0 + 2.0 * guard_band;
    bytes += (occupied_slices + 2.0) * 4.0 * grown * camera.width * grown * camera.height;
  }
  return bytes;
}

namespace {

// The phrase of scene_memory_limit_problem for a scene-shifting renderer.
std::string shifting_memory_problem(const Scene& scene, const Camera& camera, double guard_band,
                                    int occupied_slices) {
  std::ostringstream subject;
  subject << "scene shifting of the scene's " << scene.polygons.size() << " polygons";
  if (occupied_slices > 0) {
    subject << " in " << occupied_slices << (occupied_slices == 1 ? " slice" : " slices");
  }
  subject << " at " << camera.width << " x " << camera.height << " px";
  return scene_memory_limit_problem(
      scene_shifting_memory_bytes(scene, camera, guard_band, occupied_slices), subject.str(),
      occupied_slices > 0 ? "slice layers and textures" : "textures");
}

}  // namespace

SceneShiftingRenderer::SceneShiftingRenderer(const Scene& scene, const Camera& camera,
                                             const SceneShiftingSettings& settings)
    : scene_(scene), camera_(camera), settings_(settings) {
  if (const char* problem = camera_problem(camera); problem[0] != '\0') {
    throw std::invalid_argument(std::string("camera: ") + problem);
  }
  if (!(settings.epsilon_px > 0.0) || !std::isfinite(settings.epsilon_px)) {
    throw std::invalid_argument("epsilon_px: must be a positive number of pixels");
  }
  if (!(settings.design_speed >= 0.0) || !std::isfinite(settings.design_speed)) {
    throw std::invalid_argument("design_speed: must be zero or a positive speed");
  }
  if (!(settings.near >= 0.0) || !std::isfinite(settings.near)) {
    throw std::invalid_argument("near: must be zero (the nearest polygon) or a positive depth");
  }
  if (!(settings.guard_band >= 0.0 && settings.guard_band <= 16.0)) {
    throw std::invalid_argument("guard_band: must be from 0 to 16 image sizes");
  }
  for (const ScenePolygon& p : scene.polygons) {
    const PolygonProblem problem = scene_polygon_problem(scene, p);
    if (!problem.field.empty()) {
      throw std::invalid_argument("polygon '" + p.name + "': " + problem.field + ": " +
                                  problem.message);
    }
  }
  if (const std::string problem = shifting_memory_problem(scene, camera, settings.guard_band, 0);
      !problem.empty()) {
    throw std::invalid_argument(problem);
  }
  for (const ScenePolygon& p : scene.polygons) {
    const Image& texture = scene.textures[p.texture];
    std::vector<Vec2> texels;
    for (const Vec2& uv : polygon_outline(p)) {
      texels.emplace_back(uv.x * texture.width(), uv.y * texture.height());
    }
    textures_.push_back(make_layer(texture, ConvexPolygon::from_vertices(texels)));
  }
  frame_ = Image(camera.width, camera.height);
}

SceneShiftingRenderer::~SceneShiftingRenderer() = default;

void SceneShiftingRenderer::cut_slices(const ViewerPose& view) {
  const int n = static_cast<int>(scene_.polygons.size());
  std::vector<double> depth(n);
  double nearest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i) {
    const ScenePolygon& p = scene_.polygons[i];
    depth[i] = to_view(view, p.centre).z;
    if (depth[i] <= kMinDepth) continue;
    const Vec3 front = direction_to_view(view, p.front);
    if (std::abs(front.x) > 1e-6 || std::abs(front.y) > 1e-6 || front.z > 0.0) {
      throw std::invalid_argument("polygon '" + p.name +
                                  "': not parallel to the image plane (scene shifting needs "
                                  "planes facing the viewer)");
    }
    nearest = std::min(nearest, depth[i]);
  }
  SliceParameters params;
  params.speed = settings_.design_speed;
  params.focal_px = camera_.focal_px;
  params.epsilon_px = settings_.epsilon_px;
  params.near = settings_.near > 0.0 ? settings_.near : (std::isfinite(nearest) ? nearest : 1.0);
  params.max_slices = settings_.max_slices;
  slices_ = scene_slices(params);
  std::vector<int> slice_of(n, -1);
  std::vector<bool> occupied(slices_.size(), false);
  for (int i = 0; i < n; ++i) {
    if (depth[i] <= kMinDepth) continue;
    slice_of[i] = std::max(0, slice_index_at_depth(slices_, depth[i]));
    occupied[slice_of[i]] = true;
  }
  const int occupied_slices = static_cast<int>(std::count(occupied.begin(), occupied.end(), true));
  if (const std::string problem =
          shifting_memory_problem(scene_, camera_, settings_.guard_band, occupied_slices);
      !problem.empty()) {
    throw std::invalid_argument(problem);
  }
  layers_.assign(slices_.size(), SliceLayer{});
  polygon_slice_ = std::move(slice_of);
  for (int i = 0; i < n; ++i) {
    if (polygon_slice_[i] >= 0) layers_[polygon_slice_[i]].polygons.push_back(i);
  }
  for (std::size_t s = 0; s < layers_.size(); ++s) {
    std::vector<int>& list = layers_[s].polygons;
    std::stable_sort(list.begin(), list.end(), [&](int a, int b) { return depth[a] > depth[b]; });
    layers_[s].current = slices_[s];
  }
  built_corners_.assign(n, {});
}

// Renders the slice's polygons exactly from `view` into its layer, far to near, within the
// frame grown by the guard band.
void SceneShiftingRenderer::build(int slice, const ViewerPose& view,
                                  SceneShiftingFrameReport& report) {
  SliceLayer& s = layers_[slice];
  s.moved = SliceTransform{};
  s.accumulated_error_px = 0.0;
  s.layer = Layer{};
  struct Drawn {
    int polygon;
    Mat3 warp;
  };
  std::vector<Drawn> drawn;
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  for (int i : s.polygons) {
    built_corners_[i].clear();
    const ScenePolygon& p = scene_.polygons[i];
    const Image& texture = scene_.textures[p.texture];
    const PlanePose pose = polygon_pose(p, view, {texture.width(), texture.height()});
    if (!plane_visibility_problem(pose).empty()) continue;
    for (const Vec3& corner : plane_corners(pose)) {
      const Vec2 c = project_centred(camera_, corner);
      built_corners_[i].push_back(c);
      const Vec2 px = centred_to_pixel(camera_, c);
      x0 = std::min(x0, px.x), y0 = std::min(y0, px.y);
      x1 = std::max(x1, px.x), y1 = std::max(y1, px.y);
    }
    drawn.push_back({i, exact_texture_warp(camera_, pose)});
  }
  const double gx = settings_.guard_band * camera_.width;
  const double gy = settings_.guard_band * camera_.height;
  const int bx0 = static_cast<int>(std::floor(std::max(x0, -gx)));
  const int by0 = static_cast<int>(std::floor(std::max(y0, -gy)));
  const int bx1 = static_cast<int>(std::ceil(std::min(x1, camera_.width + gx)));
  const int by1 = static_cast<int>(std::ceil(std::min(y1, camera_.height + gy)));
  if (!s.polygons.empty()) ++report.rebuilt;
  if (drawn.empty() || bx1 <= bx0 || by1 <= by0) return;
  s.clipped = x0 < -gx || y0 < -gy || x1 > camera_.width + gx || y1 > camera_.height + gy;
  s.origin_x = bx0;
  s.origin_y = by0;
  Image image(bx1 - bx0, by1 - by0);
  WarpOptions options;
  options.sampling = settings_.sampling;
  if (drawn.size() == 1) {  // over a transparent image a warp is its own composite
    report.pixels_written +=
        warp_layer_into(textures_[drawn[0].polygon], drawn[0].warp, image, bx0, by0, options)
            .pixels_written;
    s.layer = make_layer(std::move(image));
    return;
  }
  if (scratch_.image.width() != image.width() || scratch_.image.height() != image.height()) {
    scratch_ = make_layer(Image(image.width(), image.height()));
  }
  for (const Drawn& d : drawn) {
    scratch_.image.fill(Pixel{});
    const WarpStats stats =
        warp_layer_into(textures_[d.polygon], d.warp, scratch_.image, bx0, by0, options);
    report.pixels_written += stats.pixels_written;
    composite_over(image, scratch_, 0, 0);
  }
  s.layer = make_layer(std::move(image));
}

// A layer cut by the guard band must still cover the frame where it was cut.
bool SceneShiftingRenderer::covers_frame(const SliceLayer& s) const {
  if (!s.clipped || s.layer.empty()) return true;
  const SliceTransform t = placed(s.moved);
  const Vec2 a = centred_to_pixel(
      camera_, apply_slice_transform(t, pixel_to_centred(camera_, Vec2(s.origin_x, s.origin_y))));
  const Vec2 b = centred_to_pixel(
      camera_, apply_slice_transform(
                   t, pixel_to_centred(camera_, Vec2(s.origin_x + s.layer.image.width(),
                                                     s.origin_y + s.layer.image.height()))));
  return a.x <= 0.0 && a.y <= 0.0 && b.x >= camera_.width && b.y >= camera_.height;
}

void SceneShiftingRenderer::compose(SceneShiftingFrameReport& report) {
  frame_.fill(Pixel{});
  WarpOptions options;
  options.sampling = settings_.sampling;
  for (auto it = layers_.rbegin(); it != layers_.rend(); ++it) {
    const SliceLayer& s = *it;
    if (s.layer.empty()) continue;
    const SliceTransform t = placed(s.moved);
    if (t.scale == 1.0) {
      report.pixels_composited +=
          composite_over(frame_, s.layer, s.origin_x + static_cast<int>(t.translation.x),
                         s.origin_y + static_cast<int>(t.translation.y));
      continue;
    }
    const Mat3 m = centred_to_pixel_homography(camera_, slice_transform_matrix(t)) *
                   layer_origin_shift(s.origin_x, s.origin_y);
    const WarpedLayer warped = warp_layer(s.layer, m, options);
    report.pixels_written += warped.stats.pixels_written;
    if (!warped.layer.empty()) {
      report.pixels_composited +=
          composite_over(frame_, warped.layer, warped.offset_x, warped.offset_y);
    }
  }
}

std::vector<Vec2> SceneShiftingRenderer::shown_corners(int polygon) const {
  const int slice = polygon_slice_.at(polygon);
  if (slice < 0) return {};
  const SliceTransform t = placed(layers_[slice].moved);
  std::vector<Vec2> shown;
  for (const Vec2& c : built_corners_[polygon]) shown.push_back(apply_slice_transform(t, c));
  return shown;
}

double SceneShiftingRenderer::measured_error(const ViewerPose& view) const {
  double worst = 0.0;
  for (std::size_t i = 0; i < scene_.polygons.size(); ++i) {
    const std::vector<Vec2> shown = shown_corners(static_cast<int>(i));
    if (shown.empty()) continue;
    const ScenePolygon& p = scene_.polygons[i];
    const Image& texture = scene_.textures[p.texture];
    const auto corners = plane_corners(polygon_pose(p, view, {texture.width(), texture.height()}));
    bool in_front = true;
    for (const Vec3& c : corners) in_front = in_front && c.z > kMinDepth;
    if (!in_front) continue;
    for (std::size_t k = 0; k < corners.size(); ++k) {
      worst = std::max(worst, glm::length(shown[k] - project_centred(camera_, corners[k])));
    }
  }
  return worst;
}

AnimationFrame SceneShiftingRenderer::start(const ViewerPose& view) {
  frame_index_ = 0;
  totals_ = SceneShiftingTotals{};
  cut_slices(view);
  SceneShiftingFrameReport report;
  report.slices = static_cast<int>(slices_.size());
  for (const SliceLayer& s : layers_) report.occupied += s.polygons.empty() ? 0 : 1;
  const auto t0 = Clock::now();
  for (int s = 0; s < report.slices; ++s) build(s, view, report);
  compose(report);
  report.time_ms = ms_since(t0);
  report.updates.assign(slices_.size(), LayerUpdate::kRebuilt);
  report.max_measured_error_px = measured_error(view);
  return finish(std::move(report));
}

AnimationFrame SceneShiftingRenderer::advance(const ViewerPose& /*previous*/,
                                              const RigidMotion& motion,
                                              const ViewerPose& current) {
  SceneShiftingFrameReport report;
  report.frame = ++frame_index_;
  report.slices = static_cast<int>(slices_.size());
  for (const SliceLayer& s : layers_) report.occupied += s.polygons.empty() ? 0 : 1;
  const ViewerStep step = viewer_step(motion);
  report.view_turned = turns_view_direction(step);
  const auto t0 = Clock::now();
  std::vector<Slice> current_slices;
  std::vector<double> accumulated;
  for (const SliceLayer& s : layers_) {
    current_slices.push_back(s.current);
    accumulated.push_back(s.accumulated_error_px);
  }
  // The viewer would reach the nearest slice: nothing can be shifted.
  const bool reaches = step.translation.z >= current_slices.front().near;
  std::vector<SliceDecision> decisions(layers_.size());
  if (!reaches && settings_.policy->allows_reuse()) {
    decisions =
        decide_slice_updates(camera_, current_slices, step, accumulated, settings_.epsilon_px);
  } else {
    for (SliceDecision& d : decisions) d.action = SliceAction::kRebuild;
  }
  for (std::size_t i = 0; i < layers_.size(); ++i) {
    SliceLayer& s = layers_[i];
    LayerUpdate update = LayerUpdate::kRebuilt;
    if (s.polygons.empty()) {
      update = LayerUpdate::kStill;  // nothing to draw: an empty slice costs nothing
    } else if (decisions[i].action == SliceAction::kShift) {
      const SliceTransform t = slice_transform(camera_, s.current, step.translation);
      s.moved = then(s.moved, t);
      s.accumulated_error_px = decisions[i].accumulated_error_px;
      if (!covers_frame(s)) {
        update = LayerUpdate::kRebuilt;
      } else if (s.moved.scale != 1.0) {
        update = LayerUpdate::kScaled;
        ++report.scaled;
      } else if (is_identity(t)) {
        update = LayerUpdate::kStill;
      } else {
        update = LayerUpdate::kShifted;
        ++report.shifted;
      }
    }
    s.current.near -= step.translation.z;
    if (!is_background(s.current)) s.current.far -= step.translation.z;
    if (update == LayerUpdate::kRebuilt) build(static_cast<int>(i), current, report);
    report.updates.push_back(update);
  }
  compose(report);
  report.time_ms = ms_since(t0);
  report.max_measured_error_px = measured_error(current);
  return finish(std::move(report));
}

// The frame in the animators' terms: each drawn polygon at the level of its slice's update.
AnimationFrame SceneShiftingRenderer::finish(SceneShiftingFrameReport&& report) {
  if (report.frame > 0) {
    totals_.rebuilt_layers += report.rebuilt;
    totals_.shifted_layers += report.shifted + report.scaled;
  }
  if (report.view_turned) {
    ++totals_.turning_frames;
    if (report.rebuilt == report.occupied) ++totals_.turning_frames_all_rebuilt;
  }
  AnimationFrame f;
  f.frame = report.frame;
  f.layers = static_cast<int>(scene_.polygons.size());
  for (int p = 0; p < f.layers; ++p) {
    const int slice = polygon_slice_[p];
    if (slice < 0 || built_corners_[p].empty()) {
      ++f.outside_frustum;
      continue;
    }
    ++f.levels[static_cast<int>(layer_level(report.updates[slice]))];
  }
  f.time_ms = report.time_ms;
  f.update_ms = report.time_ms;
  f.pixels_written = report.pixels_written;
  f.pixels_composited = report.pixels_composited;
  f.max_measured_error_px = report.max_measured_error_px;
  if (report.view_turned) f.note = "view turned: the slices are rebuilt";
  slice_report_ = std::move(report);
  return f;
}

std::vector<LayerOutline> SceneShiftingRenderer::outlines(const ViewerPose& /*view*/) const {
  std::vector<LayerOutline> result;
  for (std::size_t slice = layers_.size(); slice-- > 0;) {
    for (int p : layers_[slice].polygons) {
      LayerOutline outline;
      outline.level = layer_level(slice_report_.updates.at(slice));
      outline.polygon = p;
      for (const Vec2& c : shown_corners(p)) outline.points.push_back(centred_to_pixel(camera_, c));
      if (!outline.points.empty()) result.push_back(std::move(outline));
    }
  }
  return result;
}

double script_design_speed(const ViewerScript& script) {
  double speed = 0.0;
  for (const ViewerFrame& f : script.frames) {
    const Vec3 v = viewer_step(f.motion).translation;
    speed = std::max(speed, std::hypot(v.x, v.y));
  }
  return speed;
}

std::unique_ptr<SceneShiftingAnimator> make_scene_shifting_animator(
    std::shared_ptr<const Scene> scene, ViewerScript script, SceneShiftingSettings settings) {
  if (settings.design_speed == 0.0) settings.design_speed = script_design_speed(script);
  return std::make_unique<SceneShiftingAnimator>(std::move(scene), std::move(script), settings);
}

}  // namespace oflab
