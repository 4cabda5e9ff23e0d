// Algorithm 1 for many polygons with a moving viewer (dissertation sections 5.5 and 5.6.2),
// with visibility culling beyond the dissertation; see core/scene/scene_animator.h.
#include "scene/scene_animator.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "engine/wall_clock.h"
#include "flow/homography.h"
#include "image/composite.h"

namespace oflab {
namespace {

using Clock = WallClock;

// Throws std::invalid_argument naming the first problem of a scene engine's inputs: the
// camera, the budget, the near plane, the guard band, the hidden test's margins, a polygon,
// the scene's memory and its contents' detail (see SceneEngine's constructor).
void check_scene_inputs(const Scene& scene, const Camera& camera, const SceneSettings& settings) {
  if (const char* problem = camera_problem(camera); problem && *problem) {
    throw std::invalid_argument(std::string("camera: ") + problem);
  }
  if (const std::string problem = frame_budget_problem(settings.engine.budget); !problem.empty()) {
    throw std::invalid_argument("budget: " + problem);
  }
  if (!(settings.near > 0.0 && std::isfinite(settings.near))) {
    throw std::invalid_argument("near plane distance must be positive");
  }
  if (!(settings.guard_band >= 0.0 && settings.guard_band <= 16.0)) {
    throw std::invalid_argument("guard band must be from 0 to 16 image sizes");
  }
  if (!(settings.occluder_inset_px >= 0.0) || !(settings.candidate_margin_px >= 0.0)) {
    throw std::invalid_argument("hidden-test margins must not be negative");
  }
  for (std::size_t i = 0; i < scene.polygons.size(); ++i) {
    const PolygonProblem p = scene_polygon_problem(scene, scene.polygons[i]);
    if (!p.field.empty()) {
      throw std::invalid_argument("polygon " + std::to_string(i) + " ('" + scene.polygons[i].name +
                                  "'): " + p.field + ": " + p.message);
    }
  }
  if (const std::string problem = depth_mesh_settings_problem(settings.mesh); !problem.empty()) {
    throw std::invalid_argument(problem);
  }
  if (const std::string problem = scene_memory_problem(scene, camera, settings.guard_band);
      !problem.empty()) {
    throw std::invalid_argument(problem);
  }
  if (const std::string problem =
          scene_content_problem(scene, camera, settings.engine.content.quality);
      !problem.empty()) {
    throw std::invalid_argument(problem);
  }
}

}  // namespace

SceneEngine::SceneEngine(const Scene& scene, const Camera& camera, const SceneSettings& settings)
    : scene_(scene),
      camera_(camera),
      settings_(settings),
      ledger_(*settings.engine.policy, settings.engine.budget, camera.width, camera.height) {
  check_scene_inputs(scene, camera, settings);
  frustum_ = view_frustum(camera_, settings_.near, 1.0);
  bsp_ = BspTree(scene.polygons);
  for (const Image& t : scene.textures) scratch_textures_.push_back(make_layer(t));
  states_ = make_polygon_layers(scene);
  for (const BspFragment& f : bsp_.fragments()) {
    if (!f.whole) states_[f.polygon]->whole = false;
  }
  statuses_.assign(scene.polygons.size(), PolygonStatus::kOutsideFrustum);
  levels_.assign(scene.polygons.size(), Level::kNone);
  frame_ = Image(camera_.width, camera_.height);
  if (settings.engine.policy->frame_warp == FrameWarp::kNodeImages) {
    CacheContext context;
    context.near = settings.near;
    context.guard_band = settings.guard_band;
    context.sampling = settings.engine.sampling;
    context.content = settings.engine.content;
    cache_ = std::make_unique<HierarchicalCache>(scene, camera_, bsp_, settings.cache, context);
  }
}

SceneEngine::~SceneEngine() = default;

AnimationFrame SceneEngine::start(const ViewerPose& view) {
  frame_index_ = 0;
  plane_known_ = false;
  has_render_ = false;
  next_index_ = -1;
  split_ = 0.0;
  source_of_.clear();
  for (auto& s : states_) s->live = false;
  if (cache_) cache_->restart();
  return run_frame(nullptr, nullptr, view);
}

AnimationFrame SceneEngine::advance(const ViewerPose& previous, const RigidMotion& motion,
                                    const ViewerPose& current) {
  ++frame_index_;
  return run_frame(&previous, &motion, current);
}

void SceneEngine::classify(const ViewerPose& view, AnimationFrame& report) {
  const double gw = settings_.guard_band * camera_.width;
  const double gh = settings_.guard_band * camera_.height;
  for (std::size_t i = 0; i < states_.size(); ++i) {
    PolygonLayer& s = *states_[i];
    const ScenePolygon& polygon = scene_.polygons[i];
    s.updated = false;
    s.exact_region = ConvexPolygon();
    s.region_known = false;
    const Vec3 front = direction_to_view(view, polygon.front);
    const Vec3 centre = to_view(view, polygon.centre);
    // A two-sided sheet is culled only edge-on: when both of its sides face away.
    if (is_back_facing(front, centre) && (!polygon.two_sided || is_back_facing(-front, centre))) {
      statuses_[i] = PolygonStatus::kBackFacing;
      ++report.back_facing;
      continue;
    }
    s.clipped.points.clear();
    for (const Vec3& v : s.world_vertices) s.clipped.points.push_back(to_view(view, v));
    s.clipped.uv = s.uv;
    clip_to_frustum_in_place(s.clipped, frustum_);
    if (s.clipped.empty()) {
      statuses_[i] = PolygonStatus::kOutsideFrustum;
      ++report.outside_frustum;
      continue;
    }
    statuses_[i] = PolygonStatus::kHidden;  // until it is updated
    // The engine animates the whole texture rectangle: it must lie beyond the near plane
    // and project within the guard band.
    s.needs_clipping = false;
    for (const Vec2& corner : {Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)}) {
      const Vec3 p = to_view(view, polygon_point(polygon, corner));
      if (p.z < settings_.near) {
        s.needs_clipping = true;
        break;
      }
      const Vec2 q = centred_to_pixel(camera_, project_centred(camera_, p));
      if (q.x < -gw || q.x > camera_.width + gw || q.y < -gh || q.y > camera_.height + gh) {
        s.needs_clipping = true;
        break;
      }
    }
  }
}

ConvexPolygon SceneEngine::exact_region(const ViewPolygon& clipped) const {
  if (clipped.empty()) return ConvexPolygon();
  return project_to_pixels(camera_, clipped);
}

ConvexPolygon SceneEngine::fragment_region(int fragment, const ViewerPose& view) const {
  const BspFragment& f = bsp_.fragments()[fragment];
  const PolygonLayer& s = *states_[f.polygon];
  if (statuses_[f.polygon] == PolygonStatus::kAnimated && s.animator) {
    // Through the displayed warp, so the pieces of one layer fit together exactly.
    try {
      return transform(texel_polygon(f.uv, s.texture_size), s.animator->displayed_warp());
    } catch (const std::invalid_argument&) {
      // Falls through to the exact image of the piece.
    }
  }
  ViewPolygon piece;
  for (const Vec3& v : f.vertices) piece.points.push_back(to_view(view, v));
  piece.uv = f.uv;
  return exact_region(clip_to_frustum(piece, frustum_));
}

const ConvexPolygon& SceneEngine::polygon_region(int polygon) {
  PolygonLayer& s = *states_[polygon];
  if (!s.region_known) {
    s.exact_region = exact_region(s.clipped);
    s.region_known = true;
  }
  return s.exact_region;
}

ConvexPolygon SceneEngine::hidden_candidate(int fragment, const ViewerPose& view) {
  const BspFragment& f = bsp_.fragments()[fragment];
  if (states_[f.polygon]->whole) return polygon_region(f.polygon);
  ViewPolygon piece;
  for (const Vec3& v : f.vertices) piece.points.push_back(to_view(view, v));
  piece.uv = f.uv;
  return exact_region(clip_to_frustum(piece, frustum_));
}

bool SceneEngine::cadence_frame() const {
  return frame_index_ % std::max(1, settings_.engine.cadence) == 0;
}

void SceneEngine::update_frame_plane(const ViewerPose& current) {
  const StabilizationPlane& given = settings_.engine.stabilization;
  if (!given.automatic) {
    plane_point_ = given.point;
    plane_normal_ = given.normal;
    plane_at_infinity_ = false;
  } else if (cadence_frame() || !plane_known_) {
    // The plane of least parallax of what is seen now, kept in world coordinates.
    Vec3 m(0.0);
    const bool fitted =
        fit_inverse_depth_plane(render_depth(scene_, camera_, current, settings_.near), camera_, m);
    plane_at_infinity_ = !fitted || glm::length(m) < 1e-12;
    if (!plane_at_infinity_) {
      const Mat3 to_world = glm::transpose(current.rotation);
      plane_point_ = to_world * (m / glm::dot(m, m) - current.translation);
      plane_normal_ = to_world * m;
    }
  }
  plane_known_ = true;
  frame_plane_ = plane_at_infinity_ ? Vec3(0.0)
                                    : plane_vector_of(to_view(current, plane_point_),
                                                      direction_to_view(current, plane_normal_));
}

void SceneEngine::keep_render(const ViewerPose& current, const ViewerPose* previous) {
  rendered_frame_ = frame_;
  rendered_depth_ = render_depth(scene_, camera_, current, settings_.near);
  rendered_view_ = current;
  rendered_previous_ = previous ? *previous : current;
  rendered_index_ = frame_index_;
  has_render_ = true;
  next_index_ = -1;
  source_of_.clear();
}

double SceneEngine::reproject_frame(const ViewerPose& current, AnimationFrame& report) {
  double diagnostics_ms = 0.0;
  const auto t0 = Clock::now();
  const ReusePolicy& policy = *settings_.engine.policy;
  if (policy.pixel_motion == PixelMotion::kMotionVectors) {
    diagnostics_ms = generate_frame(current, report);
    report.update_ms = ms_since(t0) - diagnostics_ms;
  } else if (policy.pixel_motion == PixelMotion::kBetweenRenders) {
    diagnostics_ms = interpolate_frame(current, report);
    report.update_ms = ms_since(t0) - diagnostics_ms;
  } else {
    Reprojection r = reproject_by_depth(rendered_frame_, rendered_depth_, camera_,
                                        viewer_step(rendered_view_, current), settings_.hole_fill,
                                        settings_.near);
    report.update_ms = ms_since(t0);
    diagnostics_ms =
        show_splats(std::move(r.image), std::move(r.source), r.unreached, r.pixels_written,
                    r.source_pixels, r.max_error_px, current, report);
  }
  mark_reprojected(current, report);
  return diagnostics_ms;
}

double SceneEngine::show_splats(Image image, std::vector<int> source,
                                const std::vector<char>& unreached, std::int64_t pixels_written,
                                std::int64_t source_pixels, double max_error_px,
                                const ViewerPose& current, AnimationFrame& report) {
  const auto t0 = Clock::now();
  const DepthFrame now = render_depth(scene_, camera_, current, settings_.near);
  std::int64_t holes = 0;
  for (std::size_t k = 0; k < unreached.size(); ++k) holes += unreached[k] && now.polygon[k] >= 0;
  const double diagnostics_ms = ms_since(t0);
  lazy_clear_.forget();  // the frame is not the last compose's
  frame_ = std::move(image);
  source_of_ = std::move(source);
  report.pixels_written = pixels_written;
  report.model_work = static_cast<double>(source_pixels) * kPerspectiveWarpCost;
  report.hole_pixels = holes;
  report.max_measured_error_px = max_error_px;
  return diagnostics_ms;
}

double SceneEngine::generate_frame(const ViewerPose& current, AnimationFrame& report) {
  GeneratedFrame g = extrapolate_by_motion(
      rendered_frame_, rendered_depth_, camera_, viewer_step(rendered_view_, rendered_previous_),
      frame_index_ - rendered_index_, settings_.engine.policy->inpaint, settings_.near);
  // The error against the true step and the holes against the depth now: diagnostics, their
  // time returned for the caller to leave out.
  const auto t0 = Clock::now();
  measure_generated_frame(rendered_depth_, camera_, viewer_step(rendered_view_, current),
                          render_depth(scene_, camera_, current, settings_.near), g);
  const double diagnostics_ms = ms_since(t0);
  lazy_clear_.forget();  // the frame is not the last compose's
  frame_ = std::move(g.image);
  source_of_ = std::move(g.source);
  report.pixels_written = g.pixels_written + g.inpainted_pixels;
  report.model_work = static_cast<double>(g.source_pixels) * kPerspectiveWarpCost;
  report.hole_pixels = g.hole_pixels;
  report.inpainted_pixels = g.inpainted_pixels;
  report.max_measured_error_px = g.max_error_px;
  return diagnostics_ms;
}

void SceneEngine::mark_reprojected(const ViewerPose& current, AnimationFrame& report) {
  bsp_.back_to_front(eye_position(current), order_);
  for (std::size_t i = 0; i < states_.size(); ++i) {
    states_[i]->live = false;  // the layers start afresh at the next render
    states_[i]->updated = false;
    if (statuses_[i] == PolygonStatus::kBackFacing ||
        statuses_[i] == PolygonStatus::kOutsideFrustum) {
      continue;
    }
    statuses_[i] = PolygonStatus::kAnimated;
    levels_[i] = Level::kPerspective;
    ++report.levels[static_cast<int>(Level::kPerspective)];
  }
}

void SceneEngine::cache_frame(const ViewerPose& current, AnimationFrame& report) {
  std::vector<char> culled(states_.size(), 0);
  for (std::size_t i = 0; i < states_.size(); ++i) {
    culled[i] = statuses_[i] == PolygonStatus::kBackFacing ||
                statuses_[i] == PolygonStatus::kOutsideFrustum;
    states_[i]->updated = false;
  }
  // The pixel measures (holes, overlaps, per-pixel error) are diagnostics, outside the time.
  lazy_clear_.forget();  // the cache draws the frame itself
  report.time_ms -= cache_->frame(current, culled, frame_, levels_, report);
  bsp_.back_to_front(eye_position(current), order_);
  for (std::size_t i = 0; i < states_.size(); ++i) {
    if (!culled[i]) statuses_[i] = PolygonStatus::kAnimated;
  }
}

AnimationFrame SceneEngine::run_frame(const ViewerPose* previous, const RigidMotion* motion,
                                      const ViewerPose& current) {
  const auto t0 = Clock::now();
  AnimationFrame report;
  report.frame = frame_index_;
  report.layers = static_cast<int>(scene_.polygons.size());
  const ReusePolicy& policy = *settings_.engine.policy;
  report.reports_holes = reports_holes(policy);
  const bool per_pixel = policy.frame_warp == FrameWarp::kPerPixelDepth;  // or motion vectors
  if (cache_) {
    classify(current, report);
    cache_frame(current, report);  // takes its diagnostics' time off report.time_ms
    report.time_ms += ms_since(t0);
    return report;
  }
  if (policy.pixel_motion == PixelMotion::kFarMesh) {
    const double diagnostics_ms = mesh_frame(previous, motion, current, report);
    report.time_ms = ms_since(t0) - diagnostics_ms - report.budget.check_ms;
    return report;
  }
  if (per_pixel && has_render_ && !cadence_frame()) {
    // Time left out: the diagnostics, and view interpolation's next render made ahead.
    double excluded_ms = 0.0;
    if (policy.pixel_motion != PixelMotion::kBetweenRenders || look_ahead(excluded_ms)) {
      classify(current, report);
      excluded_ms += reproject_frame(current, report);
      report.time_ms = ms_since(t0) - excluded_ms;
      return report;
    }
  }
  render_frame(previous, motion, current, report);
  if (per_pixel) keep_render(current, previous);
  // The budget's optimality check is a diagnostic, left out as the measured errors are.
  report.time_ms = ms_since(t0) - report.budget.check_ms;
  return report;
}

void SceneEngine::render_frame(const ViewerPose* previous, const RigidMotion* motion,
                               const ViewerPose& current, AnimationFrame& report) {
  const ReusePolicy& policy = *settings_.engine.policy;
  if (policy.frame_warp == FrameWarp::kPerPixelDepth) {
    for (auto& s : states_) s->live = false;  // a render frame renders every polygon
  }
  uses_frame_plane_ = policy.model == ModelUpdate::kFrameHomography &&
                      policy.frame_plane == FramePlane::kStabilization;
  if (uses_frame_plane_) update_frame_plane(current);
  classify(current, report);
  if (!set_aside_.empty()) set_aside_polygons();
  bsp_.back_to_front(eye_position(current), order_);
  measure_polygons(previous, motion, current, report);
  allocate_polygons(report);
  update_front_to_back(current, report);
  tally_hidden_and_stale(report);
  report.budget = ledger_.finish();
  const auto t1 = Clock::now();
  compose(report);
  report.composite_ms = ms_since(t1);
}

void SceneEngine::tally_hidden_and_stale(AnimationFrame& report) {
  const BoundingBox frame_box{0.0, 0.0, static_cast<double>(camera_.width),
                              static_cast<double>(camera_.height)};
  for (std::size_t i = 0; i < states_.size(); ++i) {
    PolygonLayer& s = *states_[i];
    if (statuses_[i] == PolygonStatus::kHidden) {
      ++report.hidden;
      report.hidden_area_px += clip_to_box(polygon_region(static_cast<int>(i)), frame_box).area();
    }
    if (!s.updated) s.live = false;  // its layer is stale: the next update starts afresh
    if (statuses_[i] == PolygonStatus::kAnimated) report.layer_reports.push_back(s.report);
  }
}

void SceneEngine::compose(AnimationFrame& report) {
  const std::vector<BspFragment>& fragments = bsp_.fragments();
  // Cleared as it is composited: each pixel is stored about once, not cleared and then
  // stored again (the same bytes as a fill first). All the fragments, back to front, in one
  // pass of bands of rows (composite_all).
  lazy_clear_.start_on(frame_);  // the pixels the last compose left clear need no store
  std::vector<CompositeItem> items;
  for (int f : order_) {
    if (!fragment_drawn_[f]) continue;
    const int p = fragments[f].polygon;
    const PlacedLayer* shown = states_[p]->shown(statuses_[p]);
    items.push_back({&shown->layer, shown->offset_x, shown->offset_y,
                     states_[p]->whole ? nullptr : &fragment_regions_[f]});
  }
  report.pixels_composited += composite_all(frame_, items, &lazy_clear_);
  lazy_clear_.finish(frame_);
}

std::vector<LayerOutline> SceneEngine::outlines(const ViewerPose& view) const {
  std::vector<LayerOutline> result;
  std::vector<char> listed(states_.size(), 0);
  for (int f : order_) {
    const int p = bsp_.fragments()[f].polygon;
    const PolygonStatus status = statuses_[p];
    if (listed[p] || (status != PolygonStatus::kAnimated && status != PolygonStatus::kClipped)) {
      continue;
    }
    listed[p] = 1;
    LayerOutline outline;
    outline.level = levels_[p];
    outline.polygon = p;
    outline.error_px =
        status == PolygonStatus::kAnimated ? states_[p]->report.measured_error_px : 0.0;
    bool in_front = true;
    for (const Vec3& v : states_[p]->world_vertices) {
      const Vec3 r = to_view(view, v);
      in_front = in_front && r.z > 1e-3;
      if (!in_front) break;
      outline.points.push_back(centred_to_pixel(camera_, project_centred(camera_, r)));
    }
    if (in_front) result.push_back(std::move(outline));
  }
  return result;
}

std::unique_ptr<SceneScriptAnimator> make_scene_animator(std::shared_ptr<const Scene> scene,
                                                         ViewerScript script,
                                                         const SceneSettings& settings) {
  return std::make_unique<SceneScriptAnimator>(std::move(scene), std::move(script), settings);
}

}  // namespace oflab
