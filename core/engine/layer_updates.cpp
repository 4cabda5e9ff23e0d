// The plane engine's shown layer (core/engine/engine.h): the levels applied to it (a whole-
// pixel translation, the affine step from the perspective cache, a new cache, a re-render of
// the texture or of a lit content), the framing's hidden and clipped frames, the warps into
// reused memory with their work in the cost model, and the error the shown pixels measure.
// The decision that picks the level is core/engine/engine.cpp.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <utility>

#include "engine/engine.h"
#include "engine/wall_clock.h"

namespace oflab {
namespace {

using Clock = WallClock;

}  // namespace

std::array<Vec2, 4> PlaneEngine::texel_corners() const {
  const double w = texture_.image.width(), h = texture_.image.height();
  return {Vec2(0.0, 0.0), Vec2(w, 0.0), Vec2(w, h), Vec2(0.0, h)};
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
  keep_render_from_display(display_.layer);
  display_ = PlacedLayer{};
  partial_.active = false;
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
  partial_.active = false;
  accumulated_.fill(0.0);
  const auto t0 = Clock::now();
  keep_render_from_display(display_.layer);
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
  report.render_ms += ms_since(t0);
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
  report.render_ms += ms_since(t0);
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
  const bool keep = policy().allows_reuse();  // the perspective level's source
  render_in_display_ = false;                 // the new render replaces the kept one
  if (keep) {
    keep_pyramid(warped_.layer, rendered_mips_);
    rendered_from_texel_ = glm::inverse(origin) * exact;
  }
  if (policy().initial_view != InitialView::kAffinePart) {
    partial_.active = false;
    std::swap(display_.layer, warped_.layer);
    render_in_display_ = keep;  // shown as made: kept there, not copied
    display_.offset_x = warped_.offset_x;
    display_.offset_y = warped_.offset_y;
    layer_warp_ = exact;
    layer_origin_ = glm::ivec2(warped_.offset_x, warped_.offset_y);
    return;
  }
  // An affine initial view (section 6.5): the render is warped onto it, from rendered_ when
  // it is kept (moved there, its pyramid kept_render()'s), else from a copy.
  Layer copy;
  if (keep) {
    std::swap(rendered_, warped_.layer);  // warped_ takes rendered_'s old memory as scratch
  } else {
    copy = warped_.layer;
  }
  show(keep ? rendered_ : copy, displayed_ * glm::inverse(exact) * origin, displayed_, report);
}

Mat3 PlaneEngine::target_warp(const PlanePose& pose) const {
  const Mat3 exact = exact_texture_warp(camera_, sized_pose(pose));
  // Section 6.5: the initial view is affine too, and the flow model follows it.
  if (policy().initial_view == InitialView::kAffinePart) {
    return affine_part_at(exact, 0.5 * texel_corners()[2]);
  }
  return exact;
}

std::vector<Vec2> PlaneEngine::displayed_outline() const {
  if (display_.layer.empty()) return {};
  if (clipped_) return clipped_outline_;
  std::vector<Vec2> out;
  for (const Vec2& t : texel_corners()) out.push_back(apply_homography(displayed_, t));
  return out;
}

std::vector<Vec2> PlaneEngine::displayed_corners_centred() const {
  std::vector<Vec2> out;
  for (const Vec2& t : texel_corners()) {
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
  for (const Vec2& t : texel_corners()) {
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
  const bool partial = shown_pixels_ && (&source == &texture_ || &source == &cache_.layer);
  PixelRows computed;  // beyond the shown pixels: the rest of the affine bilinear blocks
  warp_reusing(source, source_to_image, report, partial ? shown_pixels_ : nullptr, &computed);
  partial_.active = partial;
  if (partial) {
    partial_.source = &source;
    partial_.warp = source_to_image;
    partial_.done =
        shown_pixels_->within(warped_.offset_x, warped_.offset_y, warped_.layer.image.width(),
                              warped_.layer.image.height());
    partial_.done.add(computed);
  }
  std::swap(display_.layer, warped_.layer);  // the old display's memory serves the next warp
  keep_render_from_display(warped_.layer);
  display_.offset_x = warped_.offset_x;
  display_.offset_y = warped_.offset_y;
  layer_warp_ = texel_to_image;
  layer_origin_ = glm::ivec2(warped_.offset_x, warped_.offset_y);
}

void PlaneEngine::warp_reusing(const Layer& source, const Mat3& warp, FrameReport& report,
                               const PixelRows* only, PixelRows* computed) {
  WarpOptions options;
  options.sampling = settings_.sampling;
  options.only = only;
  options.computed_pixels = computed;
  options.pyramid = pyramid_of(source);
  warp_layer_reusing(source, warp, warped_, options);
  report.pixels_written += warped_.stats.pixels_written;
  report.pixels_not_warped += warped_.stats.pixels_written - warped_.stats.pixels_computed;
  const bool affine = warped_.stats.kernel_used == WarpKernel::kAffine;
  report.model_work +=
      warped_.stats.pixels_written * (affine ? kAffineWarpCost : kPerspectiveWarpCost);
}

void PlaneEngine::complete_display(FrameReport& report, bool all) {
  if (!partial_.active) return;
  const Image& image = display_.layer.image;
  // The pixels wanted, as placed when the layer was warped (it has moved by whole pixels):
  // the shown pixels within the layer's box only (the frame's other rows are not copied).
  const glm::ivec2 moved = glm::ivec2(display_.offset_x, display_.offset_y) - layer_origin_;
  PixelRows wanted =
      all || !shown_pixels_
          ? PixelRows::full(image.width(), image.height()).shifted(layer_origin_.x, layer_origin_.y)
          : shown_pixels_
                ->within(display_.offset_x, display_.offset_y, image.width(), image.height())
                .shifted(-moved.x, -moved.y);
  const PixelRows missing = wanted.minus(partial_.done);
  if (!missing.empty()) {
    WarpOptions options;
    options.sampling = settings_.sampling;
    options.only = &missing;
    PixelRows computed;  // the rest of the affine bilinear blocks, not computed again later
    options.computed_pixels = &computed;
    options.pyramid = pyramid_of(*partial_.source);
    const WarpStats stats = warp_layer_into(*partial_.source, partial_.warp, display_.layer.image,
                                            layer_origin_.x, layer_origin_.y, options);
    report.pixels_not_warped -= stats.pixels_computed;
    partial_.done.add(computed);
  }
  partial_.done.add(wanted);
  if (all || !shown_pixels_) partial_.active = false;
}

const MipPyramid* PlaneEngine::pyramid_of(const Layer& source) const {
  if (settings_.sampling != Sampling::kMipmap) return nullptr;
  if (&source == &texture_) return &texture_mips_;
  if (&source == &cache_.layer) return &cache_.mips;
  if (&source == &kept_render()) return &rendered_mips_;
  return nullptr;
}

void PlaneEngine::keep_render_from_display(Layer& display_memory) {
  if (!render_in_display_) return;
  std::swap(rendered_, display_memory);
  render_in_display_ = false;
}

void PlaneEngine::keep_pyramid(const Layer& layer, MipPyramid& pyramid) const {
  if (settings_.sampling == Sampling::kMipmap) build_mip_pyramid(layer.image, pyramid);
}

void PlaneEngine::cache_from_display() {
  // The displayed layer is an exact image of the texture under displayed_, so it can serve
  // as the cache without another warp (its resolution is the output's).
  const Mat3 origin = translation_matrix(display_.offset_x, display_.offset_y);
  cache_.layer = display_.layer;  // a copy into the cache's memory when it is large enough
  keep_pyramid(cache_.layer, cache_.mips);
  cache_.to_display = origin;
  cache_.from_texel = glm::inverse(origin) * displayed_;
  cache_.valid = true;
}

void PlaneEngine::show_from_cache(FrameReport& report) {
  show(cache_.layer, cache_.to_display, cache_.to_display * cache_.from_texel, report);
}

bool PlaneEngine::apply_affine(const Mat3& correction, const Vec2& point, FrameReport& report) {
  if (!cache_.valid) {
    complete_display(report, true);  // a partial display must not become the cache
    cache_from_display();
  }
  const Mat3 step = affine_part_at(correction, point);
  const Mat3 to_display = step * cache_.to_display;
  if (largest_singular_value(to_display) > settings_.max_magnification) return false;
  cache_.to_display = to_display;
  displayed_ = step * displayed_;
  show_from_cache(report);
  return true;
}

bool PlaneEngine::apply_perspective(const Mat3& target, FrameReport& report) {
  const Vec2 centre = 0.5 * texel_corners()[2];
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
    warp_reusing(kept_render(), render_to_cache, report);
  } else {
    warp_reusing(texture_, texel_to_cache, report);
  }
  std::swap(cache_.layer, warped_.layer);  // the old cache's memory serves the next warp
  keep_pyramid(cache_.layer, cache_.mips);
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

void PlaneEngine::apply_level(FrameReport& report, const Vec2& expansion_point,
                              const PlanePose& current) {
  const Mat3 correction = model_ * glm::inverse(displayed_);
  const Vec2 point = centred_to_pixel(camera_, expansion_point);
  bool within_limit = true;
  switch (report.level) {
    case Level::kNone:
      complete_display(report);
      break;
    case Level::kTranslate:
      apply_translation(translation_step(correction, point));
      complete_display(report);
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

}  // namespace oflab
