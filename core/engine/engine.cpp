// Algorithm 1 for one plane (dissertation section 5.6.1), corrected; see core/engine/engine.h for
// the frames and manual/animation.md for the rules and the errata fixed (22-27).
#include "engine/engine.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "flow/homography.h"
#include "flow/reprojection.h"

namespace oflab {
namespace {

std::array<Vec2, 4> texel_corners(const Layer& texture) {
  const double w = texture.image.width(), h = texture.image.height();
  return {Vec2(0.0, 0.0), Vec2(w, 0.0), Vec2(w, h), Vec2(0.0, h)};
}

// Jacobian (2x2, column-major) of homography h at point p.
glm::dmat2 homography_jacobian(const Mat3& h, const Vec2& p) {
  const Vec3 q = h * Vec3(p, 1.0);
  const Vec2 u(q.x / q.z, q.y / q.z);
  const double g = entry(h, 2, 0), k = entry(h, 2, 1);
  return glm::dmat2((entry(h, 0, 0) - u.x * g) / q.z, (entry(h, 1, 0) - u.y * g) / q.z,
                    (entry(h, 0, 1) - u.x * k) / q.z, (entry(h, 1, 1) - u.y * k) / q.z);
}

// The affine map that agrees with h to first order at p (bottom row exactly (0, 0, 1)).
Mat3 affine_part_at(const Mat3& h, const Vec2& p) {
  const glm::dmat2 j = homography_jacobian(h, p);
  const Vec2 t = apply_homography(h, p) - j * p;
  return mat3_from_rows({j[0][0], j[1][0], t.x}, {j[0][1], j[1][1], t.y}, {0.0, 0.0, 1.0});
}

double largest_singular_value(const Mat3& m) {
  const glm::dmat2 a(entry(m, 0, 0), entry(m, 1, 0), entry(m, 0, 1), entry(m, 1, 1));
  const glm::dmat2 ata = glm::transpose(a) * a;
  const double tr = ata[0][0] + ata[1][1], det = glm::determinant(ata);
  return std::sqrt(0.5 * tr + std::sqrt(std::max(0.0, 0.25 * tr * tr - det)));
}

using Clock = std::chrono::steady_clock;

double elapsed_ms(Clock::time_point since) {
  return std::chrono::duration<double, std::milli>(Clock::now() - since).count();
}

// Texel -> top-left pixel homography of the plane's texture rectangle, scaled so that its
// denominator is the depth Z of the texel's point (positive in front of the eye, negative
// behind it), whichever corner lies behind the eye.
Mat3 depth_signed_texture_warp(const Camera& camera, const PlanePose& pose) {
  const PlaneAxes a = plane_axes(pose);
  const Mat3 plane_to_camera(a.right, a.up, pose.point);
  const Mat3 h = translation_matrix(camera.cx, camera.cy) * centred_intrinsics(camera) *
                 plane_to_camera * texel_to_plane(pose);
  double largest = 0.0;
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r) largest = std::max(largest, std::abs(entry(h, r, c)));
  }
  return h * (1.0 / largest);
}

// Replaces a layer's valid polygon for the lifetime of the guard, restoring it after.
class PolygonSwap {
 public:
  PolygonSwap(Layer& layer, ConvexPolygon polygon)
      : layer_(layer), saved_(std::move(layer_.polygon)) {
    layer_.polygon = std::move(polygon);
  }
  ~PolygonSwap() { layer_.polygon = std::move(saved_); }
  PolygonSwap(const PolygonSwap&) = delete;
  PolygonSwap& operator=(const PolygonSwap&) = delete;

 private:
  Layer& layer_;
  ConvexPolygon saved_;
};

}  // namespace

std::string plane_visibility_problem(const PlanePose& pose) {
  const PoseProblem p = plane_pose_problem(pose);
  if (!p.field.empty()) return p.message;
  for (const Vec3& c : plane_corners(pose)) {
    if (!(c.z > 1e-6)) return "a plane corner is at or behind the eye";
  }
  const double cosine = glm::dot(glm::normalize(pose.normal), glm::normalize(pose.point));
  if (std::abs(cosine) < 1e-3) return "the plane is seen edge-on";
  return "";
}

Mat3 exact_texture_warp(const Camera& camera, const PlanePose& pose) {
  return translation_matrix(camera.cx, camera.cy) * texture_to_image(camera, pose);
}

PlacedLayer render_exact(const Camera& camera, const Layer& texture, const PlanePose& pose,
                         Sampling sampling, WarpStats* stats) {
  PlanePose sized = pose;
  sized.texture_size = glm::ivec2(texture.image.width(), texture.image.height());
  WarpOptions options;
  options.sampling = sampling;
  WarpedLayer w = warp_layer(texture, exact_texture_warp(camera, sized), options);
  if (stats) *stats = w.stats;
  return {std::move(w.layer), w.offset_x, w.offset_y};
}

PlacedLayer render_clipped(const Camera& camera, Layer& texture, const PlanePose& pose,
                           const ViewPolygon& clipped, Sampling sampling, WarpStats* stats) {
  const glm::ivec2 size(texture.image.width(), texture.image.height());
  PlanePose sized = pose;
  sized.texture_size = size;
  double z_min = clipped.points.at(0).z, z_max = z_min;
  for (const Vec3& p : clipped.points) {
    z_min = std::min(z_min, p.z);
    z_max = std::max(z_max, p.z);
  }
  WarpOptions options;
  options.sampling = sampling;
  // The warp's horizon margin must not cut into the clipped polygon itself.
  options.horizon_epsilon = std::clamp(0.5 * z_min / z_max, 1e-4, kDefaultHorizonEpsilon);
  // Only the clipped part of the texture is drawn (the texture's own polygon is restored).
  const PolygonSwap part(texture, texel_polygon(clipped.uv, size));
  WarpedLayer w = warp_layer(texture, depth_signed_texture_warp(camera, sized), options);
  if (stats) *stats = w.stats;
  return {std::move(w.layer), w.offset_x, w.offset_y};
}

PlacedLayer render_clipped_piece(const Camera& camera, const LayerContent& content, Layer& texture,
                                 const PlanePose& pose, const ConvexPolygon& texels,
                                 const ViewPolygon& clipped, Sampling sampling,
                                 std::int64_t* pixels_written, double* model_work) {
  if (content_is_lit(content)) {
    ContentStats stats;
    PlacedLayer placed = render_clipped_content(camera, content, pose, texels, clipped, &stats);
    *pixels_written += stats.pixels_written;
    *model_work += stats.work_units * content_unit_cost(content.kind);
    return placed;
  }
  WarpStats stats;
  PlacedLayer placed = render_clipped(camera, texture, pose, clipped, sampling, &stats);
  *pixels_written += stats.pixels_written;
  *model_work += stats.pixels_written * kPerspectiveWarpCost;
  return placed;
}

PlacedLayer render_clipped_content(const Camera& camera, const LayerContent& content,
                                   const PlanePose& pose, const ConvexPolygon& texels,
                                   const ViewPolygon& clipped, ContentStats* stats) {
  WarpedLayer w;
  const ContentStats s =
      render_content(content, camera, pose, texels, project_to_pixels(camera, clipped), w);
  if (stats) *stats = s;
  return {std::move(w.layer), w.offset_x, w.offset_y};
}

PlaneEngine::PlaneEngine(const Camera& camera, Layer texture, const EngineSettings& settings)
    : camera_(camera), texture_(std::move(texture)), settings_(settings) {
  const std::string problem = content_problem(settings_.content);
  if (!problem.empty()) throw std::invalid_argument("content: " + problem);
  const std::string samples = plane_shaded_samples_problem(settings_.content, camera);
  if (!samples.empty()) throw std::invalid_argument("content: " + samples);
  const std::string budget = frame_budget_problem(settings_.budget);
  if (!budget.empty()) throw std::invalid_argument("budget: " + budget);
}

FrameReport PlaneEngine::start(const PlanePose& pose) { return apply(measure_start(pose).choice); }

FrameReport PlaneEngine::advance(const PlanePose& previous, const RigidMotion& motion,
                                 const PlanePose& current) {
  return apply(measure_advance(previous, motion, current).choice);
}

LayerCandidates PlaneEngine::measure_start(const PlanePose& pose) {
  measure(true, nullptr, nullptr, pose);
  return measured_.candidates;
}

LayerCandidates PlaneEngine::measure_advance(const PlanePose& previous, const RigidMotion& motion,
                                             const PlanePose& current) {
  measure(false, &previous, &motion, current);
  return measured_.candidates;
}

void PlaneEngine::measure(bool start, const PlanePose* previous, const RigidMotion* motion,
                          const PlanePose& current) {
  const auto t0 = Clock::now();
  measured_ = Measured{};
  measured_.start = start;
  if (previous) measured_.previous = *previous;
  if (motion) measured_.motion = *motion;
  measured_.current = current;
  try {
    // The flow is measured at the previous pose: it must be a whole, drawable plane.
    const bool flow_usable =
        !start && shown_ && plane_visibility_problem(measured_.previous).empty();
    if (flow_usable && policy().allows_reuse() && frame_pose(current).kind == Framing::kWhole) {
      measure_choice();
    } else {
      measure_fresh(current);
    }
  } catch (const std::exception& refused) {
    // The frame re-renders (apply_after_refusal); its cost is that of a fresh render.
    const std::string refusal = refused.what();
    measured_.candidates = LayerCandidates{};
    try {
      measure_fresh(current);
    } catch (const std::exception&) {
      measured_.candidates = LayerCandidates{};
    }
    measured_.refusal = refusal;
  }
  measured_.ms = elapsed_ms(t0);
}

void PlaneEngine::measure_fresh(const PlanePose& pose) {
  LayerCandidates& c = measured_.candidates;
  c.choice = Level::kRerender;
  const Framing framing = frame_pose(pose);
  if (framing.kind == Framing::kNotShown) {
    c.kind = LayerCandidates::Kind::kNotShown;
    return;
  }
  c.kind = LayerCandidates::Kind::kFresh;
  if (!policy().shares_budget) return;
  const ConvexPolygon region = framing.kind == Framing::kClipped
                                   ? project_to_pixels(camera_, framing.clipped)
                                   : transform(texture_.polygon, target_warp(pose));
  c.pixels[static_cast<int>(Level::kRerender)] = box_pixels(region);
  if (!region.empty()) {
    const BoundingBox b = region.bounds();
    c.extent_px = std::hypot(b.x_max - b.x_min, b.y_max - b.y_min);
  }
}

FrameReport PlaneEngine::apply(Level level, bool shown) {
  const auto t0 = Clock::now();
  if (measured_.start) {
    frame_ = 0;
    shown_ = false;
  } else {
    ++frame_;
  }
  std::string refusal = measured_.refusal;
  if (refusal.empty()) {
    try {
      // time_ms covers measuring, deciding, warping and placing; the diagnostics of
      // finish_report (the measured error) run after the clock is read.
      FrameReport report;
      report.frame = frame_;
      apply_measured(level, shown, report);
      report.time_ms = measured_.ms + elapsed_ms(t0);
      report.warp_ms = report.time_ms - report.render_ms;
      finish_report(measured_.current, report);
      return report;
    } catch (const std::exception& refused) {
      refusal = refused.what();
    }
  }
  return apply_after_refusal(refusal, measured_.ms + elapsed_ms(t0));
}

void PlaneEngine::apply_measured(Level level, bool shown, FrameReport& report) {
  switch (measured_.candidates.kind) {
    case LayerCandidates::Kind::kChoice:
      apply_choice(level, report);
      return;
    case LayerCandidates::Kind::kFresh:
      if (!shown) {
        hide("starved: the frame budget could not afford this layer's render", report);
        return;
      }
      break;
    case LayerCandidates::Kind::kNotShown:
      break;
  }
  render_fresh(measured_.current, report);
}

FrameReport PlaneEngine::apply_after_refusal(const std::string& refusal, double spent_ms) {
  // Any refusal (a warp beyond its range, a singular map) becomes a fresh exact render of
  // the frame, or an invisible frame when even that is refused.
  const auto t0 = Clock::now();
  const PlanePose& current = measured_.current;
  FrameReport report;
  report.frame = frame_;
  try {
    render_fresh(current, report);
    report.time_ms = spent_ms + elapsed_ms(t0);
    report.warp_ms = report.time_ms - report.render_ms;
    finish_report(current, report);
    if (report.visible) report.note = "re-rendered after a refusal: " + refusal;
  } catch (const std::exception& again) {
    report = FrameReport{};
    report.frame = frame_;
    hide(std::string("not drawn: ") + again.what(), report);
    report.time_ms = spent_ms + elapsed_ms(t0);
    report.warp_ms = report.time_ms - report.render_ms;
    finish_report(current, report);
  }
  return report;
}

PlaneEngine::Framing PlaneEngine::frame_pose(const PlanePose& pose_in) const {
  const PlanePose pose = sized_pose(pose_in);
  if (texture_.empty()) return {Framing::kNotShown, "not visible: the texture is empty", {}};
  const PoseProblem p = plane_pose_problem(pose);
  // A centre behind the eye or a plane through it is a matter for clipping; anything else
  // (non-finite values, degenerate axes) cannot be drawn at all.
  const bool drawable_axes =
      p.field.empty() || (p.field == "point" && std::isfinite(pose.point.x) &&
                          std::isfinite(pose.point.y) && std::isfinite(pose.point.z));
  if (!drawable_axes) return {Framing::kNotShown, "not visible: " + p.message, {}};
  const Vec3 corner0 = plane_corners(pose)[0];
  const Vec3 to_eye = p.field.empty() ? pose.point : corner0;
  if (std::abs(glm::dot(glm::normalize(pose.normal), glm::normalize(to_eye))) < 1e-3) {
    return {Framing::kNotShown, "not visible: the plane is seen edge-on", {}};
  }
  if (!plane_meets_image(camera_, pose, settings_.near)) {
    bool beyond_near = false;
    for (const Vec3& c : plane_corners(pose)) beyond_near = beyond_near || c.z >= settings_.near;
    return {Framing::kNotShown,
            beyond_near ? "outside the image"
                        : "not visible: wholly nearer than the near plane or behind the eye",
            {}};
  }
  const double gw = settings_.guard_band * camera_.width;
  const double gh = settings_.guard_band * camera_.height;
  ViewPolygon rectangle;
  bool whole = true;
  for (const Vec3& c : plane_corners(pose)) {
    rectangle.points.push_back(c);
    const Vec2 q = c.z > 0.0 ? centred_to_pixel(camera_, project_centred(camera_, c)) : Vec2(0.0);
    whole = whole && c.z >= settings_.near && q.x >= -gw && q.x <= camera_.width + gw &&
            q.y >= -gh && q.y <= camera_.height + gh;
  }
  if (whole) return {};
  rectangle.uv = {Vec2(0.0, 0.0), Vec2(1.0, 0.0), Vec2(1.0, 1.0), Vec2(0.0, 1.0)};
  Framing f{Framing::kClipped,
            "clipped: the plane reaches in front of the near plane or "
            "beyond the guard band, rendered exactly",
            {}};
  f.clipped = clip_to_frustum(rectangle, view_frustum(camera_, settings_.near, 1.0));
  if (f.clipped.empty()) return {Framing::kNotShown, "outside the image", {}};
  return f;
}

void PlaneEngine::render_fresh(const PlanePose& pose, FrameReport& report) {
  const Framing framing = frame_pose(pose);
  switch (framing.kind) {
    case Framing::kNotShown:
      hide(framing.note, report);
      break;
    case Framing::kClipped:
      show_clipped(pose, framing, report);
      break;
    case Framing::kWhole:
      rerender(pose, report);
      break;
  }
}

void PlaneEngine::hide(const std::string& note, FrameReport& report) {
  report.level = Level::kRerender;
  report.visible = false;
  report.note = note;
  cache_.valid = false;
  display_ = PlacedLayer{};
  clipped_outline_.clear();
  clipped_ = false;
  shown_ = false;
  accumulated_.fill(0.0);
}

void PlaneEngine::show_clipped(const PlanePose& pose, const Framing& framing, FrameReport& report) {
  report.level = Level::kRerender;
  report.clipped = true;
  report.note = framing.note;
  cache_.valid = false;
  shown_ = false;  // the layer holds only part of the plane: the next frame starts afresh
  accumulated_.fill(0.0);
  const auto t0 = Clock::now();
  if (content_is_lit(settings_.content)) {
    ContentStats stats;
    display_ = render_clipped_content(camera_, settings_.content, sized_pose(pose),
                                      texture_.polygon, framing.clipped, &stats);
    report.pixels_written += stats.pixels_written;
    report.model_work += stats.work_units * content_unit_cost(settings_.content.kind);
  } else {
    WarpStats stats;
    display_ = render_clipped(camera_, texture_, pose, framing.clipped, settings_.sampling, &stats);
    report.pixels_written += stats.pixels_written;
    report.model_work += stats.pixels_written * kPerspectiveWarpCost;
  }
  report.render_ms += elapsed_ms(t0);
  clipped_outline_ = project_to_pixels(camera_, framing.clipped).vertices();
  clipped_ = true;
}

void PlaneEngine::rerender(const PlanePose& pose, FrameReport& report) {
  report.level = Level::kRerender;
  cache_.valid = false;
  clipped_ = false;
  displayed_ = target_warp(pose);
  model_ = displayed_;
  rendered_warp_ = displayed_;
  render_pose_ = sized_pose(pose);
  if (!origin_set_) {
    origin_pose_ = render_pose_;
    origin_set_ = true;
  }
  render_plane_ = render_plane_vector(render_pose_);
  since_render_ = 0;
  const auto t0 = Clock::now();
  if (content_is_lit(settings_.content)) {
    rerender_content(pose, report);
  } else {
    // A texture's re-render is one perspective warp in the cost model, whichever kernel ran.
    const double work = report.model_work;
    const std::int64_t pixels = report.pixels_written;
    show(texture_, displayed_, displayed_, report);
    report.model_work =
        work + kPerspectiveWarpCost * static_cast<double>(report.pixels_written - pixels);
  }
  report.render_ms += elapsed_ms(t0);
  shown_ = true;
  accumulated_.fill(0.0);
}

void PlaneEngine::rerender_content(const PlanePose& pose, FrameReport& report) {
  const PlanePose sized = sized_pose(pose);
  const Mat3 exact = exact_texture_warp(camera_, sized);
  // A whole frame lies beyond the near plane: the exact warp's denominator is positive.
  const ContentStats stats = render_content(settings_.content, camera_, sized, texture_.polygon,
                                            transform(texture_.polygon, exact), warped_);
  report.pixels_written += stats.pixels_written;
  report.model_work += stats.work_units * content_unit_cost(settings_.content.kind);
  rendered_pose_ = sized;
  const Mat3 origin = translation_matrix(warped_.offset_x, warped_.offset_y);
  if (policy().allows_reuse()) {
    rendered_ = warped_.layer;  // the perspective level's source (a copy into kept memory)
    rendered_from_texel_ = glm::inverse(origin) * exact;
  }
  if (policy().initial_view != InitialView::kAffinePart) {
    std::swap(display_.layer, warped_.layer);
    display_.offset_x = warped_.offset_x;
    display_.offset_y = warped_.offset_y;
    layer_warp_ = exact;
    layer_origin_ = glm::ivec2(warped_.offset_x, warped_.offset_y);
    return;
  }
  // An affine initial view (section 6.5): the render is warped onto it.
  const Layer render = warped_.layer;
  show(render, displayed_ * glm::inverse(exact) * origin, displayed_, report);
}

Mat3 PlaneEngine::target_warp(const PlanePose& pose) const {
  const Mat3 exact = exact_texture_warp(camera_, sized_pose(pose));
  // Section 6.5: the initial view is affine too, and the flow model follows it.
  if (policy().initial_view == InitialView::kAffinePart) {
    return affine_part_at(exact, 0.5 * texel_corners(texture_)[2]);
  }
  return exact;
}

std::vector<Vec2> PlaneEngine::displayed_outline() const {
  if (display_.layer.empty()) return {};
  if (clipped_) return clipped_outline_;
  std::vector<Vec2> out;
  for (const Vec2& t : texel_corners(texture_)) out.push_back(apply_homography(displayed_, t));
  return out;
}

std::vector<Vec2> PlaneEngine::displayed_corners_centred() const {
  std::vector<Vec2> out;
  for (const Vec2& t : texel_corners(texture_)) {
    out.push_back(pixel_to_centred(camera_, apply_homography(displayed_, t)));
  }
  return out;
}

PlanePose PlaneEngine::sized_pose(const PlanePose& pose) const {
  PlanePose sized = pose;
  sized.texture_size = glm::ivec2(texture_.image.width(), texture_.image.height());
  return sized;
}

double PlaneEngine::corner_distance(const Mat3& a, const Mat3& b) const {
  double worst = 0.0;
  for (const Vec2& t : texel_corners(texture_)) {
    worst = std::max(worst, glm::length(apply_homography(a, t) - apply_homography(b, t)));
  }
  return worst;
}

double PlaneEngine::shown_error(const Mat3& reference) const {
  // Where the pixels are: the warp that made the layer, moved by the whole pixels the layer
  // was shifted since.
  const glm::ivec2 moved = glm::ivec2(display_.offset_x, display_.offset_y) - layer_origin_;
  const Mat3 shown = translation_matrix(moved.x, moved.y) * layer_warp_;
  return corner_distance(shown, reference);
}

Vec2 PlaneEngine::translation_step(const Mat3& correction, const Vec2& point) const {
  const Vec2 motion = apply_homography(correction, point) - point;
  return Vec2(std::round(motion.x), std::round(motion.y));
}

void PlaneEngine::apply_translation(const Vec2& step) {
  // The layer is reused as it is, moved by whole pixels; the remainder stays pending.
  const Mat3 shift = translation_matrix(step.x, step.y);
  displayed_ = shift * displayed_;
  cache_.to_display = shift * cache_.to_display;
  display_.offset_x += static_cast<int>(step.x);
  display_.offset_y += static_cast<int>(step.y);
}

void PlaneEngine::show(const Layer& source, const Mat3& source_to_image, const Mat3& texel_to_image,
                       FrameReport& report) {
  warp_reusing(source, source_to_image, report);
  std::swap(display_.layer, warped_.layer);  // the old display's memory serves the next warp
  display_.offset_x = warped_.offset_x;
  display_.offset_y = warped_.offset_y;
  layer_warp_ = texel_to_image;
  layer_origin_ = glm::ivec2(warped_.offset_x, warped_.offset_y);
}

void PlaneEngine::warp_reusing(const Layer& source, const Mat3& warp, FrameReport& report) {
  WarpOptions options;
  options.sampling = settings_.sampling;
  warp_layer_reusing(source, warp, warped_, options);
  report.pixels_written += warped_.stats.pixels_written;
  const bool affine = warped_.stats.kernel_used == WarpKernel::kAffine;
  report.model_work +=
      warped_.stats.pixels_written * (affine ? kAffineWarpCost : kPerspectiveWarpCost);
}

void PlaneEngine::cache_from_display() {
  // The displayed layer is an exact image of the texture under displayed_, so it can serve
  // as the cache without another warp (its resolution is the output's).
  const Mat3 origin = translation_matrix(display_.offset_x, display_.offset_y);
  cache_.layer = display_.layer;  // a copy into the cache's memory when it is large enough
  cache_.to_display = origin;
  cache_.from_texel = glm::inverse(origin) * displayed_;
  cache_.valid = true;
}

void PlaneEngine::show_from_cache(FrameReport& report) {
  show(cache_.layer, cache_.to_display, cache_.to_display * cache_.from_texel, report);
}

bool PlaneEngine::apply_affine(const Mat3& correction, const Vec2& point, FrameReport& report) {
  if (!cache_.valid) cache_from_display();
  const Mat3 step = affine_part_at(correction, point);
  const Mat3 to_display = step * cache_.to_display;
  if (largest_singular_value(to_display) > settings_.max_magnification) return false;
  cache_.to_display = to_display;
  displayed_ = step * displayed_;
  show_from_cache(report);
  return true;
}

bool PlaneEngine::apply_perspective(const Mat3& target, FrameReport& report) {
  const Vec2 centre = 0.5 * texel_corners(texture_)[2];
  const Mat3 to_centre = translation_matrix(centre.x, centre.y);
  const AffinePerspectiveSplit split =
      split_affine_perspective(target * to_centre, settings_.delta);
  // The sampling limit holds here too: the affine rest must not magnify the new cache
  // along any axis by more than the limit (its determinant alone would hide anisotropy).
  if (largest_singular_value(split.affine) > settings_.max_magnification) return false;
  const Mat3 texel_to_cache = split.perspective * translation_matrix(-centre.x, -centre.y);
  if (content_is_lit(settings_.content)) {
    // A lit content is not rendered again: the new cache is its last render, warped. That
    // warp must not magnify the render beyond the limit either (at the plane's centre).
    const Mat3 render_to_cache = texel_to_cache * glm::inverse(rendered_from_texel_);
    const Vec2 at = apply_homography(rendered_from_texel_, centre);
    if (largest_singular_value(affine_part_at(split.affine * render_to_cache, at)) >
        settings_.max_magnification) {
      return false;
    }
    warp_reusing(rendered_, render_to_cache, report);
  } else {
    warp_reusing(texture_, texel_to_cache, report);
  }
  std::swap(cache_.layer, warped_.layer);  // the old cache's memory serves the next warp
  cache_.from_texel = translation_matrix(-warped_.offset_x, -warped_.offset_y) * texel_to_cache;
  cache_.to_display = split.affine * translation_matrix(warped_.offset_x, warped_.offset_y);
  cache_.valid = true;
  displayed_ = target;
  show_from_cache(report);
  return true;
}

void PlaneEngine::finish_report(const PlanePose& pose, FrameReport& report) const {
  report.accumulated = accumulated_;
  const bool reused = report.visible && !report.clipped && report.level != Level::kRerender;
  report.estimated_error_px = 0.0;
  if (reused) {
    report.estimated_error_px = std::max(neglected_error(accumulated_, TermArray{}, Level::kNone),
                                         report.pending[static_cast<int>(report.level)]);
  }
  report.measured_error_px = std::numeric_limits<double>::quiet_NaN();
  report.reuse_error_px = std::numeric_limits<double>::quiet_NaN();
  if (report.visible) {
    report.measured_error_px =
        report.clipped ? 0.0 : shown_error(exact_texture_warp(camera_, sized_pose(pose)));
    report.reuse_error_px = report.clipped ? 0.0 : shown_error(target_warp(pose));
  }
  if (reused) {
    report.photometric_error = shading_change(settings_.content, rendered_pose_, sized_pose(pose));
  }
  if (policy().initial_view == InitialView::kAffinePart && report.visible && !report.clipped) {
    const Mat3 exact = exact_texture_warp(camera_, sized_pose(pose));
    report.affine_view_error_px = corner_distance(target_warp(pose), exact);
  }
}

LevelPixels PlaneEngine::level_pixels() const {
  const auto area = [](const Layer& l) {
    return static_cast<std::int64_t>(l.image.width()) * l.image.height();
  };
  const std::int64_t displayed = area(display_.layer);
  return estimate_level_pixels(displayed, cache_.valid ? area(cache_.layer) : displayed);
}

void PlaneEngine::set_frame_plane(const Vec3& m) {
  frame_plane_ = m;
  frame_plane_set_ = true;
}

Vec3 PlaneEngine::render_plane_vector(const PlanePose& sized) const {
  if (policy().frame_plane == FramePlane::kInfinity) return Vec3(0.0);
  if (frame_plane_set_) return frame_plane_;
  const StabilizationPlane& given = settings_.stabilization;
  if (given.automatic || !origin_set_) return plane_vector(sized);
  // The given plane moves with the single plane from its first pose.
  return plane_vector_after(plane_vector_of(given.point, given.normal),
                            rigid_step_between(origin_pose_, sized));
}

Mat3 PlaneEngine::next_model(const PlanarFlowCoefficients& flow, const PlanePose& current,
                             FitFiducials& fit) const {
  fit = fit_;
  if (policy().model == ModelUpdate::kFrameHomography) {
    // One homography for the whole frame since the render: the viewer's rigid step since
    // then and the frame plane kept at the render.
    const RigidStep3 step = rigid_step_between(render_pose_, sized_pose(current));
    return plane_induced_homography(camera_, step, render_plane_) * rendered_warp_;
  }
  if (policy().model == ModelUpdate::kExact) {
    return exact_texture_warp(camera_, sized_pose(current));  // the exact frame-to-frame homography
  }
  if (policy().model == ModelUpdate::kAffineFit) {
    // Talisman: the corners as last rendered, fitted onto their exact projections now.
    const Mat3 exact = exact_texture_warp(camera_, sized_pose(current));
    std::vector<Vec2> rendered, now;
    for (const Vec2& t : texel_corners(texture_)) {
      rendered.push_back(apply_homography(rendered_warp_, t));
      now.push_back(apply_homography(exact, t));
    }
    const AffineFit fitted = fit_rendered_polygon(rendered, now);
    fit = fitted.fiducials;
    return fitted.warp * rendered_warp_;
  }
  PlanarFlowCoefficients step = flow;
  if (policy().model == ModelUpdate::kAffineTaylor) step.px = step.py = 0.0;  // affine flow model
  return centred_to_pixel_homography(camera_, taylor_homography(step, 1.0)) * model_;
}

Mat3 PlaneEngine::warp_after(Level level, const Mat3& correction, const Vec2& point,
                             const Mat3& model) const {
  switch (level) {
    case Level::kNone:
      return displayed_;
    case Level::kTranslate: {
      const Vec2 step = translation_step(correction, point);
      return translation_matrix(step.x, step.y) * displayed_;
    }
    case Level::kAffine:
      return affine_part_at(correction, point) * displayed_;
    case Level::kPerspective:
      return model;
    case Level::kRerender:
      break;
  }
  return displayed_;
}

void PlaneEngine::measure_choice() {
  Measured& m = measured_;
  const std::vector<Vec2> corners = displayed_corners_centred();
  m.measures = measure_flow(camera_, m.previous, m.motion, corners);
  const PlanarFlowCoefficients flow =
      reexpand(planar_flow_coefficients(camera_, m.previous, m.motion), m.measures.expansion_point);
  m.flow = m.measures.flow;
  if (policy().books == FlowBooks::kPrinted) {
    m.flow = measure_printed_flow(camera_, m.previous, m.motion, corners);
  }
  if (policy().model == ModelUpdate::kExact) m.flow[3] = 0.0;  // nothing of higher order
  m.model = next_model(flow, m.current, m.fit);
  // Pending errors are image displacements: this frame's motion stretches them by up to
  // the largest singular value of its Jacobian, so they are carried forward scaled by it.
  const Mat3 stretch = mat3_from_rows({1.0 + flow.j11, flow.j12, 0.0},
                                      {flow.j21, 1.0 + flow.j22, 0.0}, {0.0, 0.0, 1.0});
  m.carried = accumulated_;
  for (double& e : m.carried) e *= std::max(1.0, largest_singular_value(stretch));
  // The exact error each level would leave, against the policy's view of the current pose.
  const Mat3 correction = m.model * glm::inverse(displayed_);
  const Vec2 point = centred_to_pixel(camera_, m.measures.expansion_point);
  const Mat3 target = target_warp(m.current);
  for (int l = 0; l < kTermCount; ++l) {
    m.pending[l] =
        corner_distance(warp_after(static_cast<Level>(l), correction, point, m.model), target);
  }
  LayerCandidates& c = m.candidates;
  c.kind = LayerCandidates::Kind::kChoice;
  c.pixels = level_pixels();
  m.since_render = since_render_ + 1;
  c.choice = policy().choose(policy(), {m.flow, m.carried, settings_.thresholds, c.pixels,
                                        m.pending, m.fit, m.since_render, settings_.cadence});
  c.feasible = policy().allowed;
  for (int l = 0; l < kTermCount; ++l) {
    c.error[l] = std::max(neglected_error(m.carried, m.flow, static_cast<Level>(l)), m.pending[l]);
  }
  if (policy().shares_budget) measure_level_costs(correction, point);
}

void PlaneEngine::measure_level_costs(const Mat3& correction, const Vec2& point) {
  // Upper bounds of the pixels each level writes (the boxes of the polygons it warps), and
  // the levels the sampling limit would refuse, as apply_affine and apply_perspective do.
  LayerCandidates& c = measured_.candidates;
  const ConvexPolygon& cache_polygon = cache_.valid ? cache_.layer.polygon : display_.layer.polygon;
  const Mat3 cache_to_display =
      cache_.valid ? cache_.to_display : translation_matrix(display_.offset_x, display_.offset_y);
  const Mat3 affine = affine_part_at(correction, point) * cache_to_display;
  const int a = static_cast<int>(Level::kAffine), p = static_cast<int>(Level::kPerspective);
  c.feasible[a] = c.feasible[a] && largest_singular_value(affine) <= settings_.max_magnification;
  c.pixels[a] = box_pixels(transform(cache_polygon, affine));
  const Vec2 centre = 0.5 * texel_corners(texture_)[2];
  const AffinePerspectiveSplit split = split_affine_perspective(
      measured_.model * translation_matrix(centre.x, centre.y), settings_.delta);
  c.feasible[p] =
      c.feasible[p] && largest_singular_value(split.affine) <= settings_.max_magnification;
  const Mat3 texel_to_cache = split.perspective * translation_matrix(-centre.x, -centre.y);
  c.pixels[p] = box_pixels(transform(texture_.polygon, texel_to_cache)) +
                box_pixels(transform(texture_.polygon, measured_.model));
  c.pixels[static_cast<int>(Level::kRerender)] =
      box_pixels(transform(texture_.polygon, target_warp(measured_.current)));
}

void PlaneEngine::apply_choice(Level level, FrameReport& report) {
  const Measured& m = measured_;
  report.flow = m.flow;
  report.carried = m.carried;
  report.pending = m.pending;
  model_ = m.model;
  fit_ = m.fit;
  report.level = level;
  // Erratum 25, corrected: the terms the level neglects accumulate, the ones it handles are
  // caught up with. What the books cannot see (the sub-pixel remainder of a whole-pixel
  // translation, higher orders the first-order bookkeeping misses) is in report.pending.
  for (int k = 0; k < kTermCount; ++k) {
    accumulated_[k] = k >= static_cast<int>(level) ? m.carried[k] + m.flow[k] : 0.0;
  }
  // Talisman's fit is checked against the exact projection each frame: nothing is carried.
  if (policy().model == ModelUpdate::kAffineFit) accumulated_.fill(0.0);
  since_render_ = m.since_render;  // a re-render below resets it
  apply_level(report, m.measures.expansion_point, m.current);
}

void PlaneEngine::apply_level(FrameReport& report, const Vec2& expansion_point,
                              const PlanePose& current) {
  const Mat3 correction = model_ * glm::inverse(displayed_);
  const Vec2 point = centred_to_pixel(camera_, expansion_point);
  bool within_limit = true;
  switch (report.level) {
    case Level::kNone:
      break;
    case Level::kTranslate:
      apply_translation(translation_step(correction, point));
      report.model_work += kTranslationCost * static_cast<double>(display_.layer.image.width()) *
                           display_.layer.image.height();
      break;
    case Level::kAffine:
      within_limit = apply_affine(correction, point, report);
      break;
    case Level::kPerspective:
      within_limit = apply_perspective(model_, report);
      break;
    case Level::kRerender:
      rerender(current, report);
      break;
  }
  if (!within_limit) {
    report.note = "sampling limit: the cache would be magnified too much";
    rerender(current, report);
  }
}

}  // namespace oflab
