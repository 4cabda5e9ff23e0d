// Algorithm 1 for one plane (dissertation section 5.6.1), corrected; see core/engine/engine.h for
// the frames and manual/animation.md for the rules and the errata fixed (22-27).
#include "engine/engine.h"

#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "flow/homography.h"

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

PlaneAnimator::PlaneAnimator(const Camera& camera, Layer texture, const EngineSettings& settings)
    : camera_(camera), texture_(std::move(texture)), settings_(settings) {}

FrameReport PlaneAnimator::start(const PlanePose& pose) {
  frame_ = 0;
  FrameReport report;
  const auto t0 = Clock::now();
  rerender(pose, report);
  report.time_ms = elapsed_ms(t0);  // the update only: the diagnostics below are not timed
  finish_report(pose, report);
  return report;
}


void PlaneAnimator::rerender(const PlanePose& pose_in, FrameReport& report) {
  report.level = Level::kRerender;
  report.frame = frame_;
  cache_.valid = false;
  PlanePose pose = pose_in;
  pose.texture_size = glm::ivec2(texture_.image.width(), texture_.image.height());
  std::string problem = plane_visibility_problem(pose);
  if (problem.empty() && texture_.empty()) problem = "the texture is empty";
  if (!problem.empty()) {
    report.visible = false;
    report.note = "not visible: " + problem;
    report.measured_error_px = std::numeric_limits<double>::quiet_NaN();
    display_ = PlacedLayer{};
    shown_ = false;
    accumulated_.fill(0.0);
    return;
  }
  displayed_ = exact_texture_warp(camera_, pose);
  if (policy().initial_view == InitialView::kAffinePart) {
    // Section 6.5: the initial view is affine too, and the flow model follows it.
    displayed_ = affine_part_at(displayed_, 0.5 * texel_corners(texture_)[2]);
  }
  model_ = displayed_;
  show(texture_, displayed_, report);
  shown_ = true;
  accumulated_.fill(0.0);
}

std::vector<Vec2> PlaneAnimator::displayed_corners_centred() const {
  std::vector<Vec2> out;
  for (const Vec2& t : texel_corners(texture_)) {
    out.push_back(pixel_to_centred(camera_, apply_homography(displayed_, t)));
  }
  return out;
}

PlanePose PlaneAnimator::sized_pose(const PlanePose& pose) const {
  PlanePose sized = pose;
  sized.texture_size = glm::ivec2(texture_.image.width(), texture_.image.height());
  return sized;
}

double PlaneAnimator::corner_error(const PlanePose& pose) const {
  const Mat3 exact = exact_texture_warp(camera_, sized_pose(pose));
  double worst = 0.0;
  for (const Vec2& t : texel_corners(texture_)) {
    worst = std::max(worst, glm::length(apply_homography(displayed_, t) -
                                        apply_homography(exact, t)));
  }
  return worst;
}

void PlaneAnimator::apply_translation(const Mat3& correction, const Vec2& point) {
  // The layer is reused as it is, placed with sub-pixel precision (drawn at the nearest
  // whole pixel: the sampling allowance); the displayed warp stays exact.
  const Vec2 motion = apply_homography(correction, point) - point;
  const Mat3 shift = translation_matrix(motion.x, motion.y);
  displayed_ = shift * displayed_;
  cache_.to_display = shift * cache_.to_display;
  shift_ += motion;
  place_display();
}

void PlaneAnimator::place_display() {
  display_.offset_x = base_offset_.x + static_cast<int>(std::lround(shift_.x));
  display_.offset_y = base_offset_.y + static_cast<int>(std::lround(shift_.y));
}

void PlaneAnimator::show(const Layer& source, const Mat3& source_to_image, FrameReport& report) {
  warp_reusing(source, source_to_image, report);
  std::swap(display_.layer, warped_.layer);  // the old display's memory serves the next warp
  base_offset_ = glm::ivec2(warped_.offset_x, warped_.offset_y);
  shift_ = Vec2(0.0);
  place_display();
}

void PlaneAnimator::warp_reusing(const Layer& source, const Mat3& warp, FrameReport& report) {
  WarpOptions options;
  options.sampling = settings_.sampling;
  warp_layer_reusing(source, warp, warped_, options);
  report.pixels_written += warped_.stats.pixels_written;
}

void PlaneAnimator::cache_from_display() {
  // The displayed layer is an exact image of the texture under displayed_, so it can serve
  // as the cache without another warp (its resolution is the output's).
  const Mat3 origin = translation_matrix(base_offset_.x + shift_.x, base_offset_.y + shift_.y);
  cache_.layer = display_.layer;  // a copy into the cache's memory when it is large enough
  cache_.to_display = origin;
  cache_.from_texel = glm::inverse(origin) * displayed_;
  cache_.valid = true;
}

void PlaneAnimator::rebuild_cache(const Mat3& target, FrameReport& report) {
  const Vec2 centre = 0.5 * texel_corners(texture_)[2];
  const Mat3 to_centre = translation_matrix(centre.x, centre.y);
  const AffinePerspectiveSplit split =
      split_affine_perspective(target * to_centre, settings_.delta);
  const Mat3 texel_to_cache = split.perspective * translation_matrix(-centre.x, -centre.y);
  warp_reusing(texture_, texel_to_cache, report);
  std::swap(cache_.layer, warped_.layer);
  cache_.from_texel = translation_matrix(-warped_.offset_x, -warped_.offset_y) * texel_to_cache;
  cache_.to_display = split.affine * translation_matrix(warped_.offset_x, warped_.offset_y);
  cache_.valid = true;
}

void PlaneAnimator::show_from_cache(FrameReport& report) {
  show(cache_.layer, cache_.to_display, report);
}

bool PlaneAnimator::apply_affine(const Mat3& correction, const Vec2& point,
                                 FrameReport& report) {
  if (!cache_.valid) cache_from_display();
  const Mat3 step = affine_part_at(correction, point);
  const Mat3 to_display = step * cache_.to_display;
  if (largest_singular_value(to_display) > settings_.max_magnification) return false;
  cache_.to_display = to_display;
  displayed_ = step * displayed_;
  show_from_cache(report);
  return true;
}

void PlaneAnimator::apply_perspective(const Mat3& target, FrameReport& report) {
  rebuild_cache(target, report);
  displayed_ = target;
  show_from_cache(report);
}

void PlaneAnimator::finish_report(const PlanePose& pose, FrameReport& report) const {
  report.accumulated = accumulated_;
  report.estimated_error_px = neglected_error(accumulated_, TermArray{}, Level::kNone);
  report.measured_error_px =
      report.visible ? corner_error(pose) : std::numeric_limits<double>::quiet_NaN();
  if (policy().initial_view == InitialView::kAffinePart && report.visible) {
    const Mat3 exact = exact_texture_warp(camera_, sized_pose(pose));
    const Mat3 affine = affine_part_at(exact, 0.5 * texel_corners(texture_)[2]);
    double worst = 0.0;
    for (const Vec2& t : texel_corners(texture_)) {
      worst = std::max(worst, glm::length(apply_homography(affine, t) - apply_homography(exact, t)));
    }
    report.affine_view_error_px = worst;
  }
}

LevelPixels PlaneAnimator::level_pixels() const {
  const auto area = [](const Layer& l) {
    return static_cast<std::int64_t>(l.image.width()) * l.image.height();
  };
  const std::int64_t displayed = area(display_.layer);
  return estimate_level_pixels(displayed, cache_.valid ? area(cache_.layer) : displayed);
}

FrameReport PlaneAnimator::advance(const PlanePose& previous, const RigidMotion& motion,
                                   const PlanePose& current_in) {
  ++frame_;
  const auto t0 = Clock::now();
  FrameReport report;
  report.frame = frame_;
  PlanePose current = current_in;
  current.texture_size = glm::ivec2(texture_.image.width(), texture_.image.height());
  const bool visible_now = plane_visibility_problem(current).empty() && !texture_.empty();
  const bool flow_usable = plane_visibility_problem(previous).empty();
  // A policy without reuse levels re-renders without measuring the flow.
  if (!shown_ || !visible_now || !flow_usable || !policy().allows_reuse()) {
    rerender(current, report);
  } else {
    decide_and_update(previous, motion, current, report);
  }
  report.time_ms = elapsed_ms(t0);  // deciding, warping and placing: not the diagnostics
  finish_report(current, report);
  return report;
}

void PlaneAnimator::advance_model(const PlanarFlowCoefficients& flow,
                                  const PlanePose& current) {
  if (policy().model == ModelUpdate::kExact) {
    model_ = exact_texture_warp(camera_, current);  // the exact frame-to-frame homography
    return;
  }
  PlanarFlowCoefficients step = flow;
  if (policy().model == ModelUpdate::kAffineTaylor) step.px = step.py = 0.0;  // affine flow model
  model_ = centred_to_pixel_homography(camera_, taylor_homography(step, 1.0)) * model_;
}

void PlaneAnimator::decide_and_update(const PlanePose& previous, const RigidMotion& motion,
                                      const PlanePose& current, FrameReport& report) {
  const FlowMeasures m = measure_flow(camera_, previous, motion, displayed_corners_centred());
  const PlanarFlowCoefficients flow =
      reexpand(planar_flow_coefficients(camera_, previous, motion), m.expansion_point);
  report.flow = m.flow;
  if (policy().model == ModelUpdate::kExact) report.flow[3] = 0.0;  // nothing of higher order
  advance_model(flow, current);
  // Pending errors are image displacements: this frame's motion stretches them by up to
  // the largest singular value of its Jacobian, so they are carried forward scaled by it.
  const Mat3 stretch = mat3_from_rows({1.0 + flow.j11, flow.j12, 0.0},
                                      {flow.j21, 1.0 + flow.j22, 0.0}, {0.0, 0.0, 1.0});
  TermArray carried = accumulated_;
  for (double& e : carried) e *= std::max(1.0, largest_singular_value(stretch));
  report.carried = carried;
  report.level =
      policy().choose(policy(), {report.flow, carried, settings_.thresholds, level_pixels()});
  for (int k = 0; k < kTermCount; ++k) {
    accumulated_[k] = k >= static_cast<int>(report.level) ? carried[k] + report.flow[k] : 0.0;
  }
  apply_level(report, m.expansion_point, current);
}

void PlaneAnimator::apply_level(FrameReport& report, const Vec2& expansion_point,
                                const PlanePose& current) {
  const Mat3 correction = model_ * glm::inverse(displayed_);
  const Vec2 point = centred_to_pixel(camera_, expansion_point);
  try {
    switch (report.level) {
      case Level::kNone: break;
      case Level::kTranslate: apply_translation(correction, point); break;
      case Level::kAffine:
        if (!apply_affine(correction, point, report)) {
          report.note = "sampling limit: the cache would be magnified too much";
          rerender(current, report);
        }
        break;
      case Level::kPerspective: apply_perspective(model_, report); break;
      case Level::kRerender: rerender(current, report); break;
    }
  } catch (const std::invalid_argument& e) {
    report.note = std::string("warp refused, re-rendered: ") + e.what();
    rerender(current, report);
  }
}

}  // namespace oflab
